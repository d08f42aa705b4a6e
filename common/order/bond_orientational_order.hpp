#pragma once
// Steinhardt bond-orientational order Q_l and q_l (Steinhardt, Nelson & Ronchetti, PRB 28, 784
// (1983); docs/order-metrics.md §2) of a packing's neighbour bonds.

#include "order/neighbour_bonds.hpp"

#include <complex>
#include <cstddef>
#include <vector>

namespace sbpack {

struct SteinhardtOrder {
    int degree = 0; ///< l
    /// Q_l = sqrt(4 pi / (2l + 1) sum_m |<Y_lm>|^2), <.> over every bond seen from both ends
    /// (docs/order-metrics.md Eq. 2.1).
    double globalOrder = 0.0;
    /// q_l(i): the same over the bonds of particle i (Eq. 2.2); NaN where i has no bond.
    std::vector<double> localOrder;
    /// Bonds of each particle.
    std::vector<int> neighbourCount;
    /// Mean of q_l(i) over the particles with at least one bond.
    double meanLocalOrder = 0.0;
    /// Particles with at least one bond.
    std::size_t bondedParticles = 0;
    std::size_t bondCount = 0;
};

/// Sums of Y_lm over bonds, m = 0..l; m < 0 follows from Y_{l,-m} = (-1)^m conj Y_lm.
using Harmonics = std::vector<std::complex<double>>;

/// The bond harmonics of each particle: q_lm(i) of Eq. 2.2 before the division by N_b(i).
struct BondHarmonics {
    int degree = 0;                  ///< l
    std::vector<Harmonics> sums;     ///< sum over the bonds of i of Y_lm(r_ij), m = 0..l
    std::vector<int> neighbourCount; ///< N_b(i)
};

/// Each particle's bond harmonics, every bond seen from both ends (r_ij from i, -r_ij from j).
/// Throws std::invalid_argument for l < 0, a bond of zero length or a particle index beyond
/// bonds.particleCount.
BondHarmonics bondHarmonics(const NeighbourBonds& bonds, int degree);

/// sum_{m=-l..l} a_lm conj(b_lm), real for harmonics of real vectors (docs/order-metrics.md
/// Eq. 2.3); a and b hold m = 0..l.
double harmonicProduct(const Harmonics& a, const Harmonics& b);

/// Q_l, q_l(i) and their mean for degree l >= 0; lengths do not enter, only the bonds'
/// directions. Throws std::invalid_argument for l < 0, no bonds, a bond of zero length or a
/// particle index beyond bonds.particleCount.
SteinhardtOrder steinhardtOrder(const NeighbourBonds& bonds, int degree);

} // namespace sbpack

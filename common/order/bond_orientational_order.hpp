#pragma once
// Steinhardt bond-orientational order Q_l and q_l (Steinhardt, Nelson & Ronchetti, PRB 28, 784
// (1983); docs/order-metrics.md §2) of a packing's neighbour bonds.

#include "order/neighbour_bonds.hpp"

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

/// Q_l, q_l(i) and their mean for degree l >= 0; lengths do not enter, only the bonds'
/// directions. Throws std::invalid_argument for l < 0, no bonds, a bond of zero length or a
/// particle index beyond bonds.particleCount.
SteinhardtOrder steinhardtOrder(const NeighbourBonds& bonds, int degree);

} // namespace sbpack

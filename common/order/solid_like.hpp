#pragma once
// Solid-like particles (ten Wolde, Ruiz-Montero & Frenkel, J. Chem. Phys. 104, 9932 (1996);
// docs/order-metrics.md §5): the per-particle crystal criterion on the correlation of bonded
// neighbours' local q_lm, and the largest crystalline cluster. freud's
// freud.order.SolidLiquid(l, q_threshold, solid_threshold, normalize_q=True) computes the same.

#include "order/neighbour_bonds.hpp"

#include <cstddef>
#include <vector>

namespace sbpack {

/// The criterion's thresholds (docs/order-metrics.md §5, where the lattices and MRJ packings
/// measured with them are): a bond is crystal-like when d_6(i, j) > 0.7, a particle solid-like
/// with at least 7 crystal-like bonds, the values of the hard-sphere nucleation studies that
/// follow ten Wolde et al.
inline constexpr double kCrystalBondThreshold = 0.7;
inline constexpr int kSolidLikeBonds = 7;

struct SolidLikeParameters {
    int degree = 6;                               ///< l
    double bondThreshold = kCrystalBondThreshold; ///< crystal-like bond: d_l(i, j) above it
    int solidThreshold = kSolidLikeBonds;         ///< solid-like particle: this many or more
};

struct SolidLikeResult {
    SolidLikeParameters parameters;
    /// d_l(i, j) = Re sum_m q_lm(i) conj q_lm(j) / (|q_l(i)| |q_l(j)|) of each bond, in the
    /// order of the bonds given (docs/order-metrics.md Eq. 5.1); NaN where q_lm(i) or q_lm(j)
    /// vanishes.
    std::vector<double> bondCorrelation;
    std::vector<int> neighbourCount; ///< bonds of each particle
    std::vector<int> crystalBonds;   ///< crystal-like bonds of each particle, xi(i)
    std::vector<bool> solidLike;     ///< xi(i) >= solidThreshold
    std::size_t solidCount = 0;
    double solidFraction = 0.0; ///< solidCount / N
    /// The most solid-like particles joined by crystal-like bonds into one cluster.
    std::size_t largestClusterSize = 0;
    double largestClusterFraction = 0.0; ///< largestClusterSize / N
};

/// The solid-like particles of a packing's neighbour bonds (a bond counts at both its ends).
class SolidLikeParticles {
  public:
    /// Throws std::invalid_argument unless l >= 1, |bondThreshold| < 1 and solidThreshold >= 1.
    explicit SolidLikeParticles(SolidLikeParameters parameters = {});
    /// Throws std::invalid_argument where bondHarmonics does (order/bond_orientational_order.hpp)
    /// or for bonds of no particle.
    SolidLikeResult compute(const NeighbourBonds& bonds) const;

  private:
    SolidLikeParameters parameters_;
};

} // namespace sbpack

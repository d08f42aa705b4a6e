#pragma once
// Cubatic orientational order P4 of the particles' cubic axes (docs/order-metrics.md §4): the
// mean fourth Legendre polynomial over the axis pairs of all particle pairs, in O(N) through the
// box's fourth-rank axis tensor.

#include "packing/packing.hpp"

#include <cstddef>
#include <vector>

namespace sbpack {

/// sum_{k,l} P4(e_k . e_l) = 3 P4(1) + 6 P4(0) = 3 + 6 (3 / 8): one particle's axes with
/// themselves, the normalisation of Eq. 4.1.
inline constexpr double kAlignedAxisSum = 5.25;

struct CubaticOrderResult {
    /// P4 = sum_{i != j} sum_{k,l} P4(u_ik . u_jl) / (N (N - 1) 5.25) (Eq. 4.1): 1 for
    /// identical orientations, 0 in expectation for independent uniformly random ones.
    double order = 0.0;
    /// Standard deviation of P4 for independent uniformly random orientations,
    /// sqrt(2 / (9 N (N - 1))) (Eq. 4.4).
    double randomOrientationError = 0.0;
    std::size_t particleCount = 0;
};

/// P4 of the body axes u_ik = R_i e_k (R_i of the quaternion body -> lab, normalised here).
/// Throws std::invalid_argument for fewer than 2 orientations or a quaternion that is zero or
/// not finite.
CubaticOrderResult cubaticOrder(const std::vector<Quaterniond>& orientations);

} // namespace sbpack

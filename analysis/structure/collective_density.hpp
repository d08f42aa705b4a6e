#pragma once
// The collective density rho(Q) = sum_j exp(-i Q . r_j) of N points in a cubic periodic box, at
// the wave vectors Q = 2 pi n / L: the kernel of S(Q) (paper Eq. 4, eq:ScattInt) and of the exact
// spectral density of spheres (paper Eq. 12, eq:spD). Equation numbers are those of the tex in
// shared/paper, counted in order; the labels are unambiguous.

#include "progress/progress.hpp"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <cstdint>
#include <span>
#include <vector>

namespace sbpack {

/// |rho(Q)|^2 at one wave vector of each pair +-n (|rho(-Q)| = |rho(Q)| for real positions): the
/// half space n_x > 0, or n_x = 0 and n_y > 0, or n_x = n_y = 0 and n_z > 0.
struct DensityModes {
    std::vector<std::array<int, 3>> n;
    std::vector<double> intensity;
    /// rho(Q) itself, where asked for (the partial structure factors' cross terms); else empty.
    std::vector<std::complex<double>> amplitude;

    std::size_t size() const { return n.size(); }
};

/// floor(sqrt(m)) for m >= 0, exact.
int isqrt(std::int64_t m);

/// cos(2 pi k x / L) and sin(2 pi k x / L) for k = 0..kmax, per particle (row j, length kmax+1).
struct PhaseTable {
    std::vector<double> c, s;
};

/// The phases of coordinate `axis` of every position: exact every 16 steps (2 pi (k x / L mod 1),
/// the argument reduced exactly), by the angle-addition recurrence in between.
PhaseTable phaseTable(std::span<const Eigen::Vector3d> positions, int axis, double boxLength,
                      int kmax);

/// |rho(Q)|^2 for every n of the half space with 1 <= |n|^2 <= maxN2, by direct summation in
/// double precision. Separable: exp(-i Q.r) is the product of one factor per axis, tabulated per
/// particle by recurrence; the four sign combinations (n_x, +-n_y, +-n_z) share their products.
/// Parallel over n_x (the order of every sum is fixed, so the result does not depend on the
/// number of threads). The modes come in an order that depends on maxN2 only, so that two sets of
/// positions give the same n at the same index. `amplitudes`: keep rho(Q) too. Throws
/// std::invalid_argument unless L > 0 and maxN2 >= 1.
DensityModes collectiveDensity(std::span<const Eigen::Vector3d> positions, double boxLength,
                               std::int64_t maxN2, const Progress& progress,
                               bool amplitudes = false);

} // namespace sbpack

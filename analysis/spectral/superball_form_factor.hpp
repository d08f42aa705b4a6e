#pragma once
// Form factor of one superball, m(k; R) = int_body exp(-i k.x) d^3x (paper Eq. 12, eq:spD, the
// m~(Q; R) that the paper approximates by voxels), in the body frame (docs/design.md §1). The
// body is centrally symmetric, so m is real: int cos(k.x) d^3x. Two independent methods:
//  - the Taylor series of cos over the body's closed-form Dirichlet moments
//    int x^{2i} y^{2j} z^{2l} d^3x, truncated where the remainder, bounded by
//    v1 sum_{n > N} (|k| R_c)^{2n} / (2n)! (R_c the circumradius), is below 1e-16 v1; its
//    rounding error is about 1e-16 v1 cosh(|k| R_c), so it is used up to |k| R_c = 8
//    (k w <= 10 needs |k| R_c <= 6.1 for every p in [0.5, 1000]);
//  - nested tanh-sinh quadrature, with the integral along one axis done in closed form, over
//    the positive octant (m depends on |k_x|, |k_y|, |k_z| only and is symmetric under their
//    permutations: the 48-fold symmetry), beyond that.
// Accuracy: absolute error below 1e-10 v1 (relative to the volume; near a zero of m a relative
// error has no meaning).

#include "geometry/superball.hpp"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace sbpack {

class SuperballFormFactor {
  public:
    /// Series up to |k| R_c = kSeriesLimit, quadrature beyond.
    static constexpr double kSeriesLimit = 8.0;
    /// Lanes of a tile (seriesTile).
    static constexpr int kTile = 8;

    /// Tabulates the series coefficients (long double Gamma functions, rounded once).
    explicit SuperballFormFactor(const Superball& shape);

    /// m(k) for k in the body frame (1 / length); length^3.
    double operator()(const Eigen::Vector3d& kBody) const;
    /// The series alone (any |k| R_c <= kSeriesLimit).
    double series(const Eigen::Vector3d& kBody) const;
    /// The quadrature alone: absolute error about `tolerance` v1. Slow (milliseconds).
    double quadrature(const Eigen::Vector3d& kBody, double tolerance = 1e-13) const;

    /// Series order N (total degree 2N) that keeps the remainder below 1e-16 v1 for every
    /// |k| <= kNorm. Throws std::invalid_argument if kNorm R_c > kSeriesLimit.
    int order(double kNorm) const;
    /// The series of order `order` at kTile wave vectors at once, given u_i = -(k_i R)^2 in the
    /// body frame (three arrays of kTile): out[lane] = m. The hot loop of the exact spectral
    /// density.
    void seriesTile(int order, const double* ux, const double* uy, const double* uz,
                    double* out) const;

    const Superball& shape() const { return shape_; }
    double volume() const { return volume_; }

  private:
    /// Coefficient of u_x^i u_y^j u_z^l (dimensionless: m = R^3 sum c u^i u^j u^l).
    double coefficient(int i, int j, int l) const {
        return coefficients_[(static_cast<std::size_t>(i) * kStride + j) * kStride + l];
    }
    static constexpr int kMaxOrder = 26;
    static constexpr int kStride = kMaxOrder + 1;

    Superball shape_;
    double volume_;
    double circumradius_;
    std::vector<double> coefficients_; ///< kStride^3, zero where i + j + l > kMaxOrder
};

/// The superball's form factor, as spectral/form_factors.hpp asks each family's body for its own.
inline SuperballFormFactor formFactorFor(const Superball& body) {
    return SuperballFormFactor(body);
}

} // namespace sbpack

#pragma once
// Superball |x|^{2p} + |y|^{2p} + |z|^{2p} <= R^{2p} in its body frame (docs/design.md §1, paper
// Eq. 1).

#include <Eigen/Core>

namespace sbpack {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// From this exponent on, superballs are "near-cubes": they stack face to face into columns that
/// can span a small periodic box (bench/RESULTS.md, "Near-cubes after the jam check").
inline constexpr double kNearCubeExponent = 3.0;

class Superball {
  public:
    /// Throws std::invalid_argument unless 0.5 <= p < inf and 0 < semiAxis < inf.
    Superball(double p, double semiAxis);

    double p() const { return p_; }
    /// The same exponent at `factor` times the semi-axis.
    Superball scaled(double factor) const { return {p_, r_ * factor}; }
    double semiAxis() const { return r_; }
    double diameter() const { return 2.0 * r_; }
    /// Exponent of the dual norm, q = 2p / (2p - 1); infinite for the octahedron p = 0.5.
    double dualExponent() const { return q_; }
    bool isOctahedron() const { return p_ == 0.5; }
    bool isSphere() const { return p_ == 1.0; }

    /// Gauge g(x) = ||x / R||_{2p}: homogeneous of degree one, inside iff g < 1.
    double gauge(const Vector3d& xBody) const;
    bool contains(const Vector3d& xBody) const { return gauge(xBody) < 1.0; }

    /// v1 = 8 R^3 Gamma(1 + 1/(2p))^3 / Gamma(1 + 3/(2p)).
    double volume() const;
    /// int x^2 dV over the body (the same for y and z by cubic symmetry).
    double secondMoment() const;
    /// I / m = 2 <x^2>: the isotropic moment of inertia per unit mass.
    double inertiaPerMass() const;

    /// Support function h(n) = R ||n||_q; n need not be a unit vector (h is homogeneous).
    double support(const Vector3d& nBody) const;
    /// The point of the surface that maximises n . x (body frame), the gradient of h, from three
    /// powers (square and cube roots at p = 1.5 and 0.75); a vertex or face point where the
    /// maximiser is not unique.
    Vector3d supportPoint(const Vector3d& nBody) const;
    /// h, its gradient (the support point, the same bits as supportPoint) and its Hessian
    /// (clamped as supportHessian) at once, from the same three powers: the event-driven
    /// predictor's inner loop.
    struct SupportJet {
        double value;
        Vector3d point;
        Matrix3d hessian;
    };
    SupportJet supportJet(const Vector3d& nBody) const;
    /// Hessian of h at n, clamped to stay finite where it diverges (faces of cube-like
    /// shapes); zero for the octahedron.
    Matrix3d supportHessian(const Vector3d& nBody) const;

    /// The curvature tensor (shape operator) of the surface at the support point along the unit
    /// nBody, in the body frame: II = Hess(xi) / |grad xi| of xi(x) = sum_k |x_k / R|^{2p} - 1
    /// (docs/jamming.md §6.1), to be projected on the tangent plane. Not finite (inf or NaN) at a
    /// body coordinate 0 for p < 1 (edges; every point of the octahedron's support map).
    Matrix3d surfaceCurvature(const Vector3d& nBody) const;

    double circumradius() const;
    double inradius() const;
    /// w = (1 / 4 pi) int_{S^2} 2 h(n) dn (paper Sec. II D), by tanh-sinh quadrature over
    /// the fundamental domain of the cubic symmetry group.
    double meanWidth() const;

  private:
    double p_;
    double r_;
    double q_;
};

} // namespace sbpack

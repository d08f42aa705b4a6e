#include "geometry/superball.hpp"

#include "geometry/norm_parts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The Hessian of h diverges like |u_i|^{q-2} where a component vanishes (q < 2): clamp the
// ratio |u_i| / ||u||_q here, which keeps every entry below ~1e100 and the 2x2 Newton
// systems of the pair solver far from overflow.
constexpr double kHessianRatioFloor = 1e-100;

using NormParts = norm::Parts;

NormParts normParts(const Vector3d& u, double e) {
    return norm::parts(u.data(), e);
}

/// ||u||_e for 1 <= e <= inf.
double lpNorm(const Vector3d& u, double e) {
    return norm::lpNorm(u.data(), e);
}

/// ||u||_q and its gradient sgn(u_i) r_i^{q-1} = sgn(u_i) t_i (norm / sum) for finite q and
/// u != 0, r_i = y_i / norm (t_i = y_i^{q-1} taken directly: no division by y_i, and no
/// underflow where y_i^q is subnormal).
struct DualNorm {
    NormParts parts;
    Vector3d gradient;
};

DualNorm dualNorm(const Vector3d& u, double q) {
    DualNorm d{normParts(u, q), {}};
    const double scale = d.parts.norm / d.parts.sum;
    for (int i = 0; i < 3; ++i)
        d.gradient[i] = std::copysign(d.parts.t[i] * scale, u[i]);
    return d;
}

/// Tanh-sinh (double exponential) quadrature of f on [0, 1]: exact to rounding for the
/// algebraic endpoint singularities |x|^q of the support function. Refines until two
/// levels agree to 1e-15.
template <class F> double tanhSinh01(F&& f) {
    const double halfPi = 0.5 * std::numbers::pi;
    auto level = [&](double h, int offset, int stride) {
        double sum = 0.0;
        for (int k = offset;; k += stride) {
            double contribution = 0.0;
            for (double t : {k * h, -k * h}) {
                const double s = halfPi * std::sinh(t);
                const double x = 0.5 * (1.0 + std::tanh(s)); // node in (0, 1)
                const double w = 0.5 * halfPi * std::cosh(t) / (std::cosh(s) * std::cosh(s));
                if (x > 0.0 && x < 1.0 && w > 0.0) contribution += w * f(x);
                if (k == 0) break;
            }
            sum += contribution;
            if (k * h > 4.0) break;
        }
        return sum;
    };
    double h = 0.5;
    double estimate = h * level(h, 0, 1);
    for (int refinement = 0; refinement < 12; ++refinement) {
        h *= 0.5;
        const double refined = 0.5 * estimate + h * level(h, 1, 2); // odd nodes only
        if (std::abs(refined - estimate) <= 1e-15 * std::abs(refined)) return refined;
        estimate = refined;
    }
    return estimate;
}

} // namespace

Superball::Superball(double p, double semiAxis) : p_(p), r_(semiAxis) {
    if (!(p >= 0.5) || !std::isfinite(p))
        throw std::invalid_argument("superball exponent p = " + std::to_string(p) +
                                    " is outside [0.5, inf): concave shapes are out of scope");
    if (!(semiAxis > 0.0) || !std::isfinite(semiAxis))
        throw std::invalid_argument("superball semi-axis R = " + std::to_string(semiAxis) +
                                    " must be positive and finite");
    q_ = (p == 0.5) ? kInf : 2.0 * p / (2.0 * p - 1.0);
}

double Superball::gauge(const Vector3d& xBody) const {
    return lpNorm(xBody / r_, 2.0 * p_);
}

double Superball::volume() const {
    const double a = 1.0 / (2.0 * p_);
    const double g = std::tgamma(1.0 + a);
    return 8.0 * r_ * r_ * r_ * g * g * g / std::tgamma(1.0 + 3.0 * a);
}

double Superball::secondMoment() const {
    // Dirichlet integral: int x^2 dV = 8 R^5 a^3 Gamma(3a) Gamma(a)^2 / Gamma(1 + 5a), a = 1/(2p).
    const double a = 1.0 / (2.0 * p_);
    const double ga = std::tgamma(a);
    return 8.0 * std::pow(r_, 5) * a * a * a * std::tgamma(3.0 * a) * ga * ga /
           std::tgamma(1.0 + 5.0 * a);
}

double Superball::inertiaPerMass() const {
    return 2.0 * secondMoment() / volume();
}

double Superball::support(const Vector3d& nBody) const {
    return r_ * lpNorm(nBody, q_);
}

Vector3d Superball::supportPoint(const Vector3d& nBody) const {
    Vector3d x = Vector3d::Zero();
    if (nBody.isZero(0.0)) return x;
    if (q_ == kInf) { // octahedron: the vertex on the dominant axis
        int k = 0;
        nBody.cwiseAbs().maxCoeff(&k);
        x[k] = std::copysign(r_, nBody[k]);
        return x;
    }
    return r_ * dualNorm(nBody, q_).gradient; // x = R grad ||u||_q
}

Superball::SupportJet Superball::supportJet(const Vector3d& nBody) const {
    if (nBody.isZero(0.0) || q_ == kInf)
        return {support(nBody), supportPoint(nBody), supportHessian(nBody)};
    // d2 ||u||_q = (q-1)/||u||_q [diag(r_i^{q-2}) - g g^T], r_i^{q-2} = |g_i| / r_i where the
    // component is regular (r_i above the Hessian's floor, y_i^q normal); else by a power.
    const DualNorm d = dualNorm(nBody, q_);
    Vector3d diagonal;
    for (int i = 0; i < 3; ++i) {
        const double ratio = d.parts.y[i] / d.parts.norm;
        const bool regular = d.parts.t[i] * d.parts.y[i] >= std::numeric_limits<double>::min() &&
                             ratio >= kHessianRatioFloor;
        diagonal[i] = regular ? std::abs(d.gradient[i]) / ratio
                              : std::pow(std::max(ratio, kHessianRatioFloor), q_ - 2.0);
    }
    Matrix3d hessian = diagonal.asDiagonal();
    hessian -= d.gradient * d.gradient.transpose();
    const double fullNorm = d.parts.m * d.parts.norm;
    return {r_ * fullNorm, r_ * d.gradient, (r_ * (q_ - 1.0) / fullNorm) * hessian};
}

Matrix3d Superball::supportHessian(const Vector3d& nBody) const {
    Matrix3d hessian = Matrix3d::Zero();
    const double m = nBody.cwiseAbs().maxCoeff();
    if (m == 0.0 || q_ == kInf) return hessian;
    // d2 ||u||_q = (q-1)/N [diag(y_i^{q-2}) - g g^T], y_i = |u_i|/N, g_i = sgn(u_i) y_i^{q-1}.
    const double norm = m * lpNorm(nBody / m, q_);
    Vector3d g;
    for (int i = 0; i < 3; ++i) {
        const double y = std::max(std::abs(nBody[i]) / norm, kHessianRatioFloor);
        g[i] = std::copysign(std::pow(y, q_ - 1.0), nBody[i]);
        hessian(i, i) = std::pow(y, q_ - 2.0);
    }
    hessian -= g * g.transpose();
    return (r_ * (q_ - 1.0) / norm) * hessian;
}

double Superball::circumradius() const {
    return r_ * std::max(1.0, std::pow(3.0, 0.5 - 0.5 / p_));
}

double Superball::inradius() const {
    return r_ * std::min(1.0, std::pow(3.0, 0.5 - 0.5 / p_));
}

double Superball::meanWidth() const {
    // Over the fundamental domain n1 >= n2 >= n3 >= 0 (1/48 of the sphere), in gnomonic
    // coordinates n ~ (1, a, a t): dOmega = a da dt / (1 + a^2 + a^2 t^2)^{3/2} and
    // h(n) = R ||(1, a, a t)||_q / sqrt(1 + a^2 + a^2 t^2).
    const double integral = tanhSinh01([&](double a) {
        return tanhSinh01([&](double t) {
            const double r2 = 1.0 + a * a * (1.0 + t * t);
            return a * support(Vector3d(1.0, a, a * t)) / (r2 * r2);
        });
    });
    return 2.0 * 48.0 * integral / (4.0 * std::numbers::pi); // w = (1/4pi) int 2 h dOmega
}

Matrix3d Superball::surfaceCurvature(const Vector3d& nBody) const {
    // With y = |x| / R: Hess(xi) / |grad xi| = (2p - 1) / R diag(y^{2p-2}) / |y^{2p-1}| (the
    // 2p / R cancel).
    const Vector3d y = (supportPoint(nBody) / r_).cwiseAbs();
    Vector3d gradient, diagonal;
    for (int k = 0; k < 3; ++k) {
        gradient[k] = std::pow(y[k], 2.0 * p_ - 1.0);
        diagonal[k] = std::pow(y[k], 2.0 * p_ - 2.0);
    }
    return ((2.0 * p_ - 1.0) / (r_ * gradient.norm())) * diagonal.asDiagonal();
}

} // namespace sbpack

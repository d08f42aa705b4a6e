#include "pair/normal_newton.hpp"

#include "pair/line_search.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <optional>

namespace sbpack {
namespace {

/// The fraction of a Newton step on the normal to try first. Where the step drives a
/// body-frame component u of the normal through zero, h ~ |u|^q there: for q < 2 its second
/// derivative diverges, Newton overshoots, and u flips sign for dozens of iterations, each
/// nearly as far out. In z = sgn(u) |u|^{q-1}, where h' is linear, Newton lands it:
/// z' = z + (q - 1) |u|^{q-2} du, so u' = u (1 - w)^{1/(q-1)} with w = (q - 1) r, r = -du / u > 1
/// (u' = -u (w - 1)^{1/(q-1)} past zero), the fraction (u' - u) / du of the step. The smallest
/// over both bodies' components is returned (1 where none crosses).
double crossingFraction(const SuperballPair& pair, const Vector3d& n, const Vector3d& move) {
    const double q = pair.shape.dualExponent();
    double fraction = 1.0;
    if (q == 2.0 || !std::isfinite(q)) return fraction;
    for (const Matrix3d* rotation : {&pair.rotationA, &pair.rotationB}) {
        const Vector3d u = rotation->transpose() * n, du = rotation->transpose() * move;
        for (int c = 0; c < 3; ++c) {
            if (!(u[c] * (u[c] + du[c]) < 0.0)) continue;
            const double r = -du[c] / u[c], w = (q - 1.0) * r;
            const double landed = w < 1.0 ? 1.0 - std::pow(1.0 - w, 1.0 / (q - 1.0))
                                          : 1.0 + std::pow(w - 1.0, 1.0 / (q - 1.0));
            fraction = std::min(fraction, landed / r);
        }
    }
    return fraction;
}

/// dn/dtau of the optimal normal by the implicit function theorem: its tangent gradient
/// g = B^T (d - x_i - x_j) stays zero, so dn = B H^{-1} dg/dtau with H the tangent Hessian of
/// -f, and at fixed n each support point moves as x_k' = omega_k x x_k + d2h_k (n x omega_k) +
/// strain x_k (the body frame's direction of n turns at n x omega_k; d2h_k in the lab frame).
Vector3d optimalNormalRate(const PairRates& rates, const Vector3d& n,
                           const Eigen::Matrix<double, 3, 2>& basis, const Eigen::Matrix2d& hessian,
                           const Vector3d& xi, const Vector3d& xj, const Matrix3d& hi,
                           const Matrix3d& hj) {
    const Vector3d drift = rates.velocity - rates.strain * (xi + xj) -
                           rates.angularVelocityA.cross(xi) - hi * n.cross(rates.angularVelocityA) -
                           rates.angularVelocityB.cross(xj) - hj * n.cross(rates.angularVelocityB);
    return basis * hessian.inverse() * (basis.transpose() * drift);
}

/// f(n) = n.d - h_i(n) - h_j(n) at a unit normal, with both bodies' support jets.
struct NormalPoint {
    Vector3d n;
    Superball::SupportJet ji, jj;
    double f;
};
NormalPoint normalPoint(const SuperballPair& pair, const Vector3d& n) {
    NormalPoint point{n, pair.shape.supportJet(pair.rotationA.transpose() * n),
                      pair.shape.supportJet(pair.rotationB.transpose() * n), 0.0};
    point.f = n.dot(pair.displacement) - point.ji.value - point.jj.value;
    return point;
}

/// Newton's step H^{-1} g on the tangent plane (Cramer's rule); none unless H is positive
/// definite.
std::optional<Eigen::Vector2d> tangentStep(const Eigen::Matrix2d& h, const Eigen::Vector2d& g) {
    const double det = h(0, 0) * h(1, 1) - h(0, 1) * h(1, 0);
    if (!(h(0, 0) > 0.0 && det > 0.0)) return std::nullopt;
    return Eigen::Vector2d((h(1, 1) * g[0] - h(0, 1) * g[1]) / det,
                           (h(0, 0) * g[1] - h(1, 0) * g[0]) / det);
}

/// Backtracking: the fraction `first` of the tangent step (`basis` times `step`), halved until f
/// does not decrease (beyond rounding), at most down to an eighth of it; whether `now` ascended.
bool backtrack(const SuperballPair& pair, NormalPoint& now,
               const Eigen::Matrix<double, 3, 2>& basis, const Eigen::Vector2d& step, double first,
               int& evaluations) {
    for (double t = first; t >= 0.125 * first; t *= 0.5) {
        ++evaluations;
        const NormalPoint next = normalPoint(pair, (now.n + basis * (t * step)).normalized());
        if (next.f >= now.f - 1e-15 * pair.shape.diameter()) {
            now = next;
            return true;
        }
    }
    return false;
}

/// The robust step rule: the exact line search for the maximum of f along the great circle of
/// the tangent direction (`basis` times `direction`, `ascent` = g . direction); whether `now`
/// ascended by more than the tolerance's move of the normal (else Newton has stalled).
bool lineSearch(const SuperballPair& pair, NormalPoint& now,
                const Eigen::Matrix<double, 3, 2>& basis, const Eigen::Vector2d& direction,
                double ascent, const PairTolerances& tolerances, int& evaluations) {
    const Vector3d& d = pair.displacement;
    const Vector3d v = basis * direction;
    // Derivative of f(normalize(u)) along v at u: (d - grad H(u) - f~(u) u / |u|^2) . v / |u|,
    // f~(u) = u . d - H(u) (H homogeneous of degree 1, its gradient of degree 0).
    auto slope = [&](const Vector3d& u) {
        ++evaluations;
        const Matrix3d& ra = pair.rotationA;
        const Matrix3d& rb = pair.rotationB;
        const double r2 = u.squaredNorm();
        const double fu = u.dot(d) - pair.shape.support(ra.transpose() * u) -
                          pair.shape.support(rb.transpose() * u);
        const Vector3d gradH = ra * pair.shape.supportPoint(ra.transpose() * u) +
                               rb * pair.shape.supportPoint(rb.transpose() * u);
        return (d - gradH - fu * u / r2).dot(v) / std::sqrt(r2);
    };
    const double length = direction.norm();
    const double t = pair_search::exactLineSearch([&](double s) { return -slope(now.n + s * v); },
                                                  -ascent, tolerances.normalTolerance / length,
                                                  1.0 / length, tolerances.maxLineSearchIterations);
    ++evaluations;
    const NormalPoint next = normalPoint(pair, (now.n + t * v).normalized());
    if (!(next.f >= now.f)) return false; // no further ascent at rounding level
    now = next;
    return t * length > tolerances.normalTolerance;
}

/// The tangent step of either rule: Newton's (none where H is not positive definite) for
/// backtracking; for the line search, Newton's on H shifted to positive definite (steepest ascent
/// where that fails).
std::optional<Eigen::Vector2d> stepOf(const SuperballPair& pair, Eigen::Matrix2d hessian,
                                      const Eigen::Vector2d& gradient, NewtonStep rule) {
    if (rule == NewtonStep::backtracking) return tangentStep(hessian, gradient);
    const double shift = 1e-12 * pair.shape.semiAxis();
    const double smallest =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(hessian).eigenvalues()[0];
    if (smallest < shift) hessian.diagonal().array() += shift - smallest;
    return pair_search::newtonDirection(hessian, -gradient, 0.0);
}

/// The quadratic model of -f on the tangent plane at `now`: both support points and their lab
/// Hessians, the tangent basis, f's tangent gradient and the tangent Hessian of -f.
struct TangentModel {
    Vector3d xi, xj;
    Matrix3d hi, hj;
    Eigen::Matrix<double, 3, 2> basis;
    Eigen::Vector2d gradient;
    Eigen::Matrix2d hessian;
};
TangentModel tangentModel(const SuperballPair& pair, const NormalPoint& now) {
    const Matrix3d& qi = pair.rotationA;
    const Matrix3d& qj = pair.rotationB;
    TangentModel m;
    m.xi = qi * now.ji.point;
    m.xj = qj * now.jj.point;
    m.hi = qi * now.ji.hessian * qi.transpose();
    m.hj = qj * now.jj.hessian * qj.transpose();
    m.basis = tangentBasis(now.n);
    m.gradient = m.basis.transpose() * (pair.displacement - m.xi - m.xj);
    m.hessian = m.basis.transpose() * (m.hi + m.hj) * m.basis;
    m.hessian.diagonal().array() += now.f;
    return m;
}

/// The plane of `now` as the ascent's answer.
NormalNewton answerAt(const SuperballPair& pair, const NormalPoint& now, int iterations,
                      int evaluations, bool converged) {
    NormalNewton w{{}, converged};
    w.result.signedDistance = now.f;
    w.result.normal = now.n;
    w.result.contactA = pair.rotationA * now.ji.point;
    w.result.contactB = pair.displacement - pair.rotationB * now.jj.point;
    w.result.iterations = iterations;
    w.result.evaluations = evaluations;
    return w;
}

} // namespace

NormalNewton normalNewton(const SuperballPair& pair, const Vector3d& start,
                          const NormalNewtonOptions& options) {
    const double size = pair.shape.diameter();
    NormalPoint now = normalPoint(pair, start);
    int evaluations = 1;
    for (int iteration = 0; iteration < options.tolerances.maxNewtonIterations; ++iteration) {
        const TangentModel m = tangentModel(pair, now);
        const std::optional<Eigen::Vector2d> step =
            stepOf(pair, m.hessian, m.gradient, options.step);
        if (!step) return answerAt(pair, now, iteration, evaluations, false);
        // Converged when the tangent gradient vanishes (a step alone can be tiny under the
        // clamped, huge Hessians of flat faces) and the predicted ascent g . step is at
        // rounding level: f(n) is a lower bound on s, accurate to ~1e-17 D then.
        auto converged = [&] {
            NormalNewton w = answerAt(pair, now, iteration + 1, evaluations, true);
            if (options.rates)
                w.normalRate = optimalNormalRate(*options.rates, now.n, m.basis, m.hessian, m.xi,
                                                 m.xj, m.hi, m.hj);
            return w;
        };
        const double ascent = m.gradient.dot(*step);
        if (m.gradient.norm() <= 1e-9 * size && ascent <= 1e-17 * size) return converged();
        if (iteration > 0 && now.f > options.enough &&
            ascent <= options.boundAscentRatio * (now.f - options.enough))
            return answerAt(pair, now, iteration + 1, evaluations, false);
        // Where a body presents a face (p > 1.5: Newton on its support function, ~|x|^q with
        // q < 1.5 across the face normal, overshoots) the gradient stays large at the optimum:
        // the supporting planes' common perpendicular certifies s instead; not where the plane
        // is already the lower bound needed (bench/RESULTS.md, "Warm Newton stops where its
        // plane will do").
        if (pair.shape.p() > 1.5 && now.f <= options.enough &&
            supportPlaneMismatch(pair, now.n, now.f, m.xi, pair.displacement - m.xj) <=
                options.tolerances.mismatchTolerance * size)
            return converged();
        // Backtracking from the fraction that lands components crossing zero, or the line search.
        const bool ascended =
            options.step == NewtonStep::backtracking
                ? backtrack(pair, now, m.basis, *step,
                            crossingFraction(pair, now.n, m.basis * *step), evaluations)
                : lineSearch(pair, now, m.basis, *step, ascent, options.tolerances, evaluations);
        if (!ascended) return answerAt(pair, now, iteration + 1, evaluations, false);
    }
    return answerAt(pair, now, options.tolerances.maxNewtonIterations, evaluations, false);
}

} // namespace sbpack

#include "shapes/superball/warm_distance.hpp"

#include "geometry/superball.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <optional>

namespace sbpack::superball {
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
                           rates.angularVelocityI.cross(xi) - hi * n.cross(rates.angularVelocityI) -
                           rates.angularVelocityJ.cross(xj) - hj * n.cross(rates.angularVelocityJ);
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
                      shapeB(pair).supportJet(pair.rotationB.transpose() * n), 0.0};
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
               const Eigen::Matrix<double, 3, 2>& basis, const Eigen::Vector2d& step,
               double first) {
    for (double t = first; t >= 0.125 * first; t *= 0.5) {
        const NormalPoint next = normalPoint(pair, (now.n + basis * (t * step)).normalized());
        if (next.f >= now.f - 1e-15 * pair.shape.diameter()) {
            now = next;
            return true;
        }
    }
    return false;
}

/// s at a warm normal by Newton steps on the unit sphere with backtracking, f(n) = n.d - h_i(n) -
/// h_j(n) being concave about its maximum near contact (docs/design.md §2); the tangent Hessian of
/// -f is P^T (d2h_i + d2h_j) P + f I. Unconverged when an eighth of a step still does not ascend,
/// the Hessian is not positive definite or it takes more than limits.newtonSteps steps (slow near
/// face normals of p > 1, where the Hessian diverges, and most evaluations of near-cubes), or,
/// where a lower bound above `enough` will do, as soon as its plane is one
/// (limits.boundAscentRatio).
WarmNewton newtonSignedDistance(const SuperballPair& pair, Vector3d n,
                                const SuperballPredictorLimits& limits,
                                const PairRates* rates = nullptr, double enough = kNoContact) {
    const Matrix3d& qi = pair.rotationA;
    const Matrix3d& qj = pair.rotationB;
    const Vector3d& d = pair.displacement;
    const double size = pair.shape.diameter();
    NormalPoint now = normalPoint(pair, n);
    auto answer = [&](int iterations, bool converged) {
        WarmNewton w{{}, converged};
        w.result.signedDistance = now.f;
        w.result.normal = now.n;
        w.result.contactA = qi * now.ji.point;
        w.result.contactB = d - qj * now.jj.point;
        w.result.iterations = iterations;
        return w;
    };
    for (int iteration = 0; iteration < limits.newtonSteps; ++iteration) {
        const Vector3d xi = qi * now.ji.point, xj = qj * now.jj.point;
        const Eigen::Matrix<double, 3, 2> basis = tangentBasis(now.n);
        const Eigen::Vector2d gradient = basis.transpose() * (d - xi - xj);
        const Matrix3d hi = qi * now.ji.hessian * qi.transpose();
        const Matrix3d hj = qj * now.jj.hessian * qj.transpose();
        Eigen::Matrix2d hessian = basis.transpose() * (hi + hj) * basis;
        hessian.diagonal().array() += now.f;
        const std::optional<Eigen::Vector2d> step = tangentStep(hessian, gradient);
        if (!step) return answer(iteration, false);
        // Converged when the tangent gradient vanishes (a step alone can be tiny under the
        // clamped, huge Hessians of flat faces) and the predicted ascent g . step is at
        // rounding level: f(n) is a lower bound on s, accurate to ~1e-17 D then.
        auto converged = [&] {
            WarmNewton w = answer(iteration + 1, true);
            if (rates)
                w.normalRate = optimalNormalRate(*rates, now.n, basis, hessian, xi, xj, hi, hj);
            return w;
        };
        const double ascent = gradient.dot(*step);
        if (gradient.norm() <= 1e-9 * size && ascent <= 1e-17 * size) return converged();
        if (iteration > 0 && now.f > enough && ascent <= limits.boundAscentRatio * (now.f - enough))
            return answer(iteration + 1, false);
        // Where a body presents a face (p > 1.5: Newton on its support function, ~|x|^q with
        // q < 1.5 across the face normal, overshoots) the gradient stays large at the optimum:
        // the supporting planes' common perpendicular certifies s instead; not where the plane
        // is already the lower bound needed (bench/RESULTS.md, "Warm Newton stops where its
        // plane will do").
        if (pair.shape.p() > 1.5 && now.f <= enough &&
            supportPlaneMismatch(pair, now.n, now.f, xi, d - xj) <=
                PairTolerances{}.mismatchTolerance * size)
            return converged();
        // Backtracking from the fraction that lands components crossing zero.
        if (!backtrack(pair, now, basis, *step, crossingFraction(pair, now.n, basis * *step)))
            return answer(iteration + 1, false);
    }
    return answer(limits.newtonSteps, false);
}

/// Whether the point x (relative to r_A) lies strictly inside both bodies of the pair.
bool insideBoth(const SuperballPair& pair, const Vector3d& x) {
    constexpr double kInside = 1.0 - 1e-14;
    return pair.shape.gauge(pair.rotationA.transpose() * x) < kInside &&
           shapeB(pair).gauge(pair.rotationB.transpose() * (x - pair.displacement)) < kInside;
}

/// Newton again from the face normal of either body with the largest plane gap (better than
/// the unconverged `warm`'s); kept when it converges or ends higher.
void restartFromFaces(const SuperballPair& pair, WarmNewton& warm,
                      const SuperballPredictorLimits& limits, PredictorStats& stats,
                      const PairRates* rates, double boundSuffices) {
    Vector3d best = Vector3d::Zero();
    double bestGap = warm.result.signedDistance;
    for (const Matrix3d* rotation : {&pair.rotationA, &pair.rotationB})
        for (int axis = 0; axis < 3; ++axis) {
            const Vector3d face = rotation->col(axis);
            const Vector3d n = face.dot(pair.displacement) >= 0.0 ? face : Vector3d(-face);
            const double gap = n.dot(pair.displacement) -
                               pair.shape.support(pair.rotationA.transpose() * n) -
                               shapeB(pair).support(pair.rotationB.transpose() * n);
            if (gap > bestGap) {
                bestGap = gap;
                best = n;
            }
        }
    if (best.isZero(0.0)) return;
    WarmNewton restart = newtonSignedDistance(pair, best, limits, rates, boundSuffices);
    stats.newtonSteps += restart.result.iterations;
    if (restart.converged || restart.result.signedDistance > warm.result.signedDistance)
        warm = restart;
}

/// Near contact, where warm Newton did not converge: the maximum of f over the normals near its
/// last one, if it lies inside that neighbourhood (docs/design.md §3, "Near-cubes"). Near-cubes
/// meeting edge to edge or edge to vertex have their optimal normal within rounding of the
/// plane of an edge of each body, where the support point along the edge is undetermined (it
/// runs as |u|^{q-1}, q - 1 = 1 / (2p - 1)): f is exact there but neither its gradient nor the
/// supporting planes' mismatch can vanish, so Newton cannot certify it. The cutting-plane search
/// needs no certificate (f is quasi-concave for s >= 0, and an interior maximum is the global
/// one) and costs a fraction of the robust solver's scale factor and search over 0.6 rad.
std::optional<SignedDistanceResult> localMaximum(const SuperballPair& pair, const Vector3d& n,
                                                 const SuperballPredictorLimits& limits,
                                                 PredictorStats& stats) {
    ++stats.localSearches;
    const LocalMaximum local =
        tangentMaximum(pair, n, limits.localSearchRadius, limits.localSearchResolution,
                       PairTolerances{}.maxCuttingPlaneIterations);
    if (!local.interior) return std::nullopt;
    SignedDistanceResult r = atNormal(pair, local.normal);
    r.signedDistance = local.value;
    return r;
}

/// What serves of warm Newton's answer: converged, its result; unconverged above the bound
/// (`lowerBound`), its plane; below it, near-cubes' local maximum. None where that is an overlap
/// without a witness: a positive local maximum of f is the global one (f(u) - c |u| is concave
/// for c > 0), but Newton from a stale normal can end on a negative local maximum while the
/// bodies are apart. It stands (a lower bound on s, as the robust solver's own answer for
/// overlaps) when the midpoint of the two support points lies inside both bodies.
std::optional<SignedDistanceResult> servingResult(const SuperballPair& pair, const WarmNewton& warm,
                                                  bool lowerBound,
                                                  const SuperballPredictorLimits& limits,
                                                  PredictorStats& stats) {
    std::optional<SignedDistanceResult> fast;
    if (warm.converged) {
        fast = warm.result;
    } else if (lowerBound) {
        fast = warm.result;
        ++stats.lowerBounds;
    } else if (pair.shape.p() > 1.0) {
        fast = localMaximum(pair, warm.result.normal, limits, stats);
    }
    if (fast && fast->signedDistance < -1e-12 * pair.shape.diameter() &&
        !insideBoth(pair, 0.5 * (fast->contactA + fast->contactB)))
        fast.reset();
    return fast;
}

} // namespace

/// The plane of unit n as the pair's answer: its gap n.d - h_i(n) - h_j(n) and the two support
/// points (relative to r_i).
SignedDistanceResult atNormal(const SuperballPair& pair, const Vector3d& n) {
    SignedDistanceResult r;
    r.normal = n;
    r.contactA = pair.rotationA * pair.shape.supportPoint(pair.rotationA.transpose() * n);
    r.contactB = pair.displacement -
                 pair.rotationB * shapeB(pair).supportPoint(pair.rotationB.transpose() * n);
    r.signedDistance = n.dot(r.contactB - r.contactA);
    return r;
}

/// s of the pair from its cached normal (updated), or from the centre line when there is none
/// (f has one maximum for s >= 0): Newton, else the robust solver. Where a lower bound on s will
/// do, one above `boundSuffices` (unconverged Newton's last plane gap) is returned as it is.
/// With `rates`, Newton's converged answers also carry the normal's rate (else it is zero).
WarmNewton exactSignedDistance(const SuperballPair& pair, Vector3d& normal, double boundSuffices,
                               const SuperballPredictorLimits& limits, PredictorStats& stats,
                               const PairRates* rates) {
    WarmNewton warm =
        newtonSignedDistance(pair, normal.isZero(0.0) ? pair.displacement.normalized() : normal,
                             limits, rates, boundSuffices);
    stats.newtonSteps += warm.result.iterations;
    // Unconverged below the bound (near-cubes, whose support functions are nearly piecewise
    // linear): Newton again from the best face normal of either body, where their contacts lie.
    if (!warm.converged && warm.result.signedDistance <= boundSuffices && pair.shape.p() > 1.0)
        restartFromFaces(pair, warm, limits, stats, rates, boundSuffices);
    // Unconverged above the bound: its plane, a lower bound on s, serves as it is.
    const bool lowerBound = !warm.converged && warm.result.signedDistance > boundSuffices;
    const std::optional<SignedDistanceResult> fast =
        servingResult(pair, warm, lowerBound, limits, stats);
    if (!fast) ++stats.robustEvaluations;
    const WarmNewton answer =
        fast ? WarmNewton{*fast, true, warm.converged ? warm.normalRate : Vector3d::Zero(),
                          !lowerBound}
             : WarmNewton{signedDistance(pair, normal), true};
    stats.distanceFallbacks += answer.result.fallbacks;
    normal = answer.result.normal;
    return answer;
}

} // namespace sbpack::superball

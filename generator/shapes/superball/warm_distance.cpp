#include "shapes/superball/warm_distance.hpp"

#include "geometry/superball.hpp"
#include "pair/normal_newton.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <optional>

namespace sbpack::superball {
namespace {

/// Warm Newton (common/pair/normal_newton.hpp) within the predictor's limits: limits.newtonSteps
/// steps (slow near face normals of p > 1, where the Hessian diverges, and in most evaluations
/// of near-cubes), stopping where a lower bound above `enough` will do (limits.boundAscentRatio).
WarmNewton newtonSignedDistance(const SuperballPair& pair, const Vector3d& n,
                                const SuperballPredictorLimits& limits, const PairRates* rates,
                                double enough) {
    PairTolerances tolerances;
    tolerances.maxNewtonIterations = limits.newtonSteps;
    const NormalNewton ascent = normalNewton(
        pair, n, {tolerances, NewtonStep::backtracking, enough, limits.boundAscentRatio, rates});
    return {ascent.result, ascent.converged, ascent.normalRate};
}

/// Whether the point x (relative to r_A) lies strictly inside both bodies of the pair.
bool insideBoth(const SuperballPair& pair, const Vector3d& x) {
    constexpr double kInside = 1.0 - 1e-14;
    return pair.shape.gauge(pair.rotationA.transpose() * x) < kInside &&
           pair.shape.gauge(pair.rotationB.transpose() * (x - pair.displacement)) < kInside;
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
                               pair.shape.support(pair.rotationB.transpose() * n);
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
                 pair.rotationB * pair.shape.supportPoint(pair.rotationB.transpose() * n);
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

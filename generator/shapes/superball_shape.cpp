#include "shapes/superball_shape.hpp"

#include "geometry/superball.hpp"
#include "pair/pair_geometry.hpp"
#include "shapes/sphere.hpp"
#include "shapes/witness_bound.hpp"


#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

namespace sbpack {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

/// A separating plane's gap g_n(tau) = n.d(tau) - h_i(n) - h_j(n), its exact rate, and the two
/// support points of n in the bodies' frames at semi-axis 1 (a witness record's points).
struct PlaneGap {
    double gap = 0.0;
    double rate = 0.0;
    Vector3d pointI = Vector3d::Zero(), pointJ = Vector3d::Zero();
};

/// dg_n/dtau from the two support points x_k (lab frame, about each centre) by the envelope
/// theorem: dh_k/dtau = (gamma / D) h_k + n . (omega_k x x_k), h_k = n . x_k.
double planeGapRate(const PairMotion& m, double diameter, const Vector3d& n, const Vector3d& xI,
                    const Vector3d& xJ) {
    return n.dot(m.relativeVelocity) - (m.growthRate / diameter) * n.dot(xI + xJ) -
           n.dot(m.angularVelocityI.cross(xI)) - n.dot(m.angularVelocityJ.cross(xJ));
}

/// s, its exact rate ds/dtau and the normal of the pair after tau, with that normal's plane gap
/// rate (ds/dtau but for where the impulse's point lies).
struct Sample {
    double tau = 0.0;
    double gap = 0.0;
    double rate = 0.0;
    Vector3d normal = Vector3d::Zero();
    double planeRate = 0.0;
    bool exact = true; ///< false: gap is a lower bound on s (a plane that separates them)
};

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

/// How the evaluated pair moves at that instant: d' = velocity, each body turns at its omega and
/// grows at R'/R = strain.
struct PairRates {
    Vector3d velocity;
    Vector3d angularVelocityI, angularVelocityJ;
    double strain;
};

/// Warm Newton's answer: s when converged, else its last iterate, whose f(n) is still a lower
/// bound on s (every plane's gap is). `normalRate`: dn/dtau of the optimal normal when converged
/// and the rates were given, else zero.
struct WarmNewton {
    SignedDistanceResult result;
    bool converged = false;
    Vector3d normalRate = Vector3d::Zero();
    bool exact = true; ///< false: the result is unconverged Newton's plane, a lower bound on s
};

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
                                const PairRates* rates = nullptr, double enough = kNever) {
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
        // is already the lower bound needed (1.02-1.15x per collision at p = 3 to 10:
        // bench/RESULTS.md, "Warm Newton stops where its plane will do").
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
           pair.shape.gauge(pair.rotationB.transpose() * (x - pair.displacement)) < kInside;
}

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

/// s of the pair from its cached normal (updated), or from the centre line when there is none
/// (f has one maximum for s >= 0): Newton, else the robust solver. Where a lower bound on s will
/// do, one above `boundSuffices` (unconverged Newton's last plane gap) is returned as it is.
/// With `rates`, Newton's converged answers also carry the normal's rate (else it is zero).
WarmNewton exactSignedDistance(const SuperballPair& pair, Vector3d& normal, double boundSuffices,
                               const SuperballPredictorLimits& limits, PredictorStats& stats,
                               const PairRates* rates = nullptr) {
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
    std::optional<SignedDistanceResult> fast;
    if (warm.converged) fast = warm.result;
    if (!warm.converged && !lowerBound && pair.shape.p() > 1.0)
        fast = localMaximum(pair, warm.result.normal, limits, stats);
    if (lowerBound) {
        fast = warm.result;
        ++stats.lowerBounds;
    }
    // A positive local maximum of f is the global one (f(u) - c |u| is concave for c > 0), but
    // Newton from a stale normal can end on a negative local maximum while the bodies are apart.
    // It stands (a lower bound on s, as the robust solver's own answer for overlaps) when a
    // witness certifies the overlap: the midpoint of the two support points inside both bodies.
    if (fast && fast->signedDistance < -1e-12 * pair.shape.diameter() &&
        !insideBoth(pair, 0.5 * (fast->contactA + fast->contactB)))
        fast.reset();
    if (!fast) ++stats.robustEvaluations;
    const WarmNewton answer =
        fast ? WarmNewton{*fast, true, warm.converged ? warm.normalRate : Vector3d::Zero(),
                          !lowerBound}
             : WarmNewton{signedDistance(pair, normal), true};
    stats.distanceFallbacks += answer.result.fallbacks;
    normal = answer.result.normal;
    return answer;
}

/// The pair along its motion, evaluated exactly, each evaluation warm-started from the last
/// normal (the pair's cached one at first).
class PairTrajectory {
  public:
    PairTrajectory(const PairMotion& m, double p, Vector3d& normal,
                   const SuperballPredictorLimits& limits, PredictorStats& stats)
        : m_(m), p_(p), normal_(normal), limits_(limits), stats_(stats) {}

    Sample at(double tau) {
        ++stats_.evaluations;
        const double diameter = m_.diameter + m_.growthRate * tau;
        const Vector3d d = m_.displacement + m_.relativeVelocity * tau;
        const SuperballPair pair{
            Superball(p_, 0.5 * diameter),
            advancedOrientation(m_.orientationI, m_.angularVelocityI, tau).toRotationMatrix(),
            advancedOrientation(m_.orientationJ, m_.angularVelocityJ, tau).toRotationMatrix(), d};
        const double strain = m_.growthRate / diameter;
        const PairRates rates{m_.relativeVelocity, m_.angularVelocityI, m_.angularVelocityJ,
                              strain};
        // Warm start: the last optimal normal carried along at its rate (first order in the
        // time since, while that turns it by less than limits.maxNormalCarry).
        const Vector3d shift = normalRate_ * (tau - lastTau_);
        if (shift.norm() < limits_.maxNormalCarry) normal_ = (normal_ + shift).normalized();
        // Wherever it proves the pair apart (above the contact gap) a lower bound on s serves:
        // its plane advances as well, and every decision there (not touching, which side of a
        // bracket) holds for s too. Near-cubes gain most: there an unconverged Newton's plane
        // spares the local search, which cost about half of p = 10's time (bench/RESULTS.md,
        // "Near-cubes: lower bounds down to the contact gap").
        const WarmNewton evaluation = exactSignedDistance(
            pair, normal_, limits_.contactGap * diameter, limits_, stats_, &rates);
        lastTau_ = tau;
        normalRate_ = evaluation.normalRate;
        return sample(tau, evaluation.result, evaluation.exact);
    }

    /// The sample at tau = 0 of an exact evaluation made elsewhere at this state (the contact
    /// the engine has just resolved), warm start of the next.
    Sample given(const SignedDistanceResult& r) {
        normal_ = r.normal;
        lastTau_ = 0.0;
        normalRate_ = Vector3d::Zero();
        return sample(0.0, r, true);
    }

  private:
    // ds/dtau by the envelope theorem: the closing speed along n of the two support points,
    // each moving at omega x x + (gamma / D) x about its own centre; taken at their midpoint,
    // the point where the resolver applies the impulse, so that "closing" means the same to
    // both (on near-flat faces the support points can lie far apart on the face).
    Sample sample(double tau, const SignedDistanceResult& r, bool exact) const {
        const double diameter = m_.diameter + m_.growthRate * tau;
        const Vector3d d = m_.displacement + m_.relativeVelocity * tau;
        const double strain = m_.growthRate / diameter;
        const Vector3d xI = 0.5 * (r.contactA + r.contactB), xJ = xI - d;
        const Vector3d vI = m_.angularVelocityI.cross(xI) + strain * xI;
        const Vector3d vJ = m_.angularVelocityJ.cross(xJ) + strain * xJ;
        return {tau,
                r.signedDistance,
                r.normal.dot(m_.relativeVelocity + vJ - vI),
                r.normal,
                planeGapRate(m_, diameter, r.normal, r.contactA, d - r.contactB),
                exact};
    }

    const PairMotion& m_;
    double p_;
    Vector3d& normal_;
    const SuperballPredictorLimits& limits_;
    PredictorStats& stats_;
    double lastTau_ = 0.0;
    Vector3d normalRate_ = Vector3d::Zero(); ///< of normal_ at lastTau_ (zero: unknown)
};

/// A bisection fallback of the refinement every this many steps when regula falsi stalls.
constexpr int kBisectEvery = 4;
/// A refinement step closer than this fraction of the bracket to its ends counts as stalled.
constexpr double kStallFraction = 1e-3;
/// The bracket is resolved when narrower than this many ulps (relative to 1 + tau).
constexpr double kBracketWidth = 4e-16;
/// The chord step tried first is at most this fraction of the chord's reach sqrt(8 g / M).
constexpr double kChordReach = 0.9;
/// Each further chord try is this fraction of the last.
constexpr double kChordShrink = 0.125;

/// The circumscribed spheres' window (tier 1 of the predictor): `enter`, when they first
/// overlap (0 if now), and `end`, when they part for good (or the horizon); none if they do not
/// meet before the horizon.
struct SphereWindow {
    double enter = 0.0;
    double end = kNever;
};
std::optional<SphereWindow> circumscribedWindow(const PairMotion& m, double c, double horizon) {
    const double D = m.diameter, gamma = m.growthRate;
    const PairMotion spheres{m.displacement, m.relativeVelocity, {}, {}, {}, {}, c * D, c * gamma};
    const double enter =
        m.displacement.squaredNorm() <= c * c * D * D ? 0.0 : SphereShape{}.collisionTime(spheres);
    if (enter >= horizon) return std::nullopt;
    double end = horizon;
    const double a = m.relativeVelocity.squaredNorm() - c * c * gamma * gamma;
    if (a > 0.0) { // after the spheres part for good, nothing touches
        const double b = m.displacement.dot(m.relativeVelocity) - c * c * D * gamma;
        const double c0 = m.displacement.squaredNorm() - c * c * D * D;
        end = std::min(end, (-b + std::sqrt(std::max(0.0, b * b - a * c0))) / a);
    }
    return SphereWindow{enter, end};
}

/// A pair's prediction as PairPrediction finds it: a Prediction, with the contact normal at the
/// root where it found a contact (zero otherwise).
struct Found {
    double time;
    bool contact = true;
    Vector3d normal = Vector3d::Zero();
};

/// One prediction of a superball pair inside its circumscribed spheres' window (tiers 2 and 3,
/// generator/shapes/superball_shape.hpp): the plane bounds of a normal (planeRate,
/// planeCurvature, planeGap), conservative advancement along planes (alongPlane), Newton steps in
/// time near contact (newtonInTime), the safeguarded refinement of a bracket (refine) and the
/// certificate of a root (advance).
class PairPrediction {
  public:
    PairPrediction(const PairMotion& m, double p, double c, double lever, SphereWindow window,
                   Vector3d& normal, const SuperballPredictorLimits& limits, PredictorStats& stats)
        : m_(m), p_(p), c_(c), growth_(std::max(m.growthRate, 0.0)), end_(window.end),
          leverBound_(lever * 0.5 * (m.diameter + growth_ * window.end)),
          radiusBound_(c * 0.5 * (m.diameter + growth_ * window.end)), limits_(limits),
          stats_(stats), trajectory_(m, p, normal, limits, stats),
          touching_(limits.contactGap * m.diameter), near_(limits.nearGap * m.diameter) {}

    double end() const { return end_; }

    // The plane bound's rate at unit normal n, valid up to `end` (R at its largest there):
    // dh_k/dtau = (n x omega_k) . x_k with x_k the support point, and only its part normal to n
    // counts, |x_perp|^2 = |x|^2 - h^2 <= (c^2 - c_in^2) R^2 (the lever; 0 for spheres).
    double planeRate(const Vector3d& n) const {
        return n.dot(m_.relativeVelocity) -
               (n.cross(m_.angularVelocityI).norm() + n.cross(m_.angularVelocityJ).norm()) *
                   leverBound_ -
               c_ * growth_;
    }

    // Second-order bound of the same plane: along the rotation the body-frame direction of n
    // runs on a circle, |u'| = |n x omega|, |u''| = |n x omega| |omega|, and a support function
    // there has h'' = u'^T (d2h) u' + x . u'' >= -c R |n x omega| |omega| (h is convex); growth
    // adds (R h_hat)'' = gamma h_hat' + R h_hat''. So g_n'' <= M_n = sum_k |n x omega_k|
    // (c gamma + c R |omega_k|), g_n - M_n t^2 / 2 is concave, and on [t0, t1] g_n lies above its
    // chord minus M_n (t - t0)(t1 - t) / 2 >= min(g0, g1) - M_n (t1 - t0)^2 / 8: one plane gap at
    // t1 certifies the whole step, however fast the first-order bound says s could fall.
    double planeCurvature(const Vector3d& n) const {
        return n.cross(m_.angularVelocityI).norm() *
                   (c_ * growth_ + radiusBound_ * m_.angularVelocityI.norm()) +
               n.cross(m_.angularVelocityJ).norm() *
                   (c_ * growth_ + radiusBound_ * m_.angularVelocityJ.norm());
    }

    // The plane gap g_n(tau) itself and its exact rate: two support points.
    PlaneGap planeGap(const Vector3d& n, double tau) const {
        const double diameter = m_.diameter + m_.growthRate * tau;
        const Superball body(p_, 0.5 * diameter);
        const Matrix3d qi =
            advancedOrientation(m_.orientationI, m_.angularVelocityI, tau).toRotationMatrix();
        const Matrix3d qj =
            advancedOrientation(m_.orientationJ, m_.angularVelocityJ, tau).toRotationMatrix();
        const Vector3d bodyI = body.supportPoint(qi.transpose() * n);
        const Vector3d bodyJ = body.supportPoint(qj.transpose() * n);
        const Vector3d xI = qi * bodyI, xJ = qj * bodyJ;
        return {n.dot(m_.displacement + m_.relativeVelocity * tau - xI - xJ),
                planeGapRate(m_, diameter, n, xI, xJ), bodyI / body.semiAxis(),
                bodyJ / body.semiAxis()};
    }

    /// Tier 3 from `start` (the cached plane's gap `cached` at tau = 0 known): advancement along
    /// the cached plane, then from exact samples along their planes, Newton steps in time near
    /// contact, and the certificate of the root they reach. `resolved`: the pair was resolved at
    /// this very state, whose contact seen from i is `contact` where known (the sample at
    /// tau = 0 without an evaluation).
    Found advance(double start, const Vector3d& normal, PlaneGap cached, bool resolved,
                  const std::optional<SignedDistanceResult>& contact, PairMemory& memory);

  private:
    Sample refine(Sample left, Sample right);
    std::variant<double, Found> alongPlane(const Vector3d& n, double tau, PlaneGap g,
                                           double reference);
    std::optional<Sample> newtonInTime(const Sample& from);
    /// Near contact and closing: Newton steps in time and the certificate of the root they
    /// reach. The prediction when that decides it; else none, with `end` shortened to an
    /// uncertified root.
    std::optional<Found> rootNear(const Sample& now);
    /// A chord step from (tau, g) along n that certifies, if any (chordStep false otherwise).
    struct Chord {
        bool step = false;
        bool reachedEnd = false;
        double tau = 0.0;
        PlaneGap gap;
    };
    Chord chordStep(const Vector3d& n, double tau, const PlaneGap& g, double firstOrder,
                    double curvature);

    const PairMotion& m_;
    double p_, c_, growth_;
    double end_; ///< no contact is looked for beyond (shortened to an uncertified root)
    double leverBound_, radiusBound_;
    const SuperballPredictorLimits& limits_;
    PredictorStats& stats_;
    PairTrajectory trajectory_;
    double touching_, near_;
    int steps_ = 0;
    Found atEnd_{kNever}; ///< what reaching `end` means: no contact, or a known one there
};

// Safeguarded Newton on s over a bracket gap(left) > 0 >= gap(right): the Newton step from
// the end nearer to zero (s has an exact rate), regula falsi when it leaves the bracket and
// bisection when that stalls. Returns the safe (left) end once it touches, so an overlap is
// never accepted (or the right end at a rounding-level overlap). If it stalls (s jumps where
// the pair solver's kinks make it inconsistent), the left end, not touching, becomes a safe
// recheck time.
Sample PairPrediction::refine(Sample left, Sample right) {
    for (int k = 0; k < limits_.maxRefinementSteps; ++k) {
        const double width = right.tau - left.tau;
        if (left.gap <= touching_ || width <= kBracketWidth * (1.0 + right.tau)) return left;
        if (right.gap >= -touching_) return right; // touching at rounding
        const Sample& nearer = left.gap < -right.gap ? left : right;
        double tau = nearer.rate < 0.0 ? nearer.tau - nearer.gap / nearer.rate : -1.0;
        if (!(tau > left.tau && tau < right.tau))
            tau = (left.tau * right.gap - right.tau * left.gap) / (right.gap - left.gap);
        if (!(tau > left.tau + kStallFraction * width &&
              tau < right.tau - kStallFraction * width) &&
            k % kBisectEvery == kBisectEvery - 1)
            tau = 0.5 * (left.tau + right.tau);
        const Sample mid = trajectory_.at(tau);
        ++stats_.refinementSteps;
        (mid.gap > 0.0 ? left : right) = mid;
    }
    ++stats_.limitHits;
    return left;
}

// The chord step where it certifies (up to `end`, or 0.9 of its reach sqrt(8 gap / M), then
// eighths of that while longer than the first-order step). The first chord tried: where the
// plane's tangent g + r t is still k = 32 times the chord's margin M t^2 / 8, the root of
// (k M / 8) t^2 - r t - g (a guess from the exact rate, since g'' has no lower bound; only the
// chord certifies). At p = 1.5 it halves the plane gaps per collision against trying 0.9 of the
// chord's reach first.
PairPrediction::Chord PairPrediction::chordStep(const Vector3d& n, double tau, const PlaneGap& g,
                                                double firstOrder, double curvature) {
    const double chord = curvature > 0.0 ? std::sqrt(8.0 * g.gap / curvature) : kNever;
    const double margin = std::sqrt(g.rate * g.rate + 16.0 * curvature * g.gap);
    const double likely =
        g.rate > 0.0 ? (g.rate + margin) / (8.0 * curvature) : 2.0 * g.gap / (margin - g.rate);
    for (double tryStep = std::min({end_ - tau, kChordReach * chord, likely});
         g.gap > 0.0 && tryStep > firstOrder; tryStep *= kChordShrink) {
        const PlaneGap far = planeGap(n, tau + tryStep);
        ++stats_.planeSteps;
        if (std::min(g.gap, far.gap) > 0.125 * curvature * tryStep * tryStep) {
            ++stats_.chordSteps;
            return {true, tau + tryStep >= end_, tau + tryStep, far};
        }
    }
    return {};
}

// Advancement along the plane of unit n from (tau, gap), each step ending at a cheap plane
// gap: a chord step where one certifies, else the first-order step gap / |plane rate|; until
// the gap drops below half of `reference`. Returns the time reached, or the prediction when the
// plane separates them up to `end` or the step limit is reached (a safe recheck time).
std::variant<double, Found> PairPrediction::alongPlane(const Vector3d& n, double tau, PlaneGap g,
                                                       double reference) {
    const double rate = planeRate(n), curvature = planeCurvature(n);
    do {
        if (rate >= 0.0) return atEnd_; // this plane separates them up to `end`
        if (++steps_ > limits_.maxAdvancementSteps) {
            ++stats_.rechecks;
            return Found{tau, false};
        }
        const double firstOrder = std::max(g.gap, touching_) / -rate;
        const Chord chord = chordStep(n, tau, g, firstOrder, curvature);
        if (chord.step) {
            if (chord.reachedEnd) return atEnd_;
            tau = chord.tau;
            g = chord.gap;
            continue;
        }
        tau += firstOrder;
        if (tau >= end_) return atEnd_;
        g = planeGap(n, tau);
        ++stats_.planeSteps;
    } while (g.gap > 0.5 * reference);
    return tau;
}

// Newton steps in time from an exact sample (each iterate exact, or above the contact gap a
// lower bound that proves the pair apart there; rootNear's certificate covers the whole step
// either way), until one touches (closing)
// or brackets a root (then refined); none when an iterate turns away, would pass `end`, goes
// beyond the reach where the root's certificate (M (t1 - t0)^2 / 2 < g(t0), in advance) keeps a
// margin of four, M (t1 - t0)^2 / 2 <= g(t0) / 4 (the root normal's plane lies below s at
// t0), or the limit is reached. Where s is convex in time the iterates approach the root from
// outside, quadratically, and no step needs certifying on the way: the root found is
// certified as the first one from the start.
std::optional<Sample> PairPrediction::newtonInTime(const Sample& from) {
    const double reach = from.tau + std::sqrt(0.5 * from.gap / planeCurvature(from.normal));
    Sample last = from;
    for (int k = 0; k < limits_.newtonStepsInTime; ++k) {
        const double tau = last.tau - last.gap / last.rate;
        if (!(tau > last.tau && tau <= std::min(end_, reach))) return std::nullopt;
        const Sample trial = trajectory_.at(tau);
        if (trial.gap <= 0.0) {
            ++stats_.newtonBrackets;
            return refine(last, trial);
        }
        if (trial.rate >= 0.0) return std::nullopt;
        if (trial.gap <= touching_) return trial;
        last = trial;
    }
    return std::nullopt;
}

// Near contact and closing, Newton steps in time; the root t1 they reach is the first one if
// the root normal's plane certifies [t0, t1): with g'' <= M and g(t1) ~ 0,
// g >= chord - M (t - t0)(t1 - t) / 2 > 0 there when g(t0) > M (t1 - t0)^2 / 2. Otherwise
// (s dips below zero and back within the step: rare, spin-driven) advancement goes on
// without Newton steps up to that root.
std::optional<Found> PairPrediction::rootNear(const Sample& now) {
    const double rate = planeRate(now.normal);
    if (!(atEnd_.time == kNever && now.exact && now.gap <= near_ && now.rate < 0.0 && rate < 0.0))
        return std::nullopt;
    const double tau = now.tau - now.gap / now.rate;
    const std::optional<Sample> root =
        tau > now.tau + now.gap / -rate ? newtonInTime(now) : std::nullopt;
    if (!root) return std::nullopt;
    if (root->gap > touching_) return Found{root->tau, false}; // refinement stalled
    const double dt = root->tau - now.tau;
    if (planeGap(root->normal, now.tau).gap > 0.5 * planeCurvature(root->normal) * dt * dt)
        return Found{root->tau, true, root->normal};
    ++stats_.uncertifiedRoots;
    end_ = root->tau;
    atEnd_ = {root->tau, true, root->normal};
    return std::nullopt;
}

Found PairPrediction::advance(double start, const Vector3d& normal, PlaneGap cached, bool resolved,
                              const std::optional<SignedDistanceResult>& contact,
                              PairMemory& memory) {
    if (cached.gap > touching_) {
        const auto reached = alongPlane(normal, 0.0, cached, cached.gap);
        if (const Found* done = std::get_if<Found>(&reached)) return *done;
        start = std::max(start, std::get<double>(reached));
    }
    memory.gap = -kNever; // the exact evaluations move the normal on
    Sample now = contact && start == 0.0 ? trajectory_.given(*contact) : trajectory_.at(start);
    if (start == 0.0 && now.gap < -touching_) ++stats_.startOverlaps;
    for (;;) {
        // A pair resolved at this very state touches now with no contact, by any path: Newton
        // steps in time from it would end on the same sample (refine returns a touching end).
        const bool justResolved = resolved && now.tau == 0.0;
        if (now.gap <= touching_ && now.rate < 0.0 && !justResolved)
            return {now.tau, true, now.normal};
        if (!justResolved)
            if (const std::optional<Found> decided = rootNear(now)) return *decided;
        const auto reached = alongPlane(now.normal, now.tau, {now.gap, now.planeRate}, now.gap);
        if (const Found* done = std::get_if<Found>(&reached)) return *done;
        const Sample previous = now;
        now = trajectory_.at(std::get<double>(reached));
        if (now.gap <= 0.0 && previous.gap > touching_) {
            const Sample root = refine(previous, now);
            return {root.tau, root.gap <= touching_, root.normal};
        }
    }
}

} // namespace

SuperballShape::SuperballShape(double p)
    : p_(p), c_(Superball(p, 1.0).circumradius()), cIn_(Superball(p, 1.0).inradius()),
      lever_(std::sqrt(c_ * c_ - cIn_ * cIn_)),
      witness_(p > 0.5 ? std::optional(supportHolderBound(p)) : std::nullopt),
      inertiaPerMassUnit_(Superball(p, 1.0).inertiaPerMass()) {}

double SuperballShape::inertiaPerMass(double diameter) const {
    return inertiaPerMassUnit_ * 0.25 * diameter * diameter;
}

// Tier 1: the circumscribed spheres meet before the horizon. Tier 2: the cached normal's
// separating plane holds up to `end`, by the first-order bound from the remembered lower bound on
// its gap (no support point), by the pair's witness record (shapes/witness_bound.hpp: its
// material points, whatever either particle did since), or from its exact gap, then by the
// chord to `end`; a pair without a normal (after a rebuild) tries the centre line's. The exact
// gap's support points become the witness record; either plane bound, with this motion's rate,
// is left for the next prediction. Tier 3: conservative advancement on exact s (PairPrediction).
Prediction SuperballShape::collisionTime(const PairMotion& m, double horizon, PairMemory& memory,
                                         bool resolved) {
    ++stats.calls;
    Vector3d& normal = memory.normal;
    const double remembered = memory.gap;
    memory.gap = -kNever; // unless a bound on this normal's gap now is known below
    memory.atContact = false;
    const Prediction none{kNever};
    if (!(horizon > 0.0)) return none;
    const std::optional<SphereWindow> window = circumscribedWindow(m, c_, horizon);
    if (!window) {
        ++stats.sphereRejections;
        return none;
    }
    PairPrediction prediction(m, p_, c_, lever_, *window, normal, limits, stats);
    const double end = window->end;
    if (normal.isZero(0.0)) normal = m.displacement.normalized();
    const double fall = std::min(0.0, prediction.planeRate(normal));
    auto separatedToEnd = [&](double gap) { return gap > 0.0 && gap + fall * end > 0.0; };
    auto bound = [&](double gap) {
        memory.gap = gap;
        memory.rate = fall;
        memory.span = end;
    };
    if (separatedToEnd(remembered)) {
        ++stats.boundRejections;
        bound(remembered);
        return none;
    }
    if (witness_ && witnessSeparates(m, normal, memory.witness, *witness_, c_, end,
                                     limits.contactGap * m.diameter)) {
        ++stats.witnessRejections;
        return none;
    }
    const PlaneGap cached = prediction.planeGap(normal, 0.0);
    const Vector3d recorded = normal;
    bound(cached.gap);
    memory.witness = {cached.pointI, cached.pointJ, m.turnedI, m.turnedJ};
    if (separatedToEnd(cached.gap) || (cached.gap > 0.0 && end < kNever &&
                                       std::min(cached.gap, prediction.planeGap(normal, end).gap) >
                                           0.125 * prediction.planeCurvature(normal) * end * end)) {
        ++stats.planeRejections;
        return none;
    }
    const Found found =
        prediction.advance(window->enter, normal, cached, resolved,
                           resolved ? resolvedContactSeenFrom(m) : std::nullopt, memory);
    if (normal != recorded) memory.witness = {}; // the record was of the plane left
    if (found.contact && found.time < kNever) {
        normal = found.normal;
        memory.witness = {};
        memory.gap = -kNever;
        memory.atContact = true;
    }
    return {found.time, found.contact};
}

// The engine re-predicts the pair right after contact() at the same state, from i (the same
// displacement) and from j (its exact negation: minimumImage is odd).
std::optional<SignedDistanceResult>
SuperballShape::resolvedContactSeenFrom(const PairMotion& m) const {
    const Vector3d& d = resolved_.displacement;
    if (m.diameter != resolved_.diameter) return std::nullopt;
    if (m.displacement == d) return resolved_.contact;
    if (m.displacement != -d) return std::nullopt;
    SignedDistanceResult r = resolved_.contact; // from j: the normal and both points mirrored
    r.normal = -r.normal;
    r.contactA = resolved_.contact.contactB - d;
    r.contactB = resolved_.contact.contactA - d;
    return r;
}

PairContact SuperballShape::contact(const PairMotion& m, PairMemory& memory) {
    Vector3d& normal = memory.normal;
    const SuperballPair pair{Superball(p_, 0.5 * m.diameter), m.orientationI.toRotationMatrix(),
                             m.orientationJ.toRotationMatrix(), m.displacement};
    // The prediction's normal was the optimal one at the root it found, a state within rounding
    // of this one: where its plane still touches (within the contact gap, either way), no
    // evaluation is needed (at p = 10 it was a local search per collision).
    SignedDistanceResult r;
    if (memory.atContact) r = atNormal(pair, normal);
    if (!memory.atContact || !(std::abs(r.signedDistance) <= 2.0 * limits.contactGap * m.diameter))
        r = exactSignedDistance(pair, normal, kNever, limits, stats).result;
    else
        ++stats.predictedContacts;
    if (normal != r.normal) memory.witness = {};
    normal = r.normal;
    memory.gap = -kNever; // a new normal: its gap bound is unknown
    memory.atContact = false;
    resolved_ = {m.displacement, m.diameter, r};
    const Vector3d armI = 0.5 * (r.contactA + r.contactB);
    return {r.normal, armI, armI - m.displacement, m.displacement.norm()};
}

} // namespace sbpack

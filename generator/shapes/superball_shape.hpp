#pragma once
// The superball as a shape of the event-driven engine (docs/design.md §2-3): collision prediction
// for two translating, rotating, growing superballs that never misses a contact.
//
// Motion over tau >= 0 in the pair's frame: d(tau) = d + w tau, q_k(tau) = exp(omega_k tau / 2) q_k
// (lab-frame omega), R(tau) = (D + gamma tau) / 2, c = circumradius / R. For a fixed unit n the
// separating-plane gap g_n(tau) = n.d(tau) - h_i(n) - h_j(n) is a lower bound on the signed
// distance s(tau) = max_n g_n(tau), and, the support point x_k of body k moving at omega_k x x_k
// plus growth (envelope theorem), with |x_k| <= c R and x_k . n = h_k >= c_in R,
//   g_n(tau) >= g_n(0) + tau [n.w - (|n x omega_i| + |n x omega_j|) R(tau) sqrt(c^2 - c_in^2)
//                             - c gamma].
// Also g_n'' <= M_n = sum_k |n x omega_k| (c gamma + c R |omega_k|) (support functions are
// convex), so g_n lies above its chord minus M_n (t - t0)(t1 - t) / 2: one plane gap at t1
// certifies [t0, t1] (the chord step), however fast the first-order bound says s could fall.
// Tiers, cheapest first: the circumscribed spheres do not meet before the horizon; the cached
// normal's plane separates up to it (first from the bound on its gap that the pair's last
// prediction left, moved on by its rate bound: no support point; then from its exact gap);
// conservative advancement on planes (first-order and chord steps on cheap plane gaps),
// refreshed by exact signed distances (warm Newton on the sphere, restarted from the best face
// normal for p > 1, the robust pair solver as fallback; far from contact an unconverged Newton's
// plane gap serves as a lower bound, and an overlap stands only with a witness point inside both
// bodies); near contact Newton steps in time until one touches or brackets the root, a
// safeguarded Newton refinement, and the root accepted as the first only when the root normal's
// plane certifies the interval before it. A prediction that reaches its step limit
// returns a safe time up to which nothing touches (Prediction::contact = false) instead of
// guessing.

#include "shapes/pair_motion.hpp"

#include <utility>

namespace sbpack {

/// Tolerances and limits of the superball predictor, in one place.
struct SuperballPredictorLimits {
    /// Touching for the engine: s <= contactGap * D (gaps of 1e-13 D stay resolvable).
    double contactGap = 1e-14;
    /// Below nearGap * D and closing, advancement also tries a Newton step in time.
    double nearGap = 1e-3;
    /// Advancement steps before the prediction settles for a safe recheck time.
    int maxAdvancementSteps = 100;
    /// Warm Newton steps of an exact signed distance before the robust pair solver takes over
    /// (32: at p = 1.5 one exact evaluation in 170 needs it, against one in 37 with 8).
    int newtonSteps = 32;
    /// Newton steps in time from one exact sample before advancement goes on along planes.
    int newtonStepsInTime = 8;
    /// Evaluations of the bracketed refinement before it settles for the bracket's safe end.
    int maxRefinementSteps = 100;
    /// Along a trajectory each exact evaluation starts from the last optimal normal carried at
    /// its rate dn/dtau, while that turns it by less than this (radians).
    double maxNormalCarry = 0.1;
    /// Near contact, an unconverged Newton's normal is polished by the cutting-plane search over
    /// the normals within this (radians, about) of it before the robust pair solver is called.
    double localSearchRadius = 1e-3;
    /// The polish stops when its normal is known to this (radians, about): f is stationary or
    /// has a kink |u|^q, q > 1, at its maximum, so its value is then exact to rounding.
    double localSearchResolution = 1e-16;
};

/// What the predictor did, summed over calls (reset by the caller).
struct SuperballPredictorStats {
    long calls = 0;
    long sphereRejections = 0;  ///< circumscribed spheres do not meet before the horizon
    long boundRejections = 0;   ///< the remembered bound on its gap shows it, unevaluated
    long planeRejections = 0;   ///< the cached normal's plane separates up to the horizon
    long evaluations = 0;       ///< exact signed distances (advancement, Newton, refinement)
    long localSearches = 0;     ///< of those, near contact: Newton's normal polished locally
    long robustEvaluations = 0; ///< of those, by the robust pair solver (no warm Newton)
    long newtonSteps = 0;       ///< warm Newton iterations on the normal, over all evaluations
    long lowerBounds = 0;       ///< of those, far from contact: unconverged Newton's bound
    long planeSteps = 0;        ///< advancement steps on a plane gap (two support functions)
    long chordSteps = 0;        ///< of those, steps certified by the plane's chord bound
    long newtonBrackets = 0;    ///< Newton steps in time that bracketed the contact
    long uncertifiedRoots = 0;  ///< of those, roots not certified first: advancement went on
    long refinementSteps = 0;   ///< evaluations in the bracketed refinement
    long distanceFallbacks = 0; ///< pair-solver cutting-plane finishes
    long rechecks = 0;          ///< step limit reached: a safe recheck time instead of a contact
    long limitHits = 0;         ///< refinement limit reached: the bracket's safe end returned
    long startOverlaps = 0;     ///< s(0) < -contactGap D (the pair just resolved, by rounding)

    /// Each counter with its provenance name (the names of earlier files kept).
    static constexpr std::pair<const char*, long SuperballPredictorStats::*> kCounters[] = {
        {"predictor_calls", &SuperballPredictorStats::calls},
        {"predictor_sphere_rejections", &SuperballPredictorStats::sphereRejections},
        {"predictor_bound_rejections", &SuperballPredictorStats::boundRejections},
        {"predictor_plane_rejections", &SuperballPredictorStats::planeRejections},
        {"predictor_evaluations", &SuperballPredictorStats::evaluations},
        {"predictor_local_searches", &SuperballPredictorStats::localSearches},
        {"predictor_robust_evaluations", &SuperballPredictorStats::robustEvaluations},
        {"predictor_newton_steps", &SuperballPredictorStats::newtonSteps},
        {"predictor_lower_bounds", &SuperballPredictorStats::lowerBounds},
        {"predictor_plane_steps", &SuperballPredictorStats::planeSteps},
        {"predictor_chord_steps", &SuperballPredictorStats::chordSteps},
        {"predictor_newton_brackets", &SuperballPredictorStats::newtonBrackets},
        {"predictor_uncertified_roots", &SuperballPredictorStats::uncertifiedRoots},
        {"predictor_refinement_steps", &SuperballPredictorStats::refinementSteps},
        {"predictor_fallbacks", &SuperballPredictorStats::distanceFallbacks},
        {"predictor_rechecks", &SuperballPredictorStats::rechecks},
        {"predictor_limit_hits", &SuperballPredictorStats::limitHits},
        {"predictor_start_overlaps", &SuperballPredictorStats::startOverlaps},
    };
    SuperballPredictorStats& operator+=(const SuperballPredictorStats& other) {
        for (const auto& [name, counter] : kCounters)
            this->*counter += other.*counter;
        return *this;
    }
};

class SuperballShape {
  public:
    /// Throws std::invalid_argument unless 0.5 <= p < inf.
    explicit SuperballShape(double p);

    static constexpr bool kRotates = true;

    double p() const { return p_; }
    /// Circumradius over semi-axis, c = max(1, 3^{1/2 - 1/(2p)}).
    double circumscribedRatio() const { return c_; }
    /// Inradius over semi-axis, min(1, 3^{1/2 - 1/(2p)}).
    double inscribedRatio() const { return cIn_; }
    /// I / m of a body of diameter D (isotropic inertia, docs/design.md §1).
    double inertiaPerMass(double diameter) const;

    /// Earliest delay in [0, horizon] at which the pair touches, or +inf if none; a safe recheck
    /// delay when the step limit is reached. `memory` (in/out): the pair's cached unit normal
    /// from i to j (zero when unknown), updated when the pair is evaluated exactly, and the bound
    /// on its plane gap now (its own or the last one's, moved on), left for the next prediction.
    /// `resolved`: the engine has just applied this pair's impulse at this very state, which left
    /// the surfaces separating at the resolver's contact point, so touching now is no contact (on
    /// near-flat faces a re-evaluation can pick another point of the face and see it closing:
    /// zero impulses would repeat at one instant, and no time would pass).
    Prediction collisionTime(const PairMotion& m, double horizon, PairMemory& memory,
                             bool resolved = false) const;

    /// Contact of touching bodies now: normal from i to j, arms to the midpoint of the two
    /// support points (the same point for both, so impulses conserve angular momentum).
    PairContact contact(const PairMotion& m, Vector3d& normal) const;

    SuperballPredictorLimits limits{};
    /// Counters; mutable because prediction is logically const.
    mutable SuperballPredictorStats stats{};

  private:
    double p_;
    double c_;
    double cIn_;
    double lever_; ///< sqrt(c^2 - c_in^2): bound on a support point's offset from its normal
    double inertiaPerMassUnit_; ///< I / m at semi-axis 1
};

} // namespace sbpack

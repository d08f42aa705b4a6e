#pragma once
// The superball as a shape of the event-driven engine (DESIGN.md §2-3): collision prediction for
// two translating, rotating, growing superballs by conservative advancement on the signed
// distance s(t), then a bracketed (Illinois) refinement of its first root.
//
// Motion over tau >= 0, in the pair's frame: d(tau) = d + w tau, q_k(tau) = exp(omega_k tau / 2)
// q_k (lab-frame omega), semi-axis R(tau) = (D + gamma tau) / 2. With c = circumradius / R,
//   |ds/dtau| <= |w| + (|omega_i| + |omega_j|) c R(tau) + |gamma| c        (envelope theorem),
// so a step h with s(tau) >= int_tau^{tau+h} bound never jumps over a contact.

#include "shapes/pair_motion.hpp"

namespace sbpack {

/// Tolerances and limits of the superball predictor, in one place.
struct SuperballPredictorLimits {
    /// Predict only up to this time; later contacts report +inf (the engine re-predicts).
    double horizon = 1e3;
    /// Conservative advancement stops once s < contactGap * D (touching for the engine).
    double contactGap = 1e-13;
    /// Below nearGap * D advancement also tries Newton steps, accepted only when they bracket.
    double nearGap = 1e-4;
    /// Advancement steps before the stalled-advancement fallback (a forward scan).
    int maxAdvancementSteps = 4000;
    /// Steps of the fallback scan and of the bracketed refinement.
    int maxScanSteps = 4000;
    int maxRefinementSteps = 200;
    /// The refinement stops when the bracket is shorter than this times (1 + tau).
    double timeTolerance = 1e-14;
};

/// What the predictor did, summed over calls (reset by the caller).
struct SuperballPredictorStats {
    long calls = 0;
    long sphereRejections = 0;  ///< bounding spheres never touch before the horizon
    long advancementSteps = 0;  ///< signed-distance evaluations in conservative advancement
    long newtonBrackets = 0;    ///< near-contact Newton steps that bracketed the root
    long refinementSteps = 0;   ///< evaluations in the bracketed refinement
    long distanceFallbacks = 0; ///< pair-solver derivative-free finishes
    long scanFallbacks = 0;     ///< advancement stalled (grazing) and a forward scan took over
    long limitHits = 0;         ///< an iteration cap ended a prediction (reported, not looped)
};

struct SuperballShape {
    double p;
    SuperballPredictorLimits limits{};
    /// Counters; mutable because prediction is logically const.
    mutable SuperballPredictorStats stats{};

    static constexpr bool kRotates = true;

    /// Earliest tau in [0, horizon] at which the bodies touch (s <= contactGap D), +inf if none.
    /// Already overlapping: 0.
    double collisionTime(const PairMotion& m) const;

    /// Contact of (nearly) touching bodies at the current time: normal from i to j, arms to the
    /// midpoint of the two support points.
    PairContact contact(const PairMotion& m) const;

    /// Signed distance of the pair advanced by tau along its motion (no collision handling).
    double signedDistanceAt(const PairMotion& m, double tau) const;
};

} // namespace sbpack

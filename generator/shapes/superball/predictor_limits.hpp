#pragma once
// The superball predictor's tolerances and limits (generator/shapes/superball_shape.hpp and its
// layers in this folder), in one place.

#include <limits>

namespace sbpack {

/// Tolerances and limits of the superball predictor, in one place.
struct SuperballPredictorLimits {
    /// Touching for the engine: s <= contactGap * D (gaps of 1e-13 D stay resolvable).
    double contactGap = 1e-14;
    /// Below nearGap * D and closing, advancement also tries Newton steps in time, from an exact
    /// sample only (a lower bound's plane has no exact rate; lower bounds are taken wherever
    /// they prove the pair apart, down to contactGap).
    double nearGap = 1e-3;
    /// Advancement steps before the prediction settles for a safe recheck time.
    int maxAdvancementSteps = 100;
    /// Warm Newton steps of an exact signed distance before its plane serves as a lower bound or
    /// the local search and the robust pair solver take over (at p = 1.5 the robust solver
    /// served one exact evaluation in 170 with 32, one in 37 with 8; since lower bounds serve
    /// down to the contact gap, 16 costs p = 1.5 nothing and spares near-cubes the steps of a
    /// Newton that will not converge: 1.2-1.26x per collision at p = 10, 1.05x at p = 5;
    /// bench/RESULTS.md, "Near-cubes: lower bounds down to the contact gap").
    int newtonSteps = 16;
    /// Where a lower bound on s will do (it must clear the contact gap), warm Newton stops, from
    /// its second iterate on, once its plane gap clears that need by 1 / this times the ascent
    /// its next step predicts: the plane serves, and at p = 10 the steps it spares were also the
    /// exact samples from which Newton steps in time bracketed kinked roots (1.37-1.49x per
    /// collision at p = 10, 1.05x at p = 5, none at p = 1.5; from the first iterate on p = 1.5
    /// lost 9 %: bench/RESULTS.md, "Warm Newton stops where its plane will do").
    double boundAscentRatio = 0.25;
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
    /// The bracketed refinement bisects every this many steps when regula falsi stalls.
    int bisectEvery = 4;
    /// A refinement step closer than this fraction of the bracket to its ends counts as stalled.
    double stallFraction = 1e-3;
    /// The bracket is resolved when narrower than this many ulps (relative to 1 + tau).
    double bracketWidth = 4e-16;
    /// The chord step tried first is at most this fraction of the chord's reach sqrt(8 g / M).
    double chordReach = 0.9;
    /// Each further chord try is this fraction of the last.
    double chordShrink = 0.125;
};

namespace superball {
/// "No contact": a time beyond every horizon.
inline constexpr double kNever = std::numeric_limits<double>::infinity();
} // namespace superball

} // namespace sbpack

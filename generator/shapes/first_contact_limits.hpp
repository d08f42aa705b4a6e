#pragma once
// The tolerances and limits of the shape-independent first-contact search
// (shapes/first_contact_search.hpp), the part of a predictor's one limits struct
// (shapes/superball/predictor_limits.hpp) that the search reads.

#include <limits>

namespace sbpack {

/// "No contact": a time beyond every horizon.
inline constexpr double kNoContact = std::numeric_limits<double>::infinity();

/// Tolerances and limits of the first-contact search over a gap function.
struct FirstContactLimits {
    /// Touching for the engine: s <= contactGap * D (gaps of 1e-13 D stay resolvable).
    double contactGap = 1e-14;
    /// Below nearGap * D and closing, advancement also tries Newton steps in time, from an exact
    /// sample only (a lower bound's plane has no exact rate; lower bounds are taken wherever
    /// they prove the pair apart, down to contactGap).
    double nearGap = 1e-3;
    /// Advancement steps before the prediction settles for a safe recheck time.
    int maxAdvancementSteps = 100;
    /// Newton steps in time from one exact sample before advancement goes on along planes.
    int newtonStepsInTime = 8;
    /// Evaluations of the bracketed refinement before it settles for the bracket's safe end.
    int maxRefinementSteps = 100;
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

} // namespace sbpack

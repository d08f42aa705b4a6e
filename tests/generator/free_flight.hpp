#pragma once
// The pair of two bodies after free flight, as the engine would hand it to a shape then (the
// predictor and witness tests share it).

#include "shapes/pair_motion.hpp"

namespace sbpack {

/// The pair after tau of free flight: displacement, orientations, diameter and accumulated
/// rotation angles moved on (what the engine hands the predictor at a recheck).
inline PairMotion advancedPair(const PairMotion& m, double tau) {
    PairMotion a = m;
    a.displacement += m.relativeVelocity * tau;
    a.orientationI = advancedOrientation(m.orientationI, m.angularVelocityI, tau);
    a.orientationJ = advancedOrientation(m.orientationJ, m.angularVelocityJ, tau);
    a.diameter += m.growthRate * tau;
    a.turnedI += m.angularVelocityI.norm() * tau;
    a.turnedJ += m.angularVelocityJ.norm() * tau;
    return a;
}

} // namespace sbpack

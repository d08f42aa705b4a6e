#pragma once
// The superball predictor's exact layer (docs/design.md §2-3): the signed distance s of a pair,
// warm-started from a normal, by Newton on the unit sphere (restarted from the best face normal
// for p > 1, polished by a local cutting-plane search near contact, the robust pair solver of
// common/pair as the fallback); far from contact an unconverged Newton's plane gap serves as a
// lower bound, and an overlap stands only with a witness point inside both bodies.

#include "pair/pair_geometry.hpp"
#include "shapes/predictor_stats.hpp"
#include "shapes/superball/predictor_limits.hpp"

namespace sbpack::superball {

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

/// s of the pair from its cached normal (updated), or from the centre line when there is none
/// (f has one maximum for s >= 0): Newton, else the robust solver. Where a lower bound on s will
/// do, one above `boundSuffices` (unconverged Newton's last plane gap) is returned as it is.
/// With `rates`, Newton's converged answers also carry the normal's rate (else it is zero).
WarmNewton exactSignedDistance(const SuperballPair& pair, Vector3d& normal, double boundSuffices,
                               const SuperballPredictorLimits& limits, PredictorStats& stats,
                               const PairRates* rates = nullptr);

/// The plane of unit n as the pair's answer: its gap n.d - h_i(n) - h_j(n) and the two support
/// points (relative to r_i).
SignedDistanceResult atNormal(const SuperballPair& pair, const Vector3d& n);

} // namespace sbpack::superball

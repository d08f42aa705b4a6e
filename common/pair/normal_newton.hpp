#pragma once
// The one Newton ascent of the signed distance's plane gap on the unit sphere (docs/design.md
// §2): f(n) = n.d - h_A(n) - h_B(n), s = max_n f(n), warm-started from any unit normal. Used by
// the robust pair solver (pair_geometry.cpp, from the scale factor's normal, with its
// certificates and cutting-plane finish) and by sbgen's exact layer (generator/shapes/superball/
// warm_distance.cpp, from the pair's remembered normal, where a lower bound may serve).

#include "pair/pair_geometry.hpp"

#include <limits>

namespace sbpack {

/// How the evaluated pair moves at that instant: d' = velocity, each body turns at its omega and
/// grows at R'/R = strain.
struct PairRates {
    Vector3d velocity;
    Vector3d angularVelocityA, angularVelocityB;
    double strain;
};

/// How a Newton step on the normal advances: backtracking from the step (cheap; unconverged
/// where the tangent Hessian is not positive definite or an eighth of the step does not ascend),
/// or the exact line search along it, the Hessian shifted to positive definite (robust from any
/// start, far from contact and in overlaps where f is not concave).
enum class NewtonStep { backtracking, lineSearch };

struct NormalNewtonOptions {
    /// Steps (maxNewtonIterations), the line search's, and the mismatch certificate's tolerance.
    PairTolerances tolerances{};
    NewtonStep step = NewtonStep::lineSearch;
    /// Where a lower bound on s above this will do: from the second iterate on, the ascent stops
    /// once its plane gap clears it by 1 / boundAscentRatio times the ascent its next step
    /// predicts (the plane is then the answer, unconverged).
    double enough = std::numeric_limits<double>::infinity();
    double boundAscentRatio = 0.25;
    /// With rates, a converged answer also carries dn/dtau of the optimal normal.
    const PairRates* rates = nullptr;
};

/// The ascent's answer: s when converged, else its last iterate, whose f(n) is still a lower
/// bound on s (every plane's gap is). `normalRate`: dn/dtau when converged and rates were given,
/// else zero.
struct NormalNewton {
    SignedDistanceResult result;
    bool converged = false;
    Vector3d normalRate = Vector3d::Zero();
};

/// Newton steps on the tangent plane of the current normal (the step rule of `options`), f being
/// concave about its maximum near contact; the tangent Hessian of -f is P^T (d2h_A + d2h_B) P +
/// f I. Converged when the tangent gradient vanishes and the predicted ascent is at rounding
/// level (or, for p > 1.5, the supporting planes have a common perpendicular); unconverged when
/// the step rule cannot ascend, where a lower bound will do (`enough`), or after the step limit.
NormalNewton normalNewton(const SuperballPair& pair, const Vector3d& n,
                          const NormalNewtonOptions& options = {});

} // namespace sbpack

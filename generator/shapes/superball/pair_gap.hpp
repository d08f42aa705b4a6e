#pragma once
// The superball pair's gap function (shapes/first_contact_search.hpp's GapFunction): the pair
// along its present motion over the circumscribed spheres' window, its plane gaps with their
// bounds, and its signed distance evaluated exactly (warm_distance.hpp) at any delay tau, each
// evaluation warm-started from the last normal carried at its rate.

#include "shapes/first_contact_search.hpp"
#include "shapes/pair_motion.hpp"
#include "shapes/predictor_stats.hpp"
#include "shapes/superball/predictor_limits.hpp"
#include "shapes/superball/warm_distance.hpp"

#include <algorithm>
#include <optional>

namespace sbpack::superball {

/// The circumscribed spheres' window (tier 1 of the predictor): `enter`, when they first
/// overlap (0 if now), and `end`, when they part for good (or the horizon); none if they do not
/// meet before the horizon.
struct SphereWindow {
    double enter = 0.0;
    double end = kNoContact;
};
std::optional<SphereWindow> circumscribedWindow(const PairMotion& m, double c, double horizon);

/// The superball pair along its motion up to `end`: plane gaps and their bounds, and s
/// evaluated exactly, each evaluation warm-started from the last normal (the pair's cached one
/// at first, which it moves on).
class SuperballPairGap {
  public:
    /// c: circumradius over semi-axis; lever: sqrt(c^2 - c_in^2).
    SuperballPairGap(const PairMotion& m, double p, double c, double lever, double end,
                     Vector3d& normal, const SuperballPredictorLimits& limits,
                     PredictorStats& stats)
        : m_(m), p_(p), c_(c), growth_(std::max(m.growthRate, 0.0)),
          leverBound_(lever * 0.5 * (m.diameter + growth_ * end)),
          radiusBound_(c * 0.5 * (m.diameter + growth_ * end)), normal_(normal), limits_(limits),
          stats_(stats) {}

    // The plane bound's rate at unit normal n, valid up to `end` (R at its largest there):
    // dh_k/dtau = (n x omega_k) . x_k with x_k the support point, and only its part normal to n
    // counts, |x_perp|^2 = |x|^2 - h^2 <= (c^2 - c_in^2) R_k^2 (the lever; 0 for spheres), R_k
    // = size_k R of a mixture's body.
    double planeRate(const Vector3d& n) const {
        return n.dot(m_.relativeVelocity) -
               (m_.sizeI * n.cross(m_.angularVelocityI).norm() +
                m_.sizeJ * n.cross(m_.angularVelocityJ).norm()) *
                   leverBound_ -
               c_ * growth_;
    }

    // Second-order bound of the same plane: along the rotation the body-frame direction of n
    // runs on a circle, |u'| = |n x omega|, |u''| = |n x omega| |omega|, and a support function
    // there has h'' = u'^T (d2h) u' + x . u'' >= -c R |n x omega| |omega| (h is convex); growth
    // adds (R h_hat)'' = gamma h_hat' + R h_hat''. So g_n'' <= M_n = sum_k |n x omega_k|
    // (c gamma + c R |omega_k|), each body's gamma and R times its size.
    double planeCurvature(const Vector3d& n) const {
        return m_.sizeI * n.cross(m_.angularVelocityI).norm() *
                   (c_ * growth_ + radiusBound_ * m_.angularVelocityI.norm()) +
               m_.sizeJ * n.cross(m_.angularVelocityJ).norm() *
                   (c_ * growth_ + radiusBound_ * m_.angularVelocityJ.norm());
    }

    /// The plane gap g_n(tau) itself and its exact rate: two support points.
    PlaneGap planeGap(const Vector3d& n, double tau) const;

    /// s after tau, exact or (above the contact gap) a lower bound that proves the pair apart.
    Sample at(double tau);

    /// The sample at tau = 0 of an exact evaluation made elsewhere at this state (the contact
    /// the engine has just resolved), warm start of the next.
    Sample given(const SignedDistanceResult& r) {
        normal_ = r.normal;
        lastTau_ = 0.0;
        normalRate_ = Vector3d::Zero();
        return sample(0.0, r, true);
    }

  private:
    Sample sample(double tau, const SignedDistanceResult& r, bool exact) const;

    const PairMotion& m_;
    double p_, c_, growth_;
    double leverBound_, radiusBound_;
    Vector3d& normal_;
    const SuperballPredictorLimits& limits_;
    PredictorStats& stats_;
    double lastTau_ = 0.0;
    Vector3d normalRate_ = Vector3d::Zero(); ///< of normal_ at lastTau_ (zero: unknown)
};
static_assert(GapFunction<SuperballPairGap>);

} // namespace sbpack::superball

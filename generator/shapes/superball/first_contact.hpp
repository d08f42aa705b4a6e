#pragma once
// The superball predictor's certified first-contact search (tiers 1-3 of
// generator/shapes/superball_shape.hpp): the circumscribed spheres' window, the plane bounds of a
// normal, conservative advancement along planes, Newton steps in time near contact, the
// safeguarded refinement of a bracket and the certificate of a root.

#include "geometry/superball.hpp"
#include "shapes/pair_motion.hpp"
#include "shapes/predictor_stats.hpp"
#include "shapes/superball/pair_trajectory.hpp"
#include "shapes/superball/predictor_limits.hpp"

#include <algorithm>
#include <optional>
#include <variant>

namespace sbpack::superball {

/// A separating plane's gap g_n(tau) = n.d(tau) - h_i(n) - h_j(n), its exact rate, and the two
/// support points of n in the bodies' frames (at the bodies' semi-axis then: a witness record's
/// points once scaled to semi-axis 1).
struct PlaneGap {
    double gap = 0.0;
    double rate = 0.0;
    Vector3d pointI = Vector3d::Zero(), pointJ = Vector3d::Zero();
};

/// The circumscribed spheres' window (tier 1 of the predictor): `enter`, when they first
/// overlap (0 if now), and `end`, when they part for good (or the horizon); none if they do not
/// meet before the horizon.
struct SphereWindow {
    double enter = 0.0;
    double end = kNever;
};
std::optional<SphereWindow> circumscribedWindow(const PairMotion& m, double c, double horizon);

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
                planeGapRate(m_, diameter, n, xI, xJ), bodyI, bodyJ};
    }

    /// Tier 3 from `start` (the cached plane's gap `cached` at tau = 0 known): advancement along
    /// the cached plane, then from exact samples along their planes, Newton steps in time near
    /// contact, and the certificate of the root they reach. `resolved`: the pair was resolved at
    /// this very state, whose contact seen from i is `contact` where known (the sample at
    /// tau = 0 without an evaluation).
    Found advance(double start, const Vector3d& normal, PlaneGap cached, bool resolved,
                  const std::optional<SignedDistanceResult>& contact, PairMemory& memory);

  private:
    Found fromSample(Sample now, bool resolved);
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

} // namespace sbpack::superball

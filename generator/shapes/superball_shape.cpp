#include "shapes/superball_shape.hpp"

#include "geometry/superball.hpp"
#include "pair/pair_geometry.hpp"
#include "shapes/sphere.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sbpack {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

/// s, its exact rate ds/dtau and the normal of the pair after tau.
struct Sample {
    double tau = 0.0;
    double gap = 0.0;
    double rate = 0.0;
    Vector3d normal = Vector3d::Zero();
};

/// The pair along its motion, evaluated exactly, each evaluation warm-started from the last
/// normal (the pair's cached one at first).
class PairTrajectory {
  public:
    PairTrajectory(const PairMotion& m, double p, Vector3d& normal, SuperballPredictorStats& stats)
        : m_(m), p_(p), normal_(normal), stats_(stats) {}

    Sample at(double tau) {
        ++stats_.evaluations;
        const double diameter = m_.diameter + m_.growthRate * tau;
        const Vector3d d = m_.displacement + m_.relativeVelocity * tau;
        const SuperballPair pair{
            Superball(p_, 0.5 * diameter),
            advancedOrientation(m_.orientationI, m_.angularVelocityI, tau).toRotationMatrix(),
            advancedOrientation(m_.orientationJ, m_.angularVelocityJ, tau).toRotationMatrix(), d};
        const SignedDistanceResult r = signedDistanceFrom(pair, normal_);
        stats_.distanceFallbacks += r.fallbacks;
        normal_ = r.normal;
        // ds/dtau by the envelope theorem: the closing speed along n of the two support points,
        // each moving at omega x x + (gamma / D) x about its own centre.
        const Vector3d xI = r.contactA, xJ = r.contactB - d;
        const double strain = m_.growthRate / diameter;
        const Vector3d vI = m_.angularVelocityI.cross(xI) + strain * xI;
        const Vector3d vJ = m_.angularVelocityJ.cross(xJ) + strain * xJ;
        return {tau, r.signedDistance, r.normal.dot(m_.relativeVelocity + vJ - vI), r.normal};
    }

  private:
    const PairMotion& m_;
    double p_;
    Vector3d& normal_;
    SuperballPredictorStats& stats_;
};

} // namespace

SuperballShape::SuperballShape(double p)
    : p_(p), c_(Superball(p, 1.0).circumradius()),
      inertiaPerMassUnit_(Superball(p, 1.0).inertiaPerMass()) {}

double SuperballShape::inertiaPerMass(double diameter) const {
    return inertiaPerMassUnit_ * 0.25 * diameter * diameter;
}

double SuperballShape::signedDistanceAt(const PairMotion& m, double tau) const {
    Vector3d cold = Vector3d::Zero();
    SuperballPredictorStats scratch;
    const double diameter = m.diameter + m.growthRate * tau;
    const SuperballPair pair{
        Superball(p_, 0.5 * diameter),
        advancedOrientation(m.orientationI, m.angularVelocityI, tau).toRotationMatrix(),
        advancedOrientation(m.orientationJ, m.angularVelocityJ, tau).toRotationMatrix(),
        m.displacement + m.relativeVelocity * tau};
    return signedDistance(pair, cold).signedDistance;
}

Prediction SuperballShape::collisionTime(const PairMotion& m, double horizon,
                                         Vector3d& normal) const {
    ++stats.calls;
    const Prediction none{kNever};
    const double D = m.diameter, gamma = m.growthRate, growth = std::max(gamma, 0.0);
    if (!(horizon > 0.0)) return none;

    // Tier 1: the circumscribed spheres (diameter c D, growing at c gamma) meet before horizon.
    const PairMotion spheres{m.displacement, m.relativeVelocity, {}, {}, {}, {}, c_ * D, c_ * gamma};
    const double enter = m.displacement.squaredNorm() <= c_ * c_ * D * D
                             ? 0.0
                             : SphereShape{}.collisionTime(spheres);
    if (enter >= horizon) {
        ++stats.sphereRejections;
        return none;
    }
    double end = horizon;
    const double a = m.relativeVelocity.squaredNorm() - c_ * c_ * gamma * gamma;
    if (a > 0.0) { // after the spheres part for good, nothing touches
        const double b = m.displacement.dot(m.relativeVelocity) - c_ * c_ * D * gamma;
        const double c0 = m.displacement.squaredNorm() - c_ * c_ * D * D;
        end = std::min(end, (-b + std::sqrt(std::max(0.0, b * b - a * c0))) / a);
    }

    // The plane bound's rate at unit normal n, valid up to `end` (R at its largest there).
    const double radiusBound = c_ * 0.5 * (D + growth * end);
    auto planeRate = [&](const Vector3d& n) {
        return n.dot(m.relativeVelocity) -
               (n.cross(m.angularVelocityI).norm() + n.cross(m.angularVelocityJ).norm()) *
                   radiusBound -
               c_ * growth;
    };

    // Tier 2: the cached normal's separating plane holds up to `end`.
    if (!normal.isZero(0.0)) {
        const Superball body(p_, 0.5 * D);
        const double gap =
            normal.dot(m.displacement) -
            body.support(m.orientationI.toRotationMatrix().transpose() * normal) -
            body.support(m.orientationJ.toRotationMatrix().transpose() * normal);
        if (gap > 0.0 && gap + std::min(0.0, planeRate(normal)) * end > 0.0) {
            ++stats.planeRejections;
            return none;
        }
    }

    // Tier 3: conservative advancement on exact s.
    PairTrajectory trajectory(m, p_, normal, stats);
    const double touching = limits.contactGap * D, near = limits.nearGap * D;

    // Illinois on s over a bracket gap(left) > 0 >= gap(right); returns the safe (left) end once
    // it touches, so an overlap is never accepted.
    auto refine = [&](Sample left, Sample right) {
        int side = 0;
        double gl = left.gap, gr = right.gap;
        for (int k = 0; k < limits.maxRefinementSteps; ++k) {
            const double width = right.tau - left.tau;
            if (left.gap <= touching || width <= 4e-16 * (1.0 + right.tau))
                return Prediction{left.tau};
            double tau = (left.tau * gr - right.tau * gl) / (gr - gl);
            if (!(tau > left.tau + 1e-3 * width && tau < right.tau - 1e-3 * width))
                tau = 0.5 * (left.tau + right.tau);
            const Sample mid = trajectory.at(tau);
            ++stats.refinementSteps;
            if (mid.gap > 0.0) {
                left = mid, gl = mid.gap;
                if (side == -1) gr *= 0.5;
                side = -1;
            } else {
                right = mid, gr = mid.gap;
                if (side == 1) gl *= 0.5;
                side = 1;
            }
        }
        ++stats.limitHits;
        return Prediction{left.tau};
    };

    Sample now = trajectory.at(enter);
    if (enter == 0.0 && now.gap < -touching) ++stats.startOverlaps;
    for (int step = 0;; ++step) {
        if (now.gap <= touching && now.rate < 0.0) return {now.tau};
        const double rate = planeRate(now.normal);
        if (rate >= 0.0) return none; // this plane separates them up to `end`
        // Near contact and closing: a Newton step in time, kept only if it brackets the root.
        const double safe = now.tau + std::max(now.gap, touching) / -rate;
        if (now.gap <= near && now.rate < 0.0) {
            const double tau = now.tau - now.gap / now.rate;
            if (tau > safe && tau <= end) {
                const Sample trial = trajectory.at(tau);
                if (trial.gap <= 0.0) {
                    ++stats.newtonBrackets;
                    return refine(now, trial);
                }
            }
        }
        if (safe >= end) return none;
        if (step == limits.maxAdvancementSteps) {
            ++stats.rechecks;
            return {safe, false};
        }
        const Sample previous = now;
        now = trajectory.at(safe);
        if (now.gap <= 0.0 && previous.gap > touching) return refine(previous, now);
    }
}

PairContact SuperballShape::contact(const PairMotion& m, Vector3d& normal) const {
    const SuperballPair pair{Superball(p_, 0.5 * m.diameter), m.orientationI.toRotationMatrix(),
                             m.orientationJ.toRotationMatrix(), m.displacement};
    const SignedDistanceResult r = signedDistanceFrom(pair, normal);
    stats.distanceFallbacks += r.fallbacks;
    normal = r.normal;
    const Vector3d armI = 0.5 * (r.contactA + r.contactB);
    return {r.normal, armI, armI - m.displacement, m.displacement.norm()};
}

} // namespace sbpack

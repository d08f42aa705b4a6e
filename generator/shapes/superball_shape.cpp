#include "shapes/superball_shape.hpp"

#include "pair/pair_geometry.hpp"
#include "shapes/sphere.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sbpack {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

/// Orientation after tau of a body spinning at lab-frame omega: exp(omega tau / 2) q0.
Quaterniond advanced(const Quaterniond& q0, const Vector3d& omega, double tau) {
    const double angle = omega.norm() * tau;
    if (angle == 0.0) return q0;
    return Quaterniond(Eigen::AngleAxisd(angle, omega.normalized())) * q0;
}

/// The pair's state after tau: s, its rate ds/dtau (closing speed of the two support points
/// along the normal) and the normal, reused as the next warm start.
struct Sample {
    double tau = 0.0;
    double gap = 0.0;
    double rate = 0.0;
};

class PairTrajectory {
public:
    PairTrajectory(const PairMotion& m, double p, SuperballPredictorStats& stats)
        : m_(m), p_(p), stats_(stats) {}

    Sample at(double tau) {
        const double diameter = m_.diameter + m_.growthRate * tau;
        const Vector3d d = m_.displacement + m_.relativeVelocity * tau;
        const SuperballPair pair{
            Superball(p_, 0.5 * diameter),
            advanced(m_.orientationI, m_.angularVelocityI, tau).toRotationMatrix(),
            advanced(m_.orientationJ, m_.angularVelocityJ, tau).toRotationMatrix(), d};
        const SignedDistanceResult r = signedDistance(pair, warmNormal_);
        stats_.distanceFallbacks += r.fallbacks;
        warmNormal_ = r.normal;
        // Material velocity of a support point x about its own centre: omega x x + (gamma/D) x.
        const Vector3d xI = r.contactA, xJ = r.contactB - d;
        const double strain = m_.growthRate / diameter;
        const Vector3d vI = m_.angularVelocityI.cross(xI) + strain * xI;
        const Vector3d vJ = m_.angularVelocityJ.cross(xJ) + strain * xJ;
        return {tau, r.signedDistance, r.normal.dot(m_.relativeVelocity + vJ - vI)};
    }

private:
    const PairMotion& m_;
    double p_;
    SuperballPredictorStats& stats_;
    Vector3d warmNormal_ = Vector3d::Zero();
};

} // namespace

double SuperballShape::signedDistanceAt(const PairMotion& m, double tau) const {
    PairTrajectory trajectory(m, p, stats);
    return trajectory.at(tau).gap;
}

double SuperballShape::collisionTime(const PairMotion& m) const {
    ++stats.calls;
    const double D = m.diameter, gamma = m.growthRate;
    const double c = Superball(p, 1.0).circumradius(); // circumradius per semi-axis
    const double spin = m.angularVelocityI.norm() + m.angularVelocityJ.norm();
    const double speed = m.relativeVelocity.norm();

    double end = limits.horizon;
    if (gamma < 0.0) end = std::min(end, 0.5 * D / -gamma); // keep the bodies half their size

    // Cheap rejection: the circumscribed spheres (diameter c D, growing at c gamma) must meet.
    const PairMotion spheres{m.displacement, m.relativeVelocity, {}, {}, {}, {}, c * D, c * gamma};
    const double a = speed * speed - c * c * gamma * gamma;
    const double b = m.displacement.dot(m.relativeVelocity) - c * c * D * gamma;
    const double c0 = m.displacement.squaredNorm() - c * c * D * D;
    const double enter = c0 <= 0.0 ? 0.0 : SphereShape{}.collisionTime(spheres);
    if (enter > end) {
        ++stats.sphereRejections;
        return kNever;
    }
    // After the spheres separate for good (a > 0: receding faster than growing), no contact.
    if (a > 0.0) {
        const double disc = std::max(0.0, b * b - a * c0);
        end = std::min(end, (-b + std::sqrt(disc)) / a);
    }

    PairTrajectory trajectory(m, p, stats);
    const double touching = limits.contactGap * D, near = limits.nearGap * D;

    // Safeguarded first root in [left, right] with gap(left) > 0 >= gap(right): Illinois.
    auto refine = [&](Sample left, Sample right) {
        int side = 0;
        double gl = left.gap, gr = right.gap;
        for (int k = 0; k < limits.maxRefinementSteps; ++k) {
            if (right.tau - left.tau <= limits.timeTolerance * (1.0 + right.tau)) return left.tau;
            double tau = (left.tau * gr - right.tau * gl) / (gr - gl);
            const double width = right.tau - left.tau;
            if (!(tau > left.tau + 1e-3 * width && tau < right.tau - 1e-3 * width))
                tau = 0.5 * (left.tau + right.tau);
            const Sample mid = trajectory.at(tau);
            ++stats.refinementSteps;
            if (mid.gap > 0.0) {
                if (mid.gap <= touching && mid.rate < 0.0 && width < 1e-9 * (1.0 + tau))
                    return mid.tau;
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
        return left.tau;
    };

    Sample now = trajectory.at(enter);
    ++stats.advancementSteps;
    if (now.gap <= 0.0 && enter == 0.0) return now.rate < 0.0 || now.gap < -touching ? 0.0 : kNever;
    Sample previous = now;

    for (int step = 0; step < limits.maxAdvancementSteps; ++step) {
        if (now.gap <= 0.0) return refine(previous, now); // rounding overshoot of advancement
        if (now.gap <= touching && now.rate < 0.0) return now.tau;
        // Near contact and closing: a Newton step, kept only if it brackets the root.
        if (now.gap <= near && now.rate < 0.0) {
            const double tau = now.tau - now.gap / now.rate;
            if (tau <= end) {
                const Sample trial = trajectory.at(tau);
                ++stats.advancementSteps;
                if (trial.gap <= 0.0) {
                    ++stats.newtonBrackets;
                    return refine(now, trial);
                }
            }
        }
        // Conservative step: s(tau + h) >= s - L h - spin c gamma h^2 / 4 with L the rate bound
        // now (R grows by gamma h / 2).
        const double R = 0.5 * (D + gamma * now.tau);
        const double bound = speed + spin * c * R + std::abs(gamma) * c;
        const double curvature = gamma > 0.0 ? 0.25 * spin * c * gamma : 0.0;
        const double gap = std::max(now.gap, touching);
        const double h = 2.0 * gap / (bound + std::sqrt(bound * bound + 4.0 * curvature * gap));
        if (!(h > 0.0) || now.tau + h > end) return kNever;
        previous = now;
        now = trajectory.at(now.tau + h);
        ++stats.advancementSteps;
    }

    // Advancement stalled (a grazing pass with a gap of a few touching): scan forward in steps
    // of the remaining time; not rigorous, so counted.
    ++stats.scanFallbacks;
    const double scanStep = (end - now.tau) / limits.maxScanSteps;
    for (int k = 0; k < limits.maxScanSteps && scanStep > 0.0; ++k) {
        previous = now;
        now = trajectory.at(now.tau + scanStep);
        ++stats.advancementSteps;
        if (now.gap <= 0.0) return refine(previous, now);
    }
    ++stats.limitHits;
    return kNever;
}

PairContact SuperballShape::contact(const PairMotion& m) const {
    const SuperballPair pair{Superball(p, 0.5 * m.diameter), m.orientationI.toRotationMatrix(),
                             m.orientationJ.toRotationMatrix(), m.displacement};
    const SignedDistanceResult r = signedDistance(pair);
    stats.distanceFallbacks += r.fallbacks;
    const Vector3d armI = 0.5 * (r.contactA + r.contactB);
    return {r.normal, armI, armI - m.displacement, m.displacement.norm()};
}

} // namespace sbpack

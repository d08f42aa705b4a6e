#pragma once
// The sphere as a shape of the event-driven engine (shapes/shape.hpp): an exact quadratic
// predictor and the contact of two spheres, in the pair's local frame (docs/design.md §2-3).
// Spheres do not rotate and their predictor remembers nothing of a pair.

#include "shapes/collision_resolver.hpp"
#include "shapes/pair_motion.hpp"
#include "shapes/predictor_stats.hpp"

#include <cmath>
#include <limits>

namespace sbpack {

struct SphereShape {
    using Memory = NoPairMemory;
    /// Spheres keep their orientation (the random start draws none).
    static constexpr bool kRotates = false;

    /// Circumradius over semi-axis: sizes the neighbour lists.
    double circumscribedRatio() const { return 1.0; }
    /// I / m = 2 R^2 / 5 of a solid sphere of diameter D (unused: spheres do not spin).
    double inertiaPerMass(double diameter) const { return 0.1 * diameter * diameter; }

    /// Spheres keep their orientation.
    Quaterniond turned(const Quaterniond& q, const Vector3d& /*omega*/, double /*tau*/) const {
        return q;
    }
    void orient(PairMotion& /*m*/, const ParticleState& /*i*/, double /*tauI*/,
                const ParticleState& /*j*/, double /*tauJ*/) const {}

    /// Whether the pair's bodies overlap now: |d| < D (the random start's test).
    bool overlapping(const PairMotion& m) const {
        return m.displacement.squaredNorm() < m.diameter * m.diameter;
    }

    /// The neighbours in list order (each prediction is exact and cheap).
    template <class MotionOf, class Consider>
    void inPredictionOrder(int count, MotionOf&& motionOf, Consider&& consider) const {
        for (int k = 0; k < count; ++k)
            consider(k, motionOf(k));
    }

    /// Earliest tau >= 0 with |d + w tau| = D + gamma tau for d = r_j - r_i, w = v_j - v_i:
    /// a tau^2 + 2 b tau + c = 0 with a = w.w - gamma^2, b = d.w - D gamma, c = d.d - D^2,
    /// in the cancellation-free form tau = c / (-b + sqrt(b^2 - a c)). Already overlapping (by
    /// rounding) and approaching: 0. +inf if they never touch.
    double collisionTime(const PairMotion& m) const {
        const double a = m.relativeVelocity.squaredNorm() - m.growthRate * m.growthRate;
        const double b = m.displacement.dot(m.relativeVelocity) - m.diameter * m.growthRate;
        const double c = m.displacement.squaredNorm() - m.diameter * m.diameter;
        constexpr double never = std::numeric_limits<double>::infinity();
        if (c <= 0.0) return b < 0.0 ? 0.0 : never;
        const double discriminant = b * b - a * c;
        if (a >= 0.0 && (b >= 0.0 || discriminant < 0.0)) return never;
        return c / (-b + std::sqrt(discriminant));
    }
    /// The engine's form: exact, so beyond the horizon too (touching and separating: +inf).
    Prediction collisionTime(const PairMotion& m, double /*horizon*/, Memory& /*memory*/,
                             const Memory::Resolved* /*resolved*/) {
        return {collisionTime(m)};
    }

    /// Contact of touching spheres: normal from i to j along the centre line, contact point at
    /// the midpoint (arms from each centre).
    PairContact contact(const PairMotion& m) const {
        const double distance = m.displacement.norm();
        const Vector3d n = m.displacement / distance;
        return {n, 0.5 * distance * n, -0.5 * distance * n, distance};
    }
    PairContact contact(const PairMotion& m, Memory& /*memory*/, Memory::Resolved& /*resolved*/) {
        return contact(m);
    }

    /// The impulse along the centre line (no torque).
    double resolve(const PairMotion& m, const PairContact& c, ParticleState& i,
                   ParticleState& j) const {
        return resolveCollision(m, c, i.velocity, j.velocity);
    }

    PredictorStats takeStats() { return {}; }
};

} // namespace sbpack

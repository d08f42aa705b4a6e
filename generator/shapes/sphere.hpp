#pragma once
// The sphere as a shape of the event-driven engine: an exact quadratic predictor and the contact
// of two spheres. Every shape answers the same two questions for a pair in the pair's local frame
// (docs/design.md §2-3): when do the two growing, moving bodies first touch, and where.

#include "shapes/pair_motion.hpp"

#include <cmath>
#include <limits>

namespace sbpack {

struct SphereShape {
    static constexpr bool kRotates = false;
    /// Circumradius over semi-axis: sizes the neighbour lists.
    double circumscribedRatio() const { return 1.0; }

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

    /// Contact of touching spheres: normal from i to j along the centre line, contact point at
    /// the midpoint (arms from each centre).
    PairContact contact(const PairMotion& m) const {
        const double distance = m.displacement.norm();
        const Vector3d n = m.displacement / distance;
        return {n, 0.5 * distance * n, -0.5 * distance * n, distance};
    }
};

} // namespace sbpack

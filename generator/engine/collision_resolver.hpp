#pragma once
// The resolver: the elastic impulse of a collision between two growing bodies (DESIGN.md §3,
// Lubachevsky-Stillinger): the normal velocity of the two surfaces at the contact point, growth
// included, is reversed, so afterwards they separate at least as fast as they grow together.

#include "shapes/pair_motion.hpp"

#include <algorithm>

namespace sbpack {

/// Applies the impulse J n to j and -J n to i (unit masses) and returns J >= 0. The contact
/// point on a body growing at rate gamma moves outward at (gamma / D) times its arm.
inline double resolveCollision(const PairMotion& m, const PairContact& c, Vector3d& velocityI,
                               Vector3d& velocityJ) {
    const double growth = m.growthRate / m.diameter;
    const double surfaceNormalVelocity =
        c.normal.dot(velocityJ - velocityI) + growth * c.normal.dot(c.armJ - c.armI);
    const double impulse = std::max(0.0, -surfaceNormalVelocity); // -2 u_n / (2 / m)
    velocityJ += impulse * c.normal;
    velocityI -= impulse * c.normal;
    return impulse;
}

} // namespace sbpack

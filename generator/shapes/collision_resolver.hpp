#pragma once
// The resolver: the elastic impulse of a collision between two growing bodies (docs/design.md §3,
// Lubachevsky-Stillinger): the normal velocity of the two surfaces at the contact point, growth
// included, is reversed, so afterwards they separate at least as fast as they grow together.

#include "shapes/pair_motion.hpp"

#include <algorithm>

namespace sbpack {

/// Spheres (arms along the normal, no torque): applies J n to j and -J n to i (unit masses) and
/// returns J >= 0. The contact point on a body growing at rate gamma moves outward at
/// (gamma / D) times its arm.
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

/// One rotating body's velocities, changed in place by the impulse.
struct BodyVelocity {
    Vector3d& linear;
    Vector3d& angular;
};

/// Rotating bodies with unit mass and isotropic inertia I (of diameter m.diameter; a mixture's
/// body k has I_k = size_k^2 I): the impulse J n acts at the common contact point. The
/// surfaces' normal velocity there,
///   u_n = n.(v_j + omega_j x a_j - v_i - omega_i x a_i) + (gamma / D) n.(a_j - a_i),
/// changes by J K with K = 2 + |a_i x n|^2 / I_i + |a_j x n|^2 / I_j; elastic: J = -2 u_n / K.
/// Returns J >= 0. Linear and angular momentum are conserved exactly (one contact point).
inline double resolveCollision(const PairMotion& m, const PairContact& c, double inertia,
                               BodyVelocity i, BodyVelocity j) {
    const Vector3d& n = c.normal;
    const double growth = m.growthRate / m.diameter;
    const double surfaceNormalVelocity =
        n.dot(j.linear + j.angular.cross(c.armJ) - i.linear - i.angular.cross(c.armI)) +
        growth * n.dot(c.armJ - c.armI);
    const Vector3d torqueI = c.armI.cross(n), torqueJ = c.armJ.cross(n);
    const double inverseI = 1.0 / (m.sizeI * m.sizeI), inverseJ = 1.0 / (m.sizeJ * m.sizeJ);
    const double k =
        2.0 + (inverseI * torqueI.squaredNorm() + inverseJ * torqueJ.squaredNorm()) / inertia;
    const double impulse = std::max(0.0, -2.0 * surfaceNormalVelocity / k);
    j.linear += impulse * n;
    i.linear -= impulse * n;
    j.angular += (inverseJ * impulse / inertia) * torqueJ;
    i.angular -= (inverseI * impulse / inertia) * torqueI;
    return impulse;
}

} // namespace sbpack

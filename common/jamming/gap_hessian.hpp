#pragma once
// The second derivatives of a contact's gap (docs/jamming.md §6.1): the exact signed distance s
// of two bodies (common/pair, any ConvexBody) as a function of the 12 coordinates (dr_A, dtheta_A,
// dr_B, dtheta_B), the rotations as R = exp([dtheta]) R0, from both surfaces' curvature at the
// contact points (the body's surfaceCurvature projected on the tangent plane; for the superball
// finite wherever no body coordinate of the contact point vanishes for p < 1: the edges of
// octahedron-like superballs, where it diverges).

#include "pair/pair_geometry.hpp"

namespace sbpack {

/// What the Hessian of a contact's gap needs: lever arms from each centre to its own closest
/// point (apart by `gap` along `normal` from A's to B's) and the two curvature tensors there.
struct ContactCurvature {
    Vector3d normal = Vector3d::Zero();     ///< n, unit, from A to B
    Vector3d leverA = Vector3d::Zero();     ///< A's closest point - r_A
    Vector3d leverB = Vector3d::Zero();     ///< B's closest point - r_B
    Matrix3d curvatureA = Matrix3d::Zero(); ///< surfaceCurvature of A along n
    Matrix3d curvatureB = Matrix3d::Zero(); ///< surfaceCurvature of B along -n
    double gap = 0.0;                       ///< s (0 for an ideal contact)
};

/// The contact of a pair of A's `shape` and B's, that shape scaled by `sizeB` (B's semi-axis over
/// A's, a mixture's pair: docs/mixtures.md), rotations body -> lab, d = r_B - r_A, at its normal
/// n and signed distance `gap` (signedDistance): both curvatures, and the closest points from
/// both support points, each trusted along the directions where its surface is the more curved
/// (a support point slides across a flat face under rounding changes of n, p > 1):
/// x_A = a + P (W_A + W_B)^{-1} W_B P^T (b - s n - a), x_B = x_A + s n; the midpoint of a and
/// b - s n where both surfaces are flat (or both curvatures diverge); where one diverges, its
/// own support point.
template <ConvexBody Body>
ContactCurvature contactCurvature(const Body& shape, const Matrix3d& rotationA,
                                  const Matrix3d& rotationB, const Vector3d& displacement,
                                  const Vector3d& normal, double gap, double sizeB = 1.0);

/// The lever arm of A to the midpoint of the two closest points, x - r_A: the contact point of
/// the rigidity matrix (docs/jamming.md §2; B's is this minus the displacement).
inline Vector3d midpointLever(const ContactCurvature& contact) {
    return contact.leverA + 0.5 * contact.gap * contact.normal;
}

using Matrix12d = Eigen::Matrix<double, 12, 12>;

/// Hess s in the order (dr_A, dtheta_A, dr_B, dtheta_B) (docs/jamming.md §6.1, Eq. H). Needs the
/// relative curvature W_A' + W_B (tangent plane) to be invertible: not two flat surfaces.
Matrix12d gapHessian(const ContactCurvature& contact);

} // namespace sbpack

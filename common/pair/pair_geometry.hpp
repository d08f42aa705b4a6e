#pragma once
// Pair geometry of two oriented convex bodies, superballs or any ConvexBody (docs/design.md §2).
//
// With K = A + B the Minkowski sum (both bodies centrally symmetric) and d = r_B - r_A:
//   scale factor     mu = max_{|n|=1} n.d / (h_A(n) + h_B(n))   (gauge of K at d)
//   signed distance  s  = max_{|n|=1} n.d - h_A(n) - h_B(n)      (gap > 0, -depth < 0)
// mu is found from its dual, a two-dimensional convex minimisation:
//   1 / mu = min { H(u) / |d| : u . d = |d| },  H = h_A + h_B,
// by Newton steps with an exact line search, checked by a primal certificate (the scaled
// bodies meet) and finished by a cutting-plane search on subgradients (the support points)
// where Newton stalls on the kinks of near-cubes; the octahedron p = 0.5 is exact over its
// candidate face normals.

#include "geometry/particle_shape.hpp"

namespace sbpack {

// ConvexBody, what the pair solvers need of a body, is geometry/shape_family.hpp's: every
// family's body is one.

/// Iteration limits and tolerances of the pair solvers, in one place.
struct PairTolerances {
    int maxNewtonIterations = 60;
    int maxLineSearchIterations = 100;
    /// Cuts of the cutting-plane finish (each takes 4/9 of the area: 200 reach rounding).
    int maxCuttingPlaneIterations = 200;
    /// Newton stops when a step moves the normal by less than this (radians).
    double normalTolerance = 1e-15;
    /// Relative excess of the primal meeting point's gauge over mu that sends the scale
    /// factor to the cutting-plane fallback.
    double certificateTolerance = 1e-12;
    /// Residual |d - grad H(n) - s n| / D above which the signed distance goes to the
    /// fallback. s is stationary in n, so a residual r costs about r^2 / curvature in s:
    /// 1e-7 D keeps s exact to ~1e-14 D, while stalls on kinks leave residuals ~0.1 D.
    double distanceCertificateTolerance = 1e-7;
    /// The other certificate of s: supportPlaneMismatch() / D below this (for s >= 0, s is
    /// then known to this much).
    double mismatchTolerance = 1e-15;
};

/// One pair: the two orientations (rotation body -> lab) and the displacement d = r_B - r_A.
/// A is `shape`; B is `shape` scaled by sizeB (a mixture's pair, docs/mixtures.md: its support
/// function sizeB h, support point sizeB x(n), gauge g / sizeB), identical where sizeB = 1.
template <ConvexBody Body> struct BodyPair {
    Body shape;
    Matrix3d rotationA;
    Matrix3d rotationB;
    Vector3d displacement;
    double sizeB = 1.0; ///< B's semi-axis over A's
};
using SuperballPair = BodyPair<Superball>;

/// B's own shape: `pair.shape` itself where sizeB = 1 (identical bodies, the same arithmetic).
template <ConvexBody Body> Body shapeB(const BodyPair<Body>& pair) {
    return pair.sizeB == 1.0 ? pair.shape : pair.shape.scaled(pair.sizeB);
}

struct ScaleFactorResult {
    double scaleFactor = 0.0; ///< mu; < 1 overlap, 1 touching
    Vector3d normal;          ///< unit, from A towards B
    int iterations = 0;       ///< Newton iterations
    int evaluations = 0;      ///< support-function evaluations, line searches included
    int fallbacks = 0;        ///< 1 if Newton stalled and the cutting-plane search finished
};

struct SignedDistanceResult {
    /// Gap if > 0, minus the penetration depth if < 0. Exact near contact; for deep overlaps
    /// (where f is not concave on the sphere) the local maximum from mu's normal, a lower
    /// bound on s, so it never understates a depth.
    double signedDistance = 0.0;
    double scaleFactor = 0.0;             ///< mu of the same pair
    Vector3d normal = Vector3d::Zero();   ///< unit contact normal, from A towards B
    Vector3d contactA = Vector3d::Zero(); ///< support point of A along normal, relative to r_A
    Vector3d contactB = Vector3d::Zero(); ///< support point of B along -normal, relative to r_A
    int iterations = 0; ///< Newton iterations (scale factor and distance together)
    int evaluations = 0;
    int fallbacks = 0; ///< cutting-plane finishes (scale factor and distance together)
};

/// How far the two supporting planes of unit normal n (from A to B), f = n.d - h_A(n) - h_B(n)
/// apart, miss a common perpendicular: B's contact point b, dropped by f onto A's plane and
/// pulled radially into A (a'), and the same with the roles swapped; the smaller |b - a'| - f.
/// With f >= 0 both points of each pair lie in the bodies, so f <= s <= f + this (to rounding);
/// for f < 0 it measures, like the tangent gradient d - grad H(n) - f n, how far n is from
/// stationary. Unlike that gradient it vanishes at the optimum where one body presents a face
/// (p > 1: its support point slides across the face under rounding changes of n), because the
/// other body's support point is well conditioned there. contactA, contactB as in
/// SignedDistanceResult (relative to r_A).
template <ConvexBody Body>
double supportPlaneMismatch(const BodyPair<Body>& pair, const Vector3d& n, double f,
                            const Vector3d& contactA, const Vector3d& contactB);

/// Orthonormal tangent basis (columns) of the plane orthogonal to the unit vector n.
Eigen::Matrix<double, 3, 2> tangentBasis(const Vector3d& n);

/// The largest f(n) = n.d - h_A(n) - h_B(n) over the normals (n + P c) / |n + P c|, |c_i| <= radius
/// (P the tangent basis of the unit n), by the centre-of-gravity cutting-plane search, which
/// needs no derivative where the support points of near-cubes jump (f is quasi-concave there for
/// s >= 0). Stops when the search polygon is within `resolution` (radians, about) of its centre,
/// or as soon as the supporting planes of the concave f~(u) = u.d - H(u) at its last few points
/// bound f over the polygon by the best value found (then the maximum, to rounding).
/// `interior`: the maximum lies well inside the square (within half its radius), so it is a
/// local maximum of f on the sphere, and the signed distance itself when >= 0.
struct LocalMaximum {
    Vector3d normal;
    double value = 0.0;
    bool interior = false;
    int evaluations = 0; ///< support-point pairs evaluated
};
template <ConvexBody Body>
LocalMaximum tangentMaximum(const BodyPair<Body>& pair, const Vector3d& n, double radius,
                            double resolution, int iterations);

/// The contact point of a pair, relative to r_A: the midpoint of the two support points
/// contactA and contactB. At touching they coincide; at a gap or depth s they are the closest
/// points (or the deepest), apart by s along the normal, so a lever arm to the midpoint gives
/// each body the same first-order change of the gap as its own support point (docs/jamming.md
/// §2). For spheres the midpoint of the centres, d / 2.
Vector3d contactPoint(const SignedDistanceResult& result);

/// mu of the pair. warmNormal, if non-zero, is a previous normal of the same pair.
template <ConvexBody Body>
ScaleFactorResult scaleFactor(const BodyPair<Body>& pair,
                              const Vector3d& warmNormal = Vector3d::Zero(),
                              const PairTolerances& tolerances = {});

/// Signed distance, normal and contact points; starts from the normal of mu.
template <ConvexBody Body>
SignedDistanceResult signedDistance(const BodyPair<Body>& pair,
                                    const Vector3d& warmNormal = Vector3d::Zero(),
                                    const PairTolerances& tolerances = {});

} // namespace sbpack

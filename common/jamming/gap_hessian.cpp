#include "jamming/gap_hessian.hpp"

#include "pair/pair_geometry.hpp"

#include <Eigen/LU>

#include <cmath>

namespace sbpack {

namespace {

using Matrix2d = Eigen::Matrix2d;
using Tangent = Eigen::Matrix<double, 2, 12>; ///< a linear map dq -> tangent plane

/// [v], the matrix of v x.
Matrix3d crossMatrix(const Vector3d& v) {
    Matrix3d m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

/// The Hessian in dtheta of -h(exp(-[dtheta]) n) beyond its curvature term w^T T w: the chart's
/// and the lever's part, -(sym(sigma n^T) - (sigma . n) I), sigma the support point along n
/// (docs/jamming.md §6.1).
Matrix3d rotationTerm(const Vector3d& sigma, const Vector3d& n) {
    const Matrix3d outer = sigma * n.transpose();
    return sigma.dot(n) * Matrix3d::Identity() - 0.5 * (outer + outer.transpose());
}

/// The curvature tensor (shape operator) of a body's surface at its support point along `normal`
/// (unit, lab frame; the surface's outward normal there), in the lab frame: symmetric, zero on
/// `normal`, the inverse radii of curvature on the tangent plane. `rotation`: body -> lab.
template <ConvexBody Body>
Matrix3d surfaceCurvature(const Body& shape, const Matrix3d& rotation, const Vector3d& normal) {
    // II = P^T Hess(xi) P / |grad xi| on the tangent plane (the body's own closed form).
    const Matrix3d bodyCurvature = shape.surfaceCurvature(rotation.transpose() * normal);
    const Matrix3d tangent = Matrix3d::Identity() - normal * normal.transpose();
    return tangent * rotation * bodyCurvature * rotation.transpose() * tangent;
}

} // namespace

template <ConvexBody Body>
ContactCurvature contactCurvature(const Body& shape, const Matrix3d& rotationA,
                                  const Matrix3d& rotationB, const Vector3d& displacement,
                                  const Vector3d& normal, double gap, double sizeB) {
    const Body shapeB = sizeB == 1.0 ? shape : shape.scaled(sizeB);
    ContactCurvature c;
    c.normal = normal;
    c.gap = gap;
    c.curvatureA = surfaceCurvature(shape, rotationA, normal);
    c.curvatureB = surfaceCurvature(shapeB, rotationB, -normal);
    const Vector3d a = rotationA * shape.supportPoint(rotationA.transpose() * normal);
    const Vector3d b =
        displacement - rotationB * shapeB.supportPoint(rotationB.transpose() * normal);
    const Eigen::Matrix<double, 3, 2> basis = tangentBasis(normal);
    const Matrix2d wA = basis.transpose() * c.curvatureA * basis;
    const Matrix2d wB = basis.transpose() * c.curvatureB * basis;
    const Vector3d toB = b - gap * normal - a; // tangential: the two points' disagreement
    // The weight of b: W_B (W_A + W_B)^{-1}; 0 where A's curvature diverges (an edge or vertex
    // of p < 1: its support point is exact), 1/2 where both do or both vanish.
    const Eigen::FullPivLU<Matrix2d> relative(wA + wB);
    Vector3d closestA = a + 0.5 * toB;
    if (!wA.allFinite() && wB.allFinite())
        closestA = a;
    else if (wA.allFinite() && !wB.allFinite())
        closestA = a + toB;
    else if (wA.allFinite() && relative.isInvertible())
        closestA = a + basis * relative.solve(wB * (basis.transpose() * toB));
    c.leverA = closestA;
    c.leverB = closestA + gap * normal - displacement;
    return c;
}

Matrix12d gapHessian(const ContactCurvature& c) {
    // s = max_{|u|=1} u . d - h_A(u) - h_B(u); by the envelope theorem and the dual form of the
    // support Hessians' tangent parts T = W^{-1} (docs/jamming.md §6.1):
    //   Hess s = Rot_A + Rot_B + s w_A^T w_A + u'^T W_B u' - (u'^T w_B + w_B^T u')
    //            - z^T (W_A' + W_B)^{-1} z,   z = W_B u' + w_A - w_B,  u' = u + s w_A,
    // u the tangential slip of B's closest point against A's, w = P^T (n x dtheta) per body,
    // W_A' = W_A (I + s W_A)^{-1} the curvature of A grown by s.
    const Vector3d& n = c.normal;
    const Eigen::Matrix<double, 3, 2> basis = tangentBasis(n);
    const Eigen::Matrix<double, 2, 3> pt = basis.transpose();
    Tangent slip = Tangent::Zero(), spinA = Tangent::Zero(), spinB = Tangent::Zero();
    slip.block<2, 3>(0, 0) = -pt;
    slip.block<2, 3>(0, 3) = pt * crossMatrix(c.leverA);
    slip.block<2, 3>(0, 6) = pt;
    slip.block<2, 3>(0, 9) = -pt * crossMatrix(c.leverB);
    spinA.block<2, 3>(0, 3) = pt * crossMatrix(n);
    spinB.block<2, 3>(0, 9) = pt * crossMatrix(n);
    const double s = c.gap;
    const Tangent grownSlip = slip + s * spinA;

    const Matrix2d wA = pt * c.curvatureA * basis, wB = pt * c.curvatureB * basis;
    const Matrix2d grownA = wA * (Matrix2d::Identity() + s * wA).inverse();
    const Tangent z = wB * grownSlip + spinA - spinB;

    Matrix12d hessian = Matrix12d::Zero();
    hessian.block<3, 3>(3, 3) = rotationTerm(c.leverA, n);
    hessian.block<3, 3>(9, 9) = rotationTerm(-c.leverB, n);
    hessian += s * spinA.transpose() * spinA;
    hessian += grownSlip.transpose() * wB * grownSlip;
    const Matrix12d mixed = grownSlip.transpose() * spinB;
    hessian -= mixed + mixed.transpose();
    hessian -= z.transpose() * (grownA + wB).inverse() * z;
    return hessian;
}

template ContactCurvature contactCurvature(const Superball&, const Matrix3d&, const Matrix3d&,
                                           const Vector3d&, const Vector3d&, double, double);
template ContactCurvature contactCurvature(const ParticleShape&, const Matrix3d&, const Matrix3d&,
                                           const Vector3d&, const Vector3d&, double, double);

} // namespace sbpack

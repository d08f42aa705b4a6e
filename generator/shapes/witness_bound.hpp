#pragma once
// Witness-point certificates of a superball pair (docs/design.md §3, "Witness-point
// certificates"). A plane evaluation at the unit normal n leaves two support points; kept in the
// bodies' frames they stay material points of the bodies whatever happens afterwards, collisions
// included. With the Hölder bound of the support function,
//   h(u) <= x(v) . u + C |u - v|^sigma      (unit u, v; x(v) the support point of v),
// the plane of n still has, at any later time,
//   g_n >= n . (P_j - P_i) - R C (theta_i^sigma + theta_j^sigma),
// where P_k are the two material points and theta_k bounds the angle body k has turned since
// (its accumulated rotation angle). Along the pair's present motion the material points' gap has
// an exact rate and a bounded curvature, so one concave lower bound certifies a whole interval.
// A stale record (turned too far, or too close) can only fail to certify, never certify wrongly.

#include "shapes/pair_motion.hpp"

#include <cmath>

namespace sbpack {

/// h(u) <= x(v) . u + constant |u - v|^exponent for unit u and v at most maxAngle apart, where h
/// is the support function of the unit superball (semi-axis 1) and x(v) its support point.
struct SupportHolderBound {
    double exponent = 2.0;
    double constant = 0.5;
    double maxAngle = 0.1;

    /// x^exponent for x >= 0 (without pow at p <= 1 and p = 1.5).
    double power(double x) const {
        if (exponent == 2.0) return x * x;
        if (exponent == 1.5) return x * std::sqrt(x);
        return std::pow(x, exponent);
    }
};

/// The bound of docs/design.md §3 ("Witness-point certificates") for exponent p: exponent
/// min(q, 2) with q = 2p / (2p - 1); for p <= 1 from the Hessian of the l_q norm, for p > 1
/// from the (q - 1)-Hölder continuity of sgn(a) |a|^{q - 1}. Throws std::invalid_argument unless
/// 0.5 < p < inf and 0 < maxAngle <= 0.25.
SupportHolderBound supportHolderBound(double p, double maxAngle = 0.1);

/// Whether the record of the plane of unit `normal` (from i to j) proves that the pair's signed
/// distance stays above `margin` for tau in [0, end] along the motion m (end finite);
/// `circumscribedRatio`: |x| <= it for every support point at semi-axis 1.
bool witnessSeparates(const PairMotion& m, const Vector3d& normal, const WitnessRecord& record,
                      const SupportHolderBound& bound, double circumscribedRatio, double end,
                      double margin);

} // namespace sbpack

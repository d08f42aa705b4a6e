#include "shapes/witness_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sbpack {
namespace {

/// Rounding of a body's orientation against its accumulated angle (radians): the quaternion
/// products of a window's flights and the matrices from them, each good to ~1e-16.
constexpr double kAngleRounding = 1e-14;

} // namespace

// docs/design.md §3, "Witness-point certificates". h(u) = ||u||_q, q = 2p / (2p - 1), and
// D(u, v) = h(u) - x(v) . u = h(u) - h(v) - x(v) . (u - v) (h is homogeneous of degree one).
// q >= 2 (p <= 1): D <= |u - v|^2 / 2 times the largest eigenvalue of the Hessian on the chord,
// at most (q - 1) / h(w) <= (q - 1) 3^{1/2 - 1/q} / |w|, and |w| >= cos(maxAngle / 2) there.
// 1 < q < 2 (p > 1): with F = h^q / q, the scalar Hölder bound of sgn(a) |a|^{q-1} (constant
// 2^{2-q}) gives F(u) <= F(v) + grad F(v) . (u - v) + E, E = (2^{2-q} / q) sum |u_c - v_c|^q <=
// (2^{2-q} / q) 3^{1 - q/2} |u - v|^q; the tangent of y^q at h(v) and the concavity of y^{1/q}
// then give D <= E / a^{q-1}, a = x(v) . u >= 1 - c |u - v| (h(v) >= 1, |x| <= c).
SupportHolderBound supportHolderBound(double p, double maxAngle) {
    if (!(p > 0.5 && p < std::numeric_limits<double>::infinity()))
        throw std::invalid_argument("supportHolderBound: p must lie in (0.5, inf)");
    if (!(maxAngle > 0.0 && maxAngle <= 0.25))
        throw std::invalid_argument("supportHolderBound: maxAngle must lie in (0, 0.25]");
    const double q = 2.0 * p / (2.0 * p - 1.0);
    if (q >= 2.0)
        return {2.0, (q - 1.0) * std::pow(3.0, 0.5 - 1.0 / q) / (2.0 * std::cos(0.5 * maxAngle)),
                maxAngle};
    const double c = std::pow(3.0, 1.0 / q - 0.5); // circumradius at semi-axis 1
    return {q,
            std::pow(2.0, 2.0 - q) / q * std::pow(3.0, 1.0 - 0.5 * q) *
                std::pow(1.0 - c * maxAngle, 1.0 - q),
            maxAngle};
}

// With y_k = Q_k x_k (semi-axis 1, lab frame) the material points' gap along n is
// M(tau) = n . d(tau) - R(tau) n . (y_i + y_j): M(0), M'(0) exact, M'' <= K = sum_k c |omega_k|
// (gamma + R_max |omega_k|) (d^2 (R Q x) / dtau^2 = gamma omega x Q x + R omega x (omega x Q x)).
// The lower bound L(tau) = M(0) + M'(0) tau - K tau^2 / 2 - R_max C sum_k (theta_k + |omega_k|
// end)^sigma is concave, so L(0) > margin and L(end) > margin certify [0, end].
bool witnessSeparates(const PairMotion& m, const Vector3d& n, const WitnessRecord& record,
                      const SupportHolderBound& bound, double circumscribedRatio, double end,
                      double margin) {
    if (!(end < std::numeric_limits<double>::infinity())) return false;
    const double spinI = m.angularVelocityI.norm(), spinJ = m.angularVelocityJ.norm();
    const double thetaI = m.turnedI - record.turnedI, thetaJ = m.turnedJ - record.turnedJ;
    // NaN: no record; negative: not a record of this pair's past
    if (!(thetaI >= 0.0 && thetaJ >= 0.0)) return false;
    const double reachI = thetaI + kAngleRounding + spinI * end;
    const double reachJ = thetaJ + kAngleRounding + spinJ * end;
    if (!(std::max(reachI, reachJ) <= bound.maxAngle)) return false;
    const double radius = 0.5 * m.diameter, growth = m.growthRate;
    const double largest = std::max(radius, radius + 0.5 * growth * end);
    // A mixture's body k: its points at R size_k, growing at gamma size_k / 2 (docs/mixtures.md).
    const double sI = m.sizeI, sJ = m.sizeJ;
    const Vector3d yI = m.orientationI * record.pointI, yJ = m.orientationJ * record.pointJ;
    const double along = n.dot(sI * yI + sJ * yJ);
    const double gap = n.dot(m.displacement) - radius * along;
    const double rate = n.dot(m.relativeVelocity) - 0.5 * growth * along -
                        radius * (sI * n.dot(m.angularVelocityI.cross(yI)) +
                                  sJ * n.dot(m.angularVelocityJ.cross(yJ)));
    const double curvature =
        circumscribedRatio * (sI * spinI * (std::abs(growth) + largest * spinI) +
                              sJ * spinJ * (std::abs(growth) + largest * spinJ));
    // The slack at the end bounds it over the whole interval (it grows with tau).
    const double slack =
        largest * bound.constant * (sI * bound.power(reachI) + sJ * bound.power(reachJ));
    const double atStart = gap - slack;
    const double atEnd = gap + rate * end - 0.5 * curvature * end * end - slack;
    return atStart > margin && atEnd > margin;
}

} // namespace sbpack

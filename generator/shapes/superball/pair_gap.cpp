#include "shapes/superball/pair_gap.hpp"

#include "geometry/superball.hpp"
#include "shapes/sphere.hpp"

#include <cmath>

namespace sbpack::superball {

namespace {
/// dg_n/dtau from the two support points x_k (lab frame, about each centre) by the envelope
/// theorem: dh_k/dtau = (gamma / D) h_k + n . (omega_k x x_k), h_k = n . x_k.
double planeGapRate(const PairMotion& m, double diameter, const Vector3d& n, const Vector3d& xI,
                    const Vector3d& xJ) {
    return n.dot(m.relativeVelocity) - (m.growthRate / diameter) * n.dot(xI + xJ) -
           n.dot(m.angularVelocityI.cross(xI)) - n.dot(m.angularVelocityJ.cross(xJ));
}
} // namespace

std::optional<SphereWindow> circumscribedWindow(const PairMotion& m, double c, double horizon) {
    const double D = m.diameter, gamma = m.growthRate;
    const PairMotion spheres{.displacement = m.displacement,
                             .relativeVelocity = m.relativeVelocity,
                             .diameter = c * D,
                             .growthRate = c * gamma};
    const double enter =
        m.displacement.squaredNorm() <= c * c * D * D ? 0.0 : SphereShape{}.collisionTime(spheres);
    if (enter >= horizon) return std::nullopt;
    double end = horizon;
    const double a = m.relativeVelocity.squaredNorm() - c * c * gamma * gamma;
    if (a > 0.0) { // after the spheres part for good, nothing touches
        const double b = m.displacement.dot(m.relativeVelocity) - c * c * D * gamma;
        const double c0 = m.displacement.squaredNorm() - c * c * D * D;
        end = std::min(end, (-b + std::sqrt(std::max(0.0, b * b - a * c0))) / a);
    }
    return SphereWindow{enter, end};
}

PlaneGap SuperballPairGap::planeGap(const Vector3d& n, double tau) const {
    const double diameter = m_.diameter + m_.growthRate * tau;
    const Superball body(p_, 0.5 * diameter * m_.sizeI);
    const Superball bodyB = m_.sizeJ == m_.sizeI ? body : Superball(p_, 0.5 * diameter * m_.sizeJ);
    const Matrix3d qi =
        advancedOrientation(m_.orientationI, m_.angularVelocityI, tau).toRotationMatrix();
    const Matrix3d qj =
        advancedOrientation(m_.orientationJ, m_.angularVelocityJ, tau).toRotationMatrix();
    const Vector3d bodyI = body.supportPoint(qi.transpose() * n);
    const Vector3d bodyJ = bodyB.supportPoint(qj.transpose() * n);
    const Vector3d xI = qi * bodyI, xJ = qj * bodyJ;
    return {n.dot(m_.displacement + m_.relativeVelocity * tau - xI - xJ),
            planeGapRate(m_, diameter, n, xI, xJ), bodyI, bodyJ};
}

Sample SuperballPairGap::at(double tau) {
    ++stats_.evaluations;
    const double diameter = m_.diameter + m_.growthRate * tau;
    const Vector3d d = m_.displacement + m_.relativeVelocity * tau;
    const SuperballPair pair{
        Superball(p_, 0.5 * diameter * m_.sizeI),
        advancedOrientation(m_.orientationI, m_.angularVelocityI, tau).toRotationMatrix(),
        advancedOrientation(m_.orientationJ, m_.angularVelocityJ, tau).toRotationMatrix(), d,
        m_.sizeJ / m_.sizeI};
    const double strain = m_.growthRate / diameter;
    const PairRates rates{m_.relativeVelocity, m_.angularVelocityI, m_.angularVelocityJ, strain};
    // Warm start: the last optimal normal carried along at its rate (first order in the time
    // since, while that turns it by less than limits.maxNormalCarry).
    const Vector3d shift = normalRate_ * (tau - lastTau_);
    if (shift.norm() < limits_.maxNormalCarry) normal_ = (normal_ + shift).normalized();
    // Wherever it proves the pair apart (above the contact gap) a lower bound on s serves: its
    // plane advances as well, and every decision there (not touching, which side of a bracket)
    // holds for s too (docs/design.md §3, near-cubes).
    const WarmNewton evaluation =
        exactSignedDistance(pair, normal_, limits_.contactGap * diameter, limits_, stats_, &rates);
    lastTau_ = tau;
    normalRate_ = evaluation.normalRate;
    return sample(tau, evaluation.result, evaluation.exact);
}

// ds/dtau by the envelope theorem: the closing speed along n of the two support points, each
// moving at omega x x + (gamma / D) x about its own centre; taken at their midpoint, the point
// where the resolver applies the impulse, so that "closing" means the same to both (on
// near-flat faces the support points can lie far apart on the face).
Sample SuperballPairGap::sample(double tau, const SignedDistanceResult& r, bool exact) const {
    const double diameter = m_.diameter + m_.growthRate * tau;
    const Vector3d d = m_.displacement + m_.relativeVelocity * tau;
    const double strain = m_.growthRate / diameter;
    const Vector3d xI = 0.5 * (r.contactA + r.contactB), xJ = xI - d;
    const Vector3d vI = m_.angularVelocityI.cross(xI) + strain * xI;
    const Vector3d vJ = m_.angularVelocityJ.cross(xJ) + strain * xJ;
    return {tau,
            r.signedDistance,
            r.normal.dot(m_.relativeVelocity + vJ - vI),
            r.normal,
            planeGapRate(m_, diameter, r.normal, r.contactA, d - r.contactB),
            exact};
}

} // namespace sbpack::superball

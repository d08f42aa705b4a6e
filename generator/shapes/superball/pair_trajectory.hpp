#pragma once
// The superball predictor's trajectory layer: the pair along its present motion, evaluated
// exactly (warm_distance.hpp) at any delay tau, each evaluation warm-started from the last
// normal carried at its rate; and the plane gap's exact rate by the envelope theorem.

#include "shapes/pair_motion.hpp"
#include "shapes/predictor_stats.hpp"
#include "shapes/superball/predictor_limits.hpp"
#include "shapes/superball/warm_distance.hpp"

namespace sbpack::superball {

/// dg_n/dtau from the two support points x_k (lab frame, about each centre) by the envelope
/// theorem: dh_k/dtau = (gamma / D) h_k + n . (omega_k x x_k), h_k = n . x_k.
inline double planeGapRate(const PairMotion& m, double diameter, const Vector3d& n,
                           const Vector3d& xI, const Vector3d& xJ) {
    return n.dot(m.relativeVelocity) - (m.growthRate / diameter) * n.dot(xI + xJ) -
           n.dot(m.angularVelocityI.cross(xI)) - n.dot(m.angularVelocityJ.cross(xJ));
}

/// s, its exact rate ds/dtau and the normal of the pair after tau, with that normal's plane gap
/// rate (ds/dtau but for where the impulse's point lies).
struct Sample {
    double tau = 0.0;
    double gap = 0.0;
    double rate = 0.0;
    Vector3d normal = Vector3d::Zero();
    double planeRate = 0.0;
    bool exact = true; ///< false: gap is a lower bound on s (a plane that separates them)
};

/// The pair along its motion, evaluated exactly, each evaluation warm-started from the last
/// normal (the pair's cached one at first).
class PairTrajectory {
  public:
    PairTrajectory(const PairMotion& m, double p, Vector3d& normal,
                   const SuperballPredictorLimits& limits, PredictorStats& stats)
        : m_(m), p_(p), normal_(normal), limits_(limits), stats_(stats) {}

    Sample at(double tau) {
        ++stats_.evaluations;
        const double diameter = m_.diameter + m_.growthRate * tau;
        const Vector3d d = m_.displacement + m_.relativeVelocity * tau;
        const SuperballPair pair{
            Superball(p_, 0.5 * diameter),
            advancedOrientation(m_.orientationI, m_.angularVelocityI, tau).toRotationMatrix(),
            advancedOrientation(m_.orientationJ, m_.angularVelocityJ, tau).toRotationMatrix(), d};
        const double strain = m_.growthRate / diameter;
        const PairRates rates{m_.relativeVelocity, m_.angularVelocityI, m_.angularVelocityJ,
                              strain};
        // Warm start: the last optimal normal carried along at its rate (first order in the
        // time since, while that turns it by less than limits.maxNormalCarry).
        const Vector3d shift = normalRate_ * (tau - lastTau_);
        if (shift.norm() < limits_.maxNormalCarry) normal_ = (normal_ + shift).normalized();
        // Wherever it proves the pair apart (above the contact gap) a lower bound on s serves:
        // its plane advances as well, and every decision there (not touching, which side of a
        // bracket) holds for s too. Near-cubes gain most: there an unconverged Newton's plane
        // spares the local search, which cost about half of p = 10's time (bench/RESULTS.md,
        // "Near-cubes: lower bounds down to the contact gap").
        const WarmNewton evaluation = exactSignedDistance(
            pair, normal_, limits_.contactGap * diameter, limits_, stats_, &rates);
        lastTau_ = tau;
        normalRate_ = evaluation.normalRate;
        return sample(tau, evaluation.result, evaluation.exact);
    }

    /// The sample at tau = 0 of an exact evaluation made elsewhere at this state (the contact
    /// the engine has just resolved), warm start of the next.
    Sample given(const SignedDistanceResult& r) {
        normal_ = r.normal;
        lastTau_ = 0.0;
        normalRate_ = Vector3d::Zero();
        return sample(0.0, r, true);
    }

  private:
    // ds/dtau by the envelope theorem: the closing speed along n of the two support points,
    // each moving at omega x x + (gamma / D) x about its own centre; taken at their midpoint,
    // the point where the resolver applies the impulse, so that "closing" means the same to
    // both (on near-flat faces the support points can lie far apart on the face).
    Sample sample(double tau, const SignedDistanceResult& r, bool exact) const {
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

    const PairMotion& m_;
    double p_;
    Vector3d& normal_;
    const SuperballPredictorLimits& limits_;
    PredictorStats& stats_;
    double lastTau_ = 0.0;
    Vector3d normalRate_ = Vector3d::Zero(); ///< of normal_ at lastTau_ (zero: unknown)
};

} // namespace sbpack::superball

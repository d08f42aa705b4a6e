#pragma once
// What a shape's predictor and contact function see of a pair: everything in the pair's local
// frame (displacement first, then motion), so gaps of 1e-13 D survive (docs/design.md §2).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <limits>

namespace sbpack {

using Eigen::Quaterniond;
using Eigen::Vector3d;

/// One body's state: the engine's particle, and what a shape advances (spheres keep their
/// orientation and have no angular velocity).
struct ParticleState {
    Vector3d position;
    Vector3d velocity;
    Quaterniond orientation = Quaterniond::Identity(); ///< body to lab
    Vector3d angularVelocity = Vector3d::Zero();       ///< lab frame
};

/// Two identical bodies i and j at the current time.
struct PairMotion {
    Vector3d displacement = Vector3d::Zero();     ///< r_j - r_i (minimum image)
    Vector3d relativeVelocity = Vector3d::Zero(); ///< v_j - v_i
    Quaterniond orientationI = Quaterniond::Identity(), orientationJ = Quaterniond::Identity();
    Vector3d angularVelocityI = Vector3d::Zero(), angularVelocityJ = Vector3d::Zero();
    double diameter = 1.0;   ///< D now
    double growthRate = 0.0; ///< dD/dt = gamma
    /// Each body's accumulated rotation angle now (the integral of |omega| dt since the engine's
    /// last rebuild): the witness records' clock (shapes/witness_bound.hpp).
    double turnedI = 0.0, turnedJ = 0.0;
};

/// Free flight of the orientation: exp(omega tau / 2) q0 for lab-frame omega, exact (constant
/// omega between collisions: isotropic inertia, docs/design.md §3).
inline Quaterniond advancedOrientation(const Quaterniond& q0, const Vector3d& omega, double tau) {
    const double speed = omega.norm();
    if (speed == 0.0 || tau == 0.0) return q0;
    return Quaterniond(Eigen::AngleAxisd(speed * tau, omega / speed)) * q0;
}

/// A predictor's answer for one pair, as a delay from now: the bodies touch at `time`, or, when
/// `contact` is false, they certainly do not touch before `time` and the pair must be predicted
/// again then (the safe smaller step of a prediction that hit its work limit).
struct Prediction {
    double time;
    bool contact = true;
};

/// Two material points of a pair: the support points of the pair's normal (PairMemory::normal,
/// from i to j) of both bodies at semi-axis 1 in their body frames (j's of +normal: the bodies
/// are centrally symmetric, so its point facing i is minus it), and each body's accumulated
/// rotation angle (PairMotion::turnedI, turnedJ) when they were taken; NaN angles: none.
struct WitnessRecord {
    Vector3d pointI = Vector3d::Zero(), pointJ = Vector3d::Zero();
    double turnedI = std::numeric_limits<double>::quiet_NaN(), turnedJ = turnedI;

    /// The same record seen from j (normal from j to i).
    WitnessRecord seenFromOther() const { return {-pointJ, -pointI, turnedJ, turnedI}; }
};

/// What a prediction leaves for the pair's next one: the warm-start normal from i to j, and a
/// lower bound on that normal's plane gap, g_n(0) >= gap, falling no faster than `rate` for tau in
/// [0, span] along the motion predicted (the tier-2 rate bound of SuperballShape::separatingPlane).
/// The next prediction may use the bound moved on to its time (`after`) only while neither particle
/// has changed its motion since, but for at that very time.
struct PairMemory {
    Vector3d normal = Vector3d::Zero();                    ///< zero: none yet
    double gap = -std::numeric_limits<double>::infinity(); ///< -inf: no bound
    double rate = 0.0;
    double span = 0.0;
    /// The prediction left found a contact, and `normal` is its normal there (the collision's
    /// contact starts from it).
    bool atContact = false;
    /// Two material points of the bodies on `normal`'s plane, valid whatever the particles did
    /// since (shapes/witness_bound.hpp); none once the normal has moved on.
    WitnessRecord witness{};

    /// The same memory `elapsed` later along the motion predicted.
    PairMemory after(double elapsed) const {
        PairMemory later = *this;
        later.gap = elapsed >= 0.0 && elapsed <= span ? gap + rate * elapsed
                                                      : -std::numeric_limits<double>::infinity();
        return later;
    }
    /// The normal and the witness (a particle's motion has changed: the gap bound no longer
    /// holds).
    PairMemory normalOnly() const {
        PairMemory kept;
        kept.normal = normal;
        kept.witness = witness;
        return kept;
    }
    /// Seen from the other particle from now on (normals from j to i).
    void flip() {
        normal = -normal;
        witness = witness.seenFromOther();
    }
};

/// What a shape whose exact predictor needs nothing from a pair's last prediction keeps of it
/// (the sphere): nothing (engine/pair_memories.hpp stores no record for it).
struct NoPairMemory {};

/// Where two touching bodies meet.
struct PairContact {
    Vector3d normal; ///< unit, from i towards j
    Vector3d armI;   ///< contact point minus r_i
    Vector3d armJ;   ///< contact point minus r_j
    double centreDistance;
};

} // namespace sbpack

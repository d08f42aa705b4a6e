#pragma once
// What a shape's predictor and contact function see of a pair: everything in the pair's local
// frame (displacement first, then motion), so gaps of 1e-13 D survive (docs/design.md §2).

#include "pair/pair_geometry.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

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

/// Two bodies i and j at the current time: identical, or of a mixture's two sizes, each with
/// its diameter sizeI D, sizeJ D about the pair's mean D (docs/mixtures.md).
struct PairMotion {
    Vector3d displacement = Vector3d::Zero();     ///< r_j - r_i (minimum image)
    Vector3d relativeVelocity = Vector3d::Zero(); ///< v_j - v_i
    Quaterniond orientationI = Quaterniond::Identity(), orientationJ = Quaterniond::Identity();
    Vector3d angularVelocityI = Vector3d::Zero(), angularVelocityJ = Vector3d::Zero();
    double diameter = 1.0;   ///< D now: the mean of the two bodies' diameters
    double growthRate = 0.0; ///< dD/dt = gamma
    /// Each body's diameter over D (their mean: sizeI + sizeJ = 2); 1 for identical bodies.
    double sizeI = 1.0, sizeJ = 1.0;
    /// Each body's accumulated rotation angle now (the integral of |omega| dt since the engine's
    /// last rebuild): the witness records' clock (shapes/witness_bound.hpp).
    double turnedI = 0.0, turnedJ = 0.0;
};

/// Below this phi^2 (phi = |omega| tau / 2, the half angle) advancedOrientation sums the series
/// of cos(phi) and sin(phi) / phi through phi^6: what it leaves, phi^8 / 8! < 2.5e-17, is below
/// half an ulp of 1, so the series is exact to rounding there, with neither sincos nor a square
/// root (the near-jammed cage's flights turn by phi ~ 1e-4; bench/RESULTS.md, "Pair records
/// across windows and the orientation series").
inline constexpr double kOrientationSeriesLimit = 1e-3;

/// Free flight of the orientation: exp(omega tau / 2) q0 for lab-frame omega, exact (constant
/// omega between collisions: isotropic inertia, docs/design.md §3): the unit quaternion
/// (cos phi, omega tau / 2 sin(phi) / phi) times q0.
inline Quaterniond advancedOrientation(const Quaterniond& q0, const Vector3d& omega, double tau) {
    const double half = 0.5 * tau;
    const double phi2 = omega.squaredNorm() * half * half;
    if (phi2 == 0.0) return q0;
    double cosine, sinc; // cos(phi), sin(phi) / phi
    if (phi2 < kOrientationSeriesLimit) {
        cosine = 1.0 - phi2 * (1.0 / 2.0 - phi2 * (1.0 / 24.0 - phi2 * (1.0 / 720.0)));
        sinc = 1.0 - phi2 * (1.0 / 6.0 - phi2 * (1.0 / 120.0 - phi2 * (1.0 / 5040.0)));
    } else {
        const double phi = std::sqrt(phi2);
        cosine = std::cos(phi);
        sinc = std::sin(phi) / phi;
    }
    const Vector3d v = omega * (half * sinc);
    return Quaterniond(cosine, v.x(), v.y(), v.z()) * q0;
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

    /// Moves the memory on by `elapsed` along the motion predicted, in place (the engine's
    /// records are updated where they lie).
    void moveOn(double elapsed) {
        gap = elapsed >= 0.0 && elapsed <= span ? gap + rate * elapsed
                                                : -std::numeric_limits<double>::infinity();
    }
    /// Keeps the normal and the witness only, in place (a particle's motion has changed: the
    /// gap bound no longer holds, nor the contact found along it).
    void forgetMotions() {
        gap = -std::numeric_limits<double>::infinity();
        rate = span = 0.0;
        atContact = false;
    }
    /// The same memory `elapsed` later along the motion predicted.
    PairMemory after(double elapsed) const {
        PairMemory later = *this;
        later.moveOn(elapsed);
        return later;
    }
    /// The normal and the witness alone.
    PairMemory normalOnly() const {
        PairMemory kept = *this;
        kept.forgetMotions();
        return kept;
    }
    /// What survives a synchronisation, where each body's accumulated rotation angle (the
    /// witness's clock) was `turnedI`, `turnedJ` and becomes the new zero: the normal and the
    /// witness, its angles counted from there (a window's end: the thermostat changes every
    /// motion, so the gap bound goes).
    PairMemory synchronised(double turnedI, double turnedJ) const {
        PairMemory kept = normalOnly();
        kept.witness.turnedI -= turnedI;
        kept.witness.turnedJ -= turnedJ;
        return kept;
    }
    /// Seen from the other particle from now on (normals from j to i).
    void flip() {
        normal = -normal;
        witness = witness.seenFromOther();
    }

    /// What the pair's predictions right after its collision, at that very state, are given
    /// (engine/pair_memories.hpp keeps the last collision's).
    struct Resolved;

    /// The columns this memory writes into a checkpoint's pair record after the pair's i and j
    /// (dataset resume_state/pair_records, docs/design.md §4): the normal from i to j, the
    /// witness points in i's and j's body frames and the bodies' angles at the record (NaN: no
    /// witness), as synchronised() leaves it.
    static constexpr std::size_t kCheckpointColumns = 3 + 3 + 3 + 2;
    void appendColumns(std::vector<double>& row) const;
    /// The memory of appendColumns' columns, or the problem that makes them none (the vectors
    /// not finite, the angles neither finite nor NaN, the normal neither unit nor zero).
    static std::optional<PairMemory> fromColumns(const double* columns, std::string& problem);
};

/// A pair the engine has just resolved at this very state: touching now is no contact (the
/// impulse left the surfaces separating at the contact point), and the contact it was resolved
/// at, seen from i, stands in for an evaluation of that state where known.
struct PairMemory::Resolved {
    Vector3d displacement = Vector3d::Zero(); ///< of the pair, from i
    std::optional<SignedDistanceResult> contact;

    /// The same seen from j: the normal and both points mirrored.
    Resolved seenFromOther() const {
        Resolved other{-displacement, contact};
        if (contact) {
            other.contact->normal = -contact->normal;
            other.contact->contactA = contact->contactB - displacement;
            other.contact->contactB = contact->contactA - displacement;
        }
        return other;
    }
};

/// What a shape whose exact predictor needs nothing from a pair's last prediction keeps of it
/// (the sphere): nothing (engine/pair_memories.hpp stores no record for it).
struct NoPairMemory {
    static constexpr std::size_t kCheckpointColumns = 0; ///< no pair records in a checkpoint
    struct Resolved {
        Resolved seenFromOther() const { return {}; }
    };
};

/// Where two touching bodies meet.
struct PairContact {
    Vector3d normal; ///< unit, from i towards j
    Vector3d armI;   ///< contact point minus r_i
    Vector3d armJ;   ///< contact point minus r_j
    double centreDistance;
};

} // namespace sbpack

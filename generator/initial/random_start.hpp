#pragma once
// The DTS starting state (paper Sec. III A, docs/design.md §3): N superballs of diameter D = 1
// placed at random without overlap, with uniformly random orientations, in the cubic box of packing
// fraction phi_init; Maxwell velocities at kT = 1 (m = 1) with zero total momentum, and random
// angular velocities at rotational kT = 1.

#include "packing/packing.hpp"
#include "random/random.hpp"

#include <functional>
#include <stdexcept>
#include <vector>

namespace sbpack {

/// Box edge L giving packing fraction phi for N particles of volume v1.
double boxLengthFor(int particles, double particleVolume, double phi);

/// Positions and orientations of a random start.
struct RandomPlacement {
    std::vector<Vector3d> positions;
    std::vector<Quaterniond> orientations; ///< identity for spheres (no random draws spent)
};

/// What a random start reports to and polls: called with the count placed so far every
/// kPlacementPoll trials; returning false stops the placement (issue 65 item 3: at N = 1e6,
/// p = 1.5, it takes about 30 s, in which a signal went unanswered).
using PlacementWatch = std::function<bool(int placed)>;
constexpr long kPlacementPoll = 1024;

/// The placement stopped because its watch said so.
struct PlacementStopped : std::runtime_error {
    PlacementStopped() : std::runtime_error("the random start was stopped") {}
};

/// Random sequential addition of non-overlapping superballs of exponent p and diameter 1 (a
/// mixture's particle k of diameter sizes[k] <= 1, docs/mixtures.md; empty: all 1): a trial is
/// accepted when every nearby body is outside its circumscribed sphere or the pair's scale
/// factor mu exceeds 1 (docs/design.md §2). Throws if it cannot place them within a generous
/// number of attempts, and PlacementStopped when `watch` returns false.
RandomPlacement randomPlacement(int particles, double p, double boxLength, Random& random,
                                const PlacementWatch& watch = {},
                                const std::vector<double>& sizes = {});

/// Gaussian velocities with the centre-of-mass motion removed, scaled to kT = 1 exactly.
std::vector<Vector3d> maxwellVelocities(int particles, Random& random);

/// Gaussian angular velocities scaled to rotational kT = I <omega^2> / 3 = 1 exactly.
std::vector<Vector3d> maxwellAngularVelocities(int particles, double inertia, Random& random);

} // namespace sbpack

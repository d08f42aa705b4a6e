#pragma once
// The DTS starting state (paper Sec. III A, docs/design.md §3): N superballs of diameter D = 1
// placed at random without overlap, with uniformly random orientations, in the cubic box of packing
// fraction phi_init; Maxwell velocities at kT = 1 (m = 1) with zero total momentum, and random
// angular velocities at rotational kT = 1.

#include "neighbours/cell_grid.hpp"
#include "packing/packing.hpp"
#include "random/random.hpp"
#include "shapes/shape.hpp"

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

/// Throws at the attempt past the last (a message naming --phi-init), or where `watch`, asked
/// every kPlacementPoll attempts with the count placed, says stop.
void placementCheck(long attempt, long attempts, int particles, int placed,
                    const PlacementWatch& watch);

/// The PairMotion of a trial body (size `sizeTrial`, orientation q) and a placed one at
/// displacement d from it: their mean diameter and sizes about it (docs/mixtures.md).
PairMotion trialPair(const Vector3d& d, const Quaterniond& q, const Quaterniond& placed,
                     double sizeTrial, double sizePlaced);

/// Random sequential addition of non-overlapping bodies of `shape` and diameter 1 (a mixture's
/// particle k of diameter sizes[k] <= 1, docs/mixtures.md; empty: all 1), at random
/// orientations where the shape rotates: a trial is accepted when every nearby body is outside
/// its circumscribed sphere or the shape finds the pair apart (EngineShape::overlapping; the
/// superball's scale factor mu > 1, docs/design.md §2). Throws if it cannot place them within a
/// generous number of attempts, and PlacementStopped when `watch` returns false.
template <EngineShape Shape>
RandomPlacement randomPlacement(const Shape& shape, int particles, double boxLength, Random& random,
                                const PlacementWatch& watch = {},
                                const std::vector<double>& sizes = {}) {
    const double reach = shape.circumscribedRatio(); // circumscribed spheres of diameter c
    const auto size = [&](int k) { return sizes.empty() ? 1.0 : sizes[k]; };
    CellGrid cells(boxLength, reach, particles);
    RandomPlacement placement;
    placement.positions.reserve(particles);
    const long attempts = 1000L * particles + 100000L;
    for (long attempt = 0; static_cast<int>(placement.positions.size()) < particles; ++attempt) {
        const int next = static_cast<int>(placement.positions.size());
        placementCheck(attempt, attempts, particles, next, watch);
        const Vector3d r(random.uniform() * boxLength, random.uniform() * boxLength,
                         random.uniform() * boxLength);
        const Quaterniond q = Shape::kRotates ? random.rotation() : Quaterniond::Identity();
        bool free = true;
        cells.forEachNearby(cells.cellContaining(r), [&](int j) {
            if (!free) return;
            const Vector3d d = minimumImage(placement.positions[j] - r, boxLength);
            const double pairSize = 0.5 * (size(next) + size(j)); // the pair's reach over c
            if (d.squaredNorm() >= reach * reach * pairSize * pairSize) return;
            free =
                !shape.overlapping(trialPair(d, q, placement.orientations[j], size(next), size(j)));
        });
        if (!free) continue;
        cells.insert(next, cells.cellContaining(r));
        placement.positions.push_back(r);
        placement.orientations.push_back(q);
    }
    return placement;
}

/// Gaussian velocities with the centre-of-mass motion removed, scaled to kT = 1 exactly.
std::vector<Vector3d> maxwellVelocities(int particles, Random& random);

/// Gaussian angular velocities scaled to rotational kT = I <omega^2> / 3 = 1 exactly.
std::vector<Vector3d> maxwellAngularVelocities(int particles, double inertia, Random& random);

} // namespace sbpack

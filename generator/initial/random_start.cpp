#include "initial/random_start.hpp"

#include "geometry/superball.hpp"
#include "neighbours/cell_grid.hpp"
#include "pair/pair_geometry.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbpack {
namespace {

/// Gaussian vectors, scaled so that their mean square is 3 / scale (kT = 1 for mass `scale`).
std::vector<Vector3d> thermalVectors(int particles, double scale, bool removeMean, Random& random) {
    std::vector<Vector3d> vectors(particles);
    Vector3d total = Vector3d::Zero();
    for (Vector3d& v : vectors) {
        v = random.normalVector();
        total += v;
    }
    double sumSquares = 0.0;
    for (Vector3d& v : vectors) {
        if (removeMean) v -= total / particles;
        sumSquares += v.squaredNorm();
    }
    const double factor = std::sqrt(3.0 * particles / (scale * sumSquares));
    for (Vector3d& v : vectors)
        v *= factor;
    return vectors;
}

} // namespace

double boxLengthFor(int particles, double particleVolume, double phi) {
    return std::cbrt(particles * particleVolume / phi);
}

RandomPlacement randomPlacement(int particles, double p, double boxLength, Random& random,
                                const PlacementWatch& watch, const std::vector<double>& sizes) {
    const Superball body(p, 0.5);
    const double reach = 2.0 * body.circumradius(); // circumscribed spheres of diameter c
    const auto size = [&](int k) { return sizes.empty() ? 1.0 : sizes[k]; };
    CellGrid cells(boxLength, reach, particles);
    RandomPlacement placement;
    placement.positions.reserve(particles);
    const long maxAttempts = 1000L * particles + 100000L;
    for (long attempt = 0; static_cast<int>(placement.positions.size()) < particles; ++attempt) {
        if (attempt == maxAttempts)
            throw std::runtime_error("random start: could not place " + std::to_string(particles) +
                                     " particles without overlap; lower --phi-init");
        if (watch && attempt % kPlacementPoll == 0 &&
            !watch(static_cast<int>(placement.positions.size())))
            throw PlacementStopped();
        const Vector3d r(random.uniform() * boxLength, random.uniform() * boxLength,
                         random.uniform() * boxLength);
        const Quaterniond q = body.isSphere() ? Quaterniond::Identity() : random.rotation();
        bool free = true;
        const int next = static_cast<int>(placement.positions.size());
        const Superball trial = sizes.empty() ? body : Superball(p, 0.5 * size(next));
        cells.forEachNearby(cells.cellContaining(r), [&](int j) {
            if (!free) return;
            const Vector3d d = minimumImage(placement.positions[j] - r, boxLength);
            const double pairSize = 0.5 * (size(next) + size(j)); // the pair's reach over c
            if (d.squaredNorm() >= reach * reach * pairSize * pairSize) return;
            if (body.isSphere()) {
                free = false;
                return;
            }
            const SuperballPair pair{trial, q.toRotationMatrix(),
                                     placement.orientations[j].toRotationMatrix(), d,
                                     size(j) / size(next)};
            free = scaleFactor(pair).scaleFactor > 1.0;
        });
        if (!free) continue;
        cells.insert(next, cells.cellContaining(r));
        placement.positions.push_back(r);
        placement.orientations.push_back(q);
    }
    return placement;
}

std::vector<Vector3d> maxwellVelocities(int particles, Random& random) {
    return thermalVectors(particles, 1.0, true, random);
}

std::vector<Vector3d> maxwellAngularVelocities(int particles, double inertia, Random& random) {
    return thermalVectors(particles, inertia, false, random);
}

} // namespace sbpack

#include "initial/random_start.hpp"

#include "neighbours/cell_grid.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbpack {

double boxLengthFor(int particles, double particleVolume, double phi) {
    return std::cbrt(particles * particleVolume / phi);
}

std::vector<Vector3d> randomSpherePositions(int particles, double boxLength, Random& random) {
    CellGrid cells(boxLength, 1.0, particles);
    std::vector<Vector3d> positions;
    positions.reserve(particles);
    const long maxAttempts = 1000L * particles + 100000L;
    for (long attempt = 0; static_cast<int>(positions.size()) < particles; ++attempt) {
        if (attempt == maxAttempts)
            throw std::runtime_error("random start: could not place " + std::to_string(particles) +
                                     " particles without overlap; lower --phi-init");
        const Vector3d r(random.uniform() * boxLength, random.uniform() * boxLength,
                         random.uniform() * boxLength);
        bool free = true;
        cells.forEachNearby(cells.cellContaining(r), [&](int j) {
            free = free && minimumImage(positions[j] - r, boxLength).squaredNorm() >= 1.0;
        });
        if (!free) continue;
        cells.insert(static_cast<int>(positions.size()), cells.cellContaining(r));
        positions.push_back(r);
    }
    return positions;
}

std::vector<Vector3d> maxwellVelocities(int particles, Random& random) {
    std::vector<Vector3d> velocities(particles);
    Vector3d total = Vector3d::Zero();
    for (Vector3d& v : velocities) {
        v = random.normalVector();
        total += v;
    }
    double sumSquares = 0.0;
    for (Vector3d& v : velocities) {
        v -= total / particles;
        sumSquares += v.squaredNorm();
    }
    const double scale = std::sqrt(3.0 * particles / sumSquares); // kT = <v^2> / 3 = 1
    for (Vector3d& v : velocities)
        v *= scale;
    return velocities;
}

} // namespace sbpack

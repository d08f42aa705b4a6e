#include "initial/random_start.hpp"

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

void placementCheck(long attempt, long attempts, int particles, int placed,
                    const PlacementWatch& watch) {
    if (attempt == attempts)
        throw std::runtime_error("random start: could not place " + std::to_string(particles) +
                                 " particles without overlap; lower --phi-init");
    if (watch && attempt % kPlacementPoll == 0 && !watch(placed)) throw PlacementStopped();
}

PairMotion trialPair(const Vector3d& d, const Quaterniond& q, const Quaterniond& placed,
                     double sizeTrial, double sizePlaced) {
    PairMotion m;
    m.displacement = d;
    m.orientationI = q;
    m.orientationJ = placed;
    m.diameter = 0.5 * (sizeTrial + sizePlaced);
    if (sizeTrial != sizePlaced) { // identical: sizes 1 exactly
        m.sizeI = sizeTrial / m.diameter;
        m.sizeJ = sizePlaced / m.diameter;
    }
    return m;
}

std::vector<Vector3d> maxwellVelocities(int particles, Random& random) {
    return thermalVectors(particles, 1.0, true, random);
}

std::vector<Vector3d> maxwellAngularVelocities(int particles, double inertia, Random& random) {
    return thermalVectors(particles, inertia, false, random);
}

} // namespace sbpack

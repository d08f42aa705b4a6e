#pragma once
// The DTS starting state (paper Sec. III A, DESIGN.md §3): N particles of diameter D = 1 placed at
// random without overlap in the cubic box of packing fraction phi_init, with Maxwell velocities
// at kT = 1 (m = 1) and zero total momentum.

#include "engine/event_driven_md.hpp"
#include "random/random.hpp"

#include <vector>

namespace sbpack {

/// Box edge L giving packing fraction phi for N particles of volume v1.
double boxLengthFor(int particles, double particleVolume, double phi);

/// Random sequential addition of non-overlapping spheres of diameter 1 (throws if it cannot
/// place them within a generous number of attempts).
std::vector<Vector3d> randomSpherePositions(int particles, double boxLength, Random& random);

/// Gaussian velocities with the centre-of-mass motion removed, scaled to kT = 1 exactly.
std::vector<Vector3d> maxwellVelocities(int particles, Random& random);

} // namespace sbpack

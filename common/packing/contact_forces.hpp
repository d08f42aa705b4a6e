#pragma once
// What sbgen's contact forces say about their packing (docs/jamming.md, "Contact forces"): the
// net force and torque on each particle, which vanish for a balanced self-stress, and the
// reduced pressure of their virial.

#include "packing/packing.hpp"

#include <vector>

namespace sbpack {

/// Per particle, the sums over its contacts of the force it receives and of its torque.
struct ForceBalance {
    std::vector<Vector3d> netForces;  ///< sum_c f_c n_c, n_c pointing into it, in kT / D
    std::vector<Vector3d> netTorques; ///< sum_c ((x_c - r_i) / D) x f_c n_c, in kT
};

/// The net force and torque residual of every particle under `forces` (the packing's
/// positions; lever arms by the minimum image). Throws std::invalid_argument when a contact
/// names a particle outside the packing.
ForceBalance forceBalance(const Packing& packing, const ContactForces& forces);

/// The reduced pressure of the forces' virial, sbgen's formula (docs/design.md §3) with the
/// time-averaged collision virial per contact: P = 1 + (1 / (3 N)) sum_c f_c (r_ij . n_c) / D,
/// f in kT / D and r_ij the minimum-image separation of the packing's centres.
double virialPressure(const Packing& packing, const ContactForces& forces);

} // namespace sbpack

#pragma once
// What sbgen's contact forces say about their packing (docs/jamming.md, "Contact forces"): the
// net force and torque on each particle, which vanish for a balanced self-stress, and the
// reduced pressure of their virial.

#include "packing/packing.hpp"

#include <cstdint>
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

/// The distribution of x = f / <f> over the stored contacts (docs/jamming.md §8, "The force
/// distribution"): the density in kBins equal bins over [0, kLargest], the fraction beyond, and the
/// moments. With no contacts, count = 0 and the rest NaN.
struct ForceDistribution {
    static constexpr int kBins = 40;
    static constexpr double kLargest = 4.0; ///< x; MRJ packings hold about 1 % beyond
    std::int64_t count = 0;                 ///< contacts with a stored force
    double mean = 0.0;                      ///< <f>, kT / D
    double secondMoment = 0.0;              ///< <x^2> (<x> = 1 by construction)
    double tailFraction = 0.0;              ///< fraction with x >= kLargest
    std::vector<double> edges;              ///< kBins + 1 edges of x
    std::vector<double> density;            ///< P(x) per bin: sums to (1 - tail) / bin width
};
ForceDistribution forceDistribution(const ContactForces& forces);

/// The reduced pressure of the forces' virial, sbgen's formula (docs/design.md §3) with the
/// time-averaged collision virial per contact: P = 1 + (1 / (3 N)) sum_c f_c (r_ij . n_c) / D,
/// f in kT / D and r_ij the minimum-image separation of the packing's centres.
double virialPressure(const Packing& packing, const ContactForces& forces);

} // namespace sbpack

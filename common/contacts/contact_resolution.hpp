#pragma once
// Honest contacts (docs/design.md §3, "Honest contacts"): does a contact tolerance separate a
// packing's contacts from its near contacts? At reduced pressure P the load-bearing gaps reach
// about gapsPerPressure / P D (the jam check's scale, contacts/jam_check.hpp), so a tolerance
// below that leaves true contacts open and Z and phi_R at it mean nothing (e.g. spheres at
// P = 1e10 and the paper's 1e-10 D: Z = 0, every particle a rattler). Then the distribution of
// the gaps is reported instead of a Z.

#include "contacts/contact_network.hpp"
#include "contacts/jam_check.hpp"
#include "packing/packing.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sbpack {

/// Pairs by decade of gap / D: counts[k] pairs with gap in [edges[k], edges[k + 1]), the first
/// bin also holding every gap below edges[0] (touching or rounding-level overlaps).
struct GapDistribution {
    std::vector<double> edges; ///< 1e-16, 1e-15, ..., 1e-2 (units of D)
    std::vector<long> counts;  ///< one fewer than edges
};

struct ContactResolution {
    /// Whether the tolerance separates the contacts; unknown without a reduced pressure.
    std::optional<bool> resolved;
    /// The smallest tolerance that does at the packing's pressure: gapsPerPressure / P (units D).
    double neededTolerance = 0.0;
    /// Filled only when not resolved: what to look at instead of Z.
    std::optional<GapDistribution> gaps;
    /// Where every coordinate is a single-precision number (singlePrecisionRounding): how far
    /// that rounding may move a pair's surfaces, units of D.
    std::optional<double> singlePrecision;
    std::string verdict; ///< one line
};

/// Whether `packing` was stored in single precision (a file through OVITO or GSD: every position
/// coordinate a float32, exactly or as its 9-digit decimal, some with more than 12 significant
/// bits, so not a hand-made lattice of short binary fractions; the orientations are normalised
/// on reading, off float32's grid), and if so how far that rounding may move two particles'
/// surfaces against each other, units of D: 2 sqrt(3) L 2^-24 for the centres, 2 r_c 2^-23 for
/// the orientations (docs/design.md §3, "Honest contacts").
std::optional<double> singlePrecisionRounding(const Packing& packing);

/// Whether the worst overlap of `contacts` (computed at particle diameter `diameter`) lies within
/// `rounding` (singlePrecisionRounding, units of D): overlaps that are rounding, not a defect.
bool overlapsWithinRounding(const ContactResult& contacts, double diameter,
                            const std::optional<double>& rounding);

/// The resolution of `tolerance` (units of D) for `packing`: not resolved where the file is in
/// single precision and the tolerance is below its rounding, or below the gaps of its recorded
/// reduced pressure.
ContactResolution resolveContacts(const Packing& packing, double tolerance,
                                  const JamCheckParameters& scale = {});

/// Pairs with gaps below 1e-2 D, by decade.
GapDistribution gapDistribution(const Packing& packing);

/// One line per non-empty decade, e.g. "  [1e-09, 1e-08) D: 1234 pairs".
std::string describe(const GapDistribution& gaps);

} // namespace sbpack

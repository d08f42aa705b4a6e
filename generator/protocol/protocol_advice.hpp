#pragma once
// What sbgen says once, before a run, about a protocol that will be very slow or is unlikely to
// jam, with the cost it expects (docs/design.md §3, "Expected cost"): a model fitted to
// measured runs (bench/RESULTS.md, "Fidelity", E11), not a promise.

#include "protocol/jamming_protocol.hpp"

#include <string>
#include <vector>

namespace sbpack {

/// The expected cost of a run from phi_init to pressureFinal.
struct ExpectedCost {
    double collisions; ///< total, all particles
    double cpuSeconds; ///< at the shape's measured collision rate on this machine class
};

/// Collisions per particle: kFastPhaseCollisions up to the switch, then per decade of pressure
/// a constant over gamma_slow (the gaps shrink tenfold per decade at a rate gamma while the
/// collision rate grows as P, so each decade costs about 1/gamma collisions per particle);
/// CPU seconds at the shape's measured collision rate (shapes/measured_protocol.hpp).
ExpectedCost expectedCost(const ProtocolParameters& parameters);

/// The slow phase's windows per doubling of the reduced pressure at growth rate `rate` in the
/// cost model (expectedCost's collisions per particle per decade, log10 2 of a decade, over the
/// collisions per particle of a window): about 51 for superballs at 1e-2, 1440 for spheres at
/// 1e-4 (docs/design.md §3, "Plateaus").
double expectedWindowsPerDoubling(const ProtocolParameters& parameters, double rate);

/// The warnings, each one line, for a protocol that is very slow (expected CPU above an hour),
/// outside the paper's fast-rate range (0.005, 0.05), beyond the practical exponents (p > 10),
/// or of near-cubes in a box a column of them can span (refused as not jammed, bench/RESULTS.md,
/// "Near-cubes after the jam check"). Empty for the defaults at every p <= 10 and N = 1000.
std::vector<std::string> protocolWarnings(const ProtocolParameters& parameters);

} // namespace sbpack

#pragma once
// The superball's measurements (shapes/measured_protocol.hpp): the paper's rates
// (protocol/paper_rates), the engines' collision rates and the slow phase's cost, for the
// rotating superball and the exact sphere engine of p = 1 (docs/design.md §3).

#include "shapes/measured_protocol.hpp"

namespace sbpack {

/// Collisions per CPU second measured at exponent p (N = 1000 and 200 runs; bench/RESULTS.md,
/// "Results (collisions per CPU second, median over 5 seeds)"), interpolated log-linearly in p;
/// the exact sphere engine's at p = 1.
double collisionRate(double p);

/// What sbgen has measured of superballs of exponent p.
MeasuredProtocol superballProtocol(double p);

} // namespace sbpack

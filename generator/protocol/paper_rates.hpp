#pragma once
// The expansion rates of the paper's protocol at each p (Sec. III A: "gamma in (0.05, 0.005) up
// to P = 1e6", then "gamma ~ 0.001"): the paper states a range, not the rate it used at each p,
// so the defaults are the rates at which sbgen reproduces the paper's phi (fast) and Z (slow,
// superballs) at N = 1000. How they were measured, and the conventions tested and excluded
// first: docs/design.md §3.

#include <vector>

namespace sbpack {

/// A value measured at exponent p: a rate gamma (dD/dt in units of sqrt(kT/m)), or a cost.
struct MeasuredAtP {
    double p;
    double value;
};

/// How a table is read between its p values.
enum class Interpolation { linear, logarithmic };

/// The table (ascending in p) at p: interpolated in p, linearly in the value or in its
/// logarithm, its end values outside.
double interpolateInP(const std::vector<MeasuredAtP>& table, double p,
                      Interpolation kind = Interpolation::linear);

/// The default fast rate for exponent p: the measured rates interpolated linearly in p between
/// the paper's p values, the end values outside [0.85, 1.5] (beyond the paper's range: its
/// nearest protocol).
double paperFastRate(double p);
/// The measured (p, rate) pairs behind paperFastRate, ascending in p.
const std::vector<MeasuredAtP>& paperFastRates();

/// The default slow rate of rotating superballs (p != 1), interpolated as paperFastRate.
double paperSlowRate(double p);
/// The measured (p, rate) pairs behind paperSlowRate, ascending in p.
const std::vector<MeasuredAtP>& paperSlowRates();

} // namespace sbpack

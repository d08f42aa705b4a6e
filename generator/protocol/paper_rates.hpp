#pragma once
// The expansion rates of the paper's protocol at each p (Sec. III A: "gamma in (0.05, 0.005) up
// to P = 1e6", then "gamma ~ 0.001"; the paper states a range and an order of magnitude, not the
// rates it used at each p). The defaults are the rates at which sbgen reproduces the paper's
// tables at N = 1000: the fast rate its phi (bench/RESULTS.md, "Fidelity", E8;
// bench/fidelity/rate_calibration.spec), the slow rate of superballs its Z (E11;
// bench/fidelity/slow_rate.spec), measured after the conventions that could explain the
// difference were tested and excluded (E1-E7: engine continuity at p = 1, system size, inertia,
// thermostat, thermostat interval, slow rate, final pressure). docs/design.md §3.

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

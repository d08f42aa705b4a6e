#pragma once
// The fast expansion rate of the paper's protocol at each p (Sec. III A: "gamma in (0.05, 0.005)
// up to P = 1e6"; the paper states the range, not the rate it used at each p). The default is
// the rate, inside that range, at which sbgen reproduces the paper's phi at N = 1000: measured at
// the paper's p values (bench/RESULTS.md, "Fidelity", E8; bench/fidelity/rate_calibration.spec)
// after the conventions that could explain the difference were tested and excluded (E1-E7:
// engine continuity at p = 1, system size, inertia, thermostat, thermostat interval, slow rate,
// final pressure). docs/design.md §3.

#include <vector>

namespace sbpack {

/// The default fast rate gamma (dD/dt in units of sqrt(kT/m)) for exponent p: the measured rates
/// interpolated linearly in p between the paper's p values, the end values outside
/// [0.85, 1.5] (beyond the paper's range: its nearest protocol).
double paperFastRate(double p);

/// The measured (p, rate) pairs behind paperFastRate, ascending in p.
struct MeasuredRate {
    double p;
    double gamma;
};
const std::vector<MeasuredRate>& paperFastRates();

} // namespace sbpack

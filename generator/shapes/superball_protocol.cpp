#include "shapes/superball_protocol.hpp"

#include "protocol/paper_rates.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

namespace sbpack {
namespace {

/// Collisions per CPU second of the rotating engine, measured on this machine class with the
/// other core busy (bench/RESULTS.md: "Extreme p" at N = 50 for p <= 0.55, the "Fidelity" E9
/// defaults at N = 1000 for 0.85-1.5, "Near-cubes after the jam check" and the local search at
/// N = 200 for 2-3; "Near-octahedra" at N = 100 for p = 0.5000001, so that the rate falls, and
/// the warning comes, as p -> 1/2: issue 46, defect 12; "The near-cube rates again" for p >= 5:
/// the N = 1000 ensembles at 5 and 10, the feasibility row at 20, N = 50 at 50-1000).
const std::vector<MeasuredAtP>& rotatingRates() {
    static const std::vector<MeasuredAtP> rates = {
        {0.5000001, 2.1e2}, {0.501, 3.8e3}, {0.51, 1.8e4}, {0.55, 3.9e4},  {0.85, 7.8e4},
        {1.1, 8.4e4},       {1.5, 7.4e4},   {2.0, 5.3e4},  {3.0, 3.6e4},   {5.0, 1.7e4},
        {10.0, 1.1e4},      {20.0, 5.2e3},  {50.0, 3.3e3}, {100.0, 1.6e3}, {1000.0, 1.4e3},
    };
    return rates;
}

/// The exact sphere engine (bench/RESULTS.md, "MRJ spheres, N = 1000").
constexpr double kSphereRate = 6.5e5;

/// Collisions per particle per decade of pressure, times gamma_slow, in the slow phase
/// (bench/RESULTS.md, "Fidelity", E11: the same runs at gamma_slow 1e-2 and 5e-3; spheres
/// from "MRJ spheres, N = 1000": 290 M collisions at 1e-4 against 40 M at 1e-3 to 1e12).
constexpr double kSlowCollisionsTimesRateSpheres = 4.8;
constexpr double kSlowCollisionsTimesRateSuperballs = 17.0;

} // namespace

double collisionRate(double p) {
    return p != 1.0 ? interpolateInP(rotatingRates(), p, Interpolation::logarithmic) : kSphereRate;
}

MeasuredProtocol superballProtocol(double p) {
    // The octahedron p = 0.5 itself stalls the predictor (194 collisions in 20 CPU s at N = 50;
    // p = 0.501 makes 3.8e3 per CPU s): bench/RESULTS.md, "Extreme p".
    if (!(std::isfinite(p) && p > 0.5 && p <= 1e3))
        return {.problem = MeasuredProtocol::Problem{
                    "p", "must be in (0.5, 1000] (the octahedron p = 0.5 stalls the "
                         "event-driven predictor)"}};
    const bool sphere = p == 1.0; // the exact sphere engine
    MeasuredProtocol measured{
        .fastRate = paperFastRate(p),
        // Spheres: Z = 5.978 +- 0.005 at N = 1000 at 1e-4, where 1e-3 leaves 5.94 (docs/design.md
        // §3).
        .slowRate = sphere ? 1e-4 : paperSlowRate(p),
        .collisionRate = collisionRate(p),
        .slowCollisionsTimesRate =
            sphere ? kSlowCollisionsTimesRateSpheres : kSlowCollisionsTimesRateSuperballs,
    };
    if (p > 10.0)
        measured.warnings.push_back(
            fmt::format("p = {:g}: beyond the ensembles measured (p <= 10 at N = 1000); at "
                        "N = 200, p = 20 jammed without order in 14 CPU minutes and p = 50 "
                        "aligned its axes (P4 0.93) and was refused (bench/RESULTS.md, \"The "
                        "feasibility row\")",
                        p));
    return measured;
}

} // namespace sbpack

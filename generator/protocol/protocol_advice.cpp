#include "protocol/protocol_advice.hpp"

#include "shapes/registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sbpack {
namespace {

/// Collisions per particle up to the switch pressure at the paper's fast rates (0.01-0.03:
/// 2.5-4e3 to P = 1e7, bench/RESULTS.md, "Fidelity", E8).
constexpr double kFastPhaseCollisions = 3.0e3;

/// Above this expected CPU time a run is called very slow.
constexpr double kSlowRunSeconds = 3600.0;

/// The paper's range of fast rates (Sec. III A).
constexpr double kPaperFastMin = 0.005, kPaperFastMax = 0.05;

/// Near-cubes (p >= kNearCubeExponent) form a column spanning a box this few diameters across
/// (N = 200 at p >= 3).
constexpr double kColumnBoxDiameters = 8.0;

/// Below this N, jammed packings are often partly ordered, phi and Z above MRJ's, at every p
/// measured (bench/RESULTS.md, "Small boxes order": p = 0.85 to 1.5, N = 40 to 200, defaults).
constexpr int kSmallBoxParticles = 250;

/// The box edge in diameters at jamming, with phi about 0.85 (bench/RESULTS.md, "Near-cubes after
/// the jam check").
double jammedBoxDiameters(const ProtocolParameters& parameters) {
    const double unitVolume = ParticleShape(parameters.shape, 0.5).volume(); // D = 1
    return std::cbrt(parameters.particles * unitVolume / 0.85);
}

std::string costText(const ExpectedCost& cost) {
    const double hours = cost.cpuSeconds / 3600.0;
    return hours >= 1.0
               ? fmt::format("about {:.3g} CPU hours ({:.2g} collisions)", hours, cost.collisions)
               : fmt::format("about {:.2g} CPU minutes ({:.2g} collisions)", cost.cpuSeconds / 60.0,
                             cost.collisions);
}

} // namespace

ExpectedCost expectedCost(const ProtocolParameters& parameters) {
    // The slow phase's decades of pressure, those of the finish (issue 64) at its own rate.
    const auto decadesTo = [&](double pressure) {
        return std::max(0.0, std::log10(pressure / std::max(1.0, parameters.pressureSwitch)));
    };
    const double total = decadesTo(parameters.pressureFinal);
    const double slow =
        parameters.pressureFinish > 0.0 ? decadesTo(parameters.pressureFinish) : total;
    const MeasuredProtocol measured = measuredProtocol(parameters.shape);
    const double perDecade = measured.slowCollisionsTimesRate;
    const double perParticle = kFastPhaseCollisions +
                               perDecade * slow / parameters.slowGrowthRate() +
                               perDecade * (total - slow) / parameters.finishGrowthRate();
    const double collisions = perParticle * parameters.particles;
    return {collisions, collisions / measured.collisionRate};
}

double expectedWindowsPerDoubling(const ProtocolParameters& parameters, double rate) {
    return measuredProtocol(parameters.shape).slowCollisionsTimesRate * std::log10(2.0) /
           (rate * parameters.collisionsPerWindow);
}

std::vector<std::string> protocolWarnings(const ProtocolParameters& parameters) {
    std::vector<std::string> warnings;
    const ExpectedCost cost = expectedCost(parameters);
    if (cost.cpuSeconds > kSlowRunSeconds)
        warnings.push_back(
            "a very slow run: expected " + costText(cost) +
            " from the measured collision counts and rates (docs/design.md §3)" +
            (parameters.costLimit > 0.0
                 ? fmt::format("; --cost-limit stops it, not jammed, after {:g} times that",
                               parameters.costLimit)
                 : std::string()));
    const double fast = parameters.fastGrowthRate();
    if (fast > kPaperFastMax)
        warnings.push_back(
            fmt::format("gamma-fast {:g} is above the paper's range (0.005, 0.05): the fast "
                        "phase ends far from jamming and the slow phase densifies the "
                        "packing, to larger phi and Z than MRJ (paper Sec. III A)",
                        fast));
    if (fast < kPaperFastMin)
        warnings.push_back(
            fmt::format("gamma-fast {:g} is below the paper's range (0.005, 0.05): the "
                        "compression follows the equilibrium branch and may crystallise "
                        "(paper Sec. III A)",
                        fast));
    // issue 66 item 3: "--gamma-slow 1e-3, a faster slow phase" is so for spheres (1e-4) and five
    // times slower for superballs (4e-3 to 7e-3); the slow phase's collisions go as 1 / rate.
    ProtocolParameters defaults = parameters;
    defaults.gammaSlow.reset();
    if (parameters.gammaSlow && *parameters.gammaSlow < defaults.slowGrowthRate())
        warnings.push_back(fmt::format(
            "gamma-slow {:g} is slower than the default for {}, {:.2g}: about {:.2g} "
            "times the slow phase's collisions; a larger rate is the faster one, and speed "
            "(--speed, speed=) scales the default for any shape (docs/design.md §3, \"Speed\")",
            *parameters.gammaSlow, parameters.shape.describe(), defaults.slowGrowthRate(),
            defaults.slowGrowthRate() / *parameters.gammaSlow));
    for (const std::string& warning : measuredProtocol(parameters.shape).warnings)
        warnings.push_back(warning);
    const double box = jammedBoxDiameters(parameters);
    if (ParticleShape(parameters.shape, 0.5).stacksInColumns() && box < kColumnBoxDiameters)
        warnings.push_back(
            fmt::format("{}, N = {}: the box will be about {:.1f} diameters across, so "
                        "a column of near-cubes can span it and carry the pressure "
                        "alone; such runs end refused as not jammed (at N = 200 most "
                        "did); N >= 1000 avoids it",
                        parameters.shape.describe(), parameters.particles, box));
    else if (parameters.particles < kSmallBoxParticles)
        warnings.push_back(
            fmt::format("N = {}: a box this small often jams partly ordered, phi and Z "
                        "above MRJ's (a third to two thirds of the seeds at N = 40-100, "
                        "p = 0.85-1.5, and still one of three at N = 200, p = 1.5: "
                        "bench/RESULTS.md, \"Small boxes order\"); N >= {} for MRJ, the "
                        "paper's N is 1000 and 5000",
                        parameters.particles, kSmallBoxParticles));
    return warnings;
}

} // namespace sbpack

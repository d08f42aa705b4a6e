// The expected cost and the warnings sbgen prints once before a run (generator/protocol/
// protocol_advice): the model against the runs it was fitted to, and a warning exactly where a
// protocol is very slow, outside the paper's fast-rate range or unlikely to jam.
#include "protocol/protocol_advice.hpp"
#include "shapes/superball_protocol.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace sbpack {
namespace {

ProtocolParameters defaults(double p, int particles) {
    ProtocolParameters parameters;
    parameters.shape = sbpack::ShapeSpec::superball(p);
    parameters.particles = particles;
    return parameters;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(ProtocolAdvice, TheDefaultsAtThePapersExponentsNeedNoWarning) {
    for (double p : {0.85, 0.9, 0.95, 0.975, 1.0, 1.025, 1.05, 1.1, 1.2, 1.3, 1.4, 1.5, 2.0})
        EXPECT_TRUE(protocolWarnings(defaults(p, 1000)).empty()) << "p = " << p;
}

TEST(ProtocolAdvice, TheExpectedCollisionsMatchTheMeasuredRunsWithinAFactorOfTwo) {
    // bench/RESULTS.md: spheres, N = 1000, defaults (gamma_slow 1e-4) to 1e12: about 290 M
    // collisions; with gamma_slow 1e-3: 40 M. p = 1.5, N = 1000, defaults: 9.4-12.2 M (E9).
    const double spheres = expectedCost(defaults(1.0, 1000)).collisions;
    EXPECT_GT(spheres, 290e6 / 2);
    EXPECT_LT(spheres, 290e6 * 2);
    ProtocolParameters faster = defaults(1.0, 1000);
    faster.gammaSlow = 1e-3;
    EXPECT_GT(expectedCost(faster).collisions, 40e6 / 2);
    EXPECT_LT(expectedCost(faster).collisions, 40e6 * 2);
    const double superballs = expectedCost(defaults(1.5, 1000)).collisions;
    EXPECT_GT(superballs, 9.4e6 / 2);
    EXPECT_LT(superballs, 12.2e6 * 2);
}

TEST(ProtocolAdvice, TheCostGrowsWithNAndTheSlowPhaseAsOneOverItsRate) {
    const ExpectedCost base = expectedCost(defaults(1.2, 1000));
    EXPECT_NEAR(expectedCost(defaults(1.2, 5000)).collisions, 5.0 * base.collisions,
                1e-9 * base.collisions);
    ProtocolParameters slower = defaults(1.2, 1000);
    slower.gammaSlow = slower.slowGrowthRate() / 10.0;
    ProtocolParameters noSlowPhase = defaults(1.2, 1000);
    noSlowPhase.pressureFinal = noSlowPhase.pressureSwitch;
    const double fastPart = expectedCost(noSlowPhase).collisions;
    EXPECT_NEAR(expectedCost(slower).collisions - fastPart, 10.0 * (base.collisions - fastPart),
                1e-9 * base.collisions);
    // Flatter shapes collide more slowly: the rate falls from p = 1.5 to the near-cubes.
    EXPECT_GT(collisionRate(1.5), collisionRate(3.0));
    EXPECT_GT(collisionRate(3.0), collisionRate(10.0));
    EXPECT_GT(collisionRate(1.0), 5.0 * collisionRate(1.1)); // the exact sphere engine
}

TEST(ProtocolAdvice, ADoublingOfThePressureTakesTheModelsWindows) {
    // docs/design.md §3, "Plateaus": 17 (superballs) or 4.8 (spheres) collisions per particle
    // per decade over the rate, log10 2 of a decade, 10 collisions per particle a window; about
    // 50-60 windows were measured at p = 10, gamma_slow 1e-2 ("A stalled pressure checks the jam").
    EXPECT_NEAR(expectedWindowsPerDoubling(defaults(10.0, 1000), 1e-2), 51.2, 0.1);
    EXPECT_NEAR(expectedWindowsPerDoubling(defaults(1.0, 1000), 1e-4), 1445.0, 1.0);
    EXPECT_NEAR(expectedWindowsPerDoubling(defaults(3.0, 1000), 2e-2),
                0.5 * expectedWindowsPerDoubling(defaults(3.0, 1000), 1e-2), 1e-12);
}

TEST(ProtocolAdvice, AVerySlowRunIsToldItsExpectedCost) {
    ProtocolParameters slow = defaults(1.5, 5000);
    slow.gammaSlow = 1e-4;
    const auto warnings = protocolWarnings(slow);
    ASSERT_EQ(warnings.size(), 2u); // and the rate slower than the default
    EXPECT_NE(warnings[0].find("CPU hours"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("after 40 times that"), std::string::npos) << warnings[0];
    slow.costLimit = 0.0;
    EXPECT_EQ(protocolWarnings(slow)[0].find("cost-limit"), std::string::npos);
}

// Issue 66 item 3: --gamma-slow 1e-3, offered as "a faster slow phase", is faster for spheres
// (default 1e-4) and about six times slower at p = 1.3 (default 6.3e-3).
TEST(ProtocolAdvice, ASlowRateBelowTheDefaultIsToldItsCost) {
    ProtocolParameters superballs = defaults(1.3, 1000);
    superballs.gammaSlow = 1e-3;
    const auto warnings = protocolWarnings(superballs);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("gamma-slow 0.001 is slower than the default for p = 1.3, 0.0063: "
                               "about 6.3 times the slow phase's collisions"),
              std::string::npos)
        << warnings[0];
    ProtocolParameters spheres = defaults(1.0, 1000);
    spheres.gammaSlow = 1e-3;
    EXPECT_TRUE(protocolWarnings(spheres).empty());
    superballs.gammaSlow = defaults(1.3, 1000).slowGrowthRate(); // the default, given
    EXPECT_TRUE(protocolWarnings(superballs).empty());
}

TEST(ProtocolAdvice, SmallBoxesAreWarnedAtEveryP) { // issue 43
    // sbgen --p 1.2 --n 40 --seed 1 jammed a crystal (phi 0.749, Z 10.95; the paper: 0.681, 7.51).
    for (double p : {0.85, 1.0, 1.2, 1.5, 2.0})
        EXPECT_TRUE(mentions(protocolWarnings(defaults(p, 40)), "partly ordered")) << p;
    EXPECT_FALSE(mentions(protocolWarnings(defaults(1.2, 1000)), "partly ordered"));
    // Near-cubes get the more specific column warning instead.
    const auto cubes = protocolWarnings(defaults(10.0, 40));
    EXPECT_TRUE(mentions(cubes, "column"));
    EXPECT_FALSE(mentions(cubes, "partly ordered"));
}

TEST(ProtocolAdvice, NearOctahedraAreToldTheirCost) { // issue 46, defect 12
    // About 200 collisions a second at p = 0.5000001 (bench/RESULTS.md, "Near-octahedra"):
    // a default N = 1000 run takes CPU hours, and says so.
    EXPECT_LT(collisionRate(0.5000001), 300.0);
    EXPECT_TRUE(mentions(protocolWarnings(defaults(0.5000001, 1000)), "CPU hours"));
    EXPECT_GT(collisionRate(0.51), 10.0 * collisionRate(0.5000001));
}

TEST(ProtocolAdvice, FastRatesOutsideThePapersRangeAreNamed) {
    ProtocolParameters fast = defaults(1.5, 1000);
    fast.gammaFast = 0.1;
    EXPECT_TRUE(mentions(protocolWarnings(fast), "above the paper's range"));
    fast.gammaFast = 0.002;
    EXPECT_TRUE(mentions(protocolWarnings(fast), "below the paper's range"));
    fast.gammaFast = 0.05;
    EXPECT_TRUE(protocolWarnings(fast).empty());
}

TEST(ProtocolAdvice, NearCubesInASmallBoxAreWarnedOfAColumnSpanningIt) {
    // N = 200 at p >= 3 formed spanning columns (bench/RESULTS.md, "Near-cubes after the jam
    // check"); N = 1000 and p = 2 at N = 200 jammed.
    EXPECT_TRUE(mentions(protocolWarnings(defaults(10.0, 200)), "column"));
    EXPECT_TRUE(mentions(protocolWarnings(defaults(3.0, 200)), "column"));
    EXPECT_FALSE(mentions(protocolWarnings(defaults(2.0, 200)), "column"));
    EXPECT_FALSE(mentions(protocolWarnings(defaults(3.0, 1000)), "column"));
    EXPECT_TRUE(mentions(protocolWarnings(defaults(100.0, 1000)), "beyond the ensembles measured"));
}

} // namespace
} // namespace sbpack

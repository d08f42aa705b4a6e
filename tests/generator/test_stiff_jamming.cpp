// Near-cubes run to a jam (issue 25): whatever sbgen's protocol declares jammed must have the
// contact network of a jam by an independent count (all pairs, the robust pair solver, no cell
// list, rattlers removed here), and a refusal must name a chain that wraps around the box.
#include "io/packing_io.hpp"
#include "pair/pair_geometry.hpp"
#include "protocol/jamming_protocol.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

namespace sbpack {
namespace {

/// Contacts per particle (all particles) and the rattler fraction (fewer than 4 contacts,
/// removed iteratively) at gap < tolerance D, over every pair by minimum image.
struct Network {
    double contactsPerParticle = 0.0;
    double rattlerFraction = 0.0;
    double smallestGap = INFINITY; ///< in units of D
};

Network countContacts(const Packing& packing, double tolerance) {
    const int n = static_cast<int>(packing.size());
    const double diameter = 2.0 * packing.semiAxis, box = packing.boxLength;
    std::vector<std::vector<int>> neighbours(n);
    Network net;
    int contacts = 0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            Vector3d d = packing.positions[j] - packing.positions[i];
            for (int k = 0; k < 3; ++k)
                d[k] -= box * std::round(d[k] / box);
            if (d.norm() > 2.0 * packing.shape().circumradius() + tolerance * diameter) continue;
            const SuperballPair pair{packing.superball(),
                                     packing.orientations[i].toRotationMatrix(),
                                     packing.orientations[j].toRotationMatrix(), d};
            const double gap = signedDistance(pair).signedDistance / diameter;
            net.smallestGap = std::min(net.smallestGap, gap);
            if (gap >= tolerance) continue;
            ++contacts;
            neighbours[i].push_back(j);
            neighbours[j].push_back(i);
        }
    std::vector<bool> rattler(n, false);
    for (bool changed = true; changed;) {
        changed = false;
        for (int i = 0; i < n; ++i) {
            if (rattler[i]) continue;
            int live = 0;
            for (int j : neighbours[i])
                live += rattler[j] ? 0 : 1;
            if (live < 4) rattler[i] = changed = true;
        }
    }
    int rattlers = 0;
    for (bool r : rattler)
        rattlers += r ? 1 : 0;
    net.contactsPerParticle = 2.0 * contacts / n;
    net.rattlerFraction = static_cast<double>(rattlers) / n;
    return net;
}

class StiffJamming : public ::testing::TestWithParam<double> {};

TEST_P(StiffJamming, AJamHasTheContactsOfOneAndARefusalNamesTheChain) {
    ProtocolParameters parameters;
    parameters.shape = sbpack::ShapeSpec::superball(GetParam());
    parameters.particles = 40;
    parameters.seed = 3;
    parameters.gammaSlow = 1e-2;
    parameters.pressureSwitch = 1e4;
    parameters.pressureFinal = 1e8;
    JammingProtocol run(parameters);
    ASSERT_TRUE(run.run([](const ProtocolStatus&) {}));
    const ProtocolStatus& status = run.status();
    ASSERT_TRUE(status.jam.has_value());
    const Packing packing = run.checkpoint();
    const Network net = countContacts(packing, status.jam->tolerance);
    std::printf("p = %g: %s; P = %.3g, %.2f contacts per particle, rattlers %.3f, smallest gap "
                "%.2g D, %.2f fallbacks per collision\n",
                parameters.shape.superballExponent().value(),
                status.jam->jammed ? "jammed" : "refused", status.reducedPressure,
                net.contactsPerParticle, net.rattlerFraction, net.smallestGap,
                static_cast<double>(status.predictor.distanceFallbacks) /
                    static_cast<double>(status.collisions));
    EXPECT_GT(net.smallestGap, -1e-12); // no overlap
    if (status.jam->jammed) {
        EXPECT_GE(status.reducedPressure, parameters.pressureFinal);
        EXPECT_GE(net.contactsPerParticle, 5.0);
        EXPECT_LE(net.rattlerFraction, 0.1);
    } else {
        ASSERT_TRUE(status.jam->chain.has_value()) << status.jam->verdict;
        EXPECT_NE(status.jam->verdict.find("wraps around the periodic box"), std::string::npos);
    }
}

// With this build p = 2 jams here, and p = 3, 5 and 10 are refused: in a box 3.5 D across a
// column of near-cubes wraps (at p = 10 in seeds 1-6 at N = 40 and 1, 3 at N = 100, 12-23 CPU s
// each), and their cases assert the refusal's chain. Jams of each p are checked at N = 200 and
// 1000 by bench/jamming_stiff.sh (bench/RESULTS.md, "A stalled pressure checks the jam").
INSTANTIATE_TEST_SUITE_P(NearCubes, StiffJamming, ::testing::Values(2.0, 3.0, 5.0, 10.0));

// The checkpoint of a p = 10, N = 200 run (seed 4) whose pressure stalled at ~2e9 for over a
// million collisions on a column of 6 near-cubes wrapping around the box while 95 % of the
// particles collided (bench/RESULTS.md, "A stalled pressure checks the jam"). The subset watch
// cannot see it; the stall watch must end the run, not jammed, naming the chain, within a few
// stall periods (a guard stops the run after 400 windows instead of letting it go on for hours).
TEST(StiffJamming, AStalledPressureOnAWrappingColumnEndsTheRunNotJammed) {
    const std::string file = std::string(SBPACK_DATA_DIR) + "/stalled-column-p10-200.h5";
    JammingProtocol run(readPacking(file), file);
    const std::uint64_t start = run.status().windows;
    StopRequest guard;
    const bool done = run.run(
        [&](const ProtocolStatus& status) {
            if (status.windows - start >= 400) guard.request();
        },
        guard);
    ASSERT_TRUE(done) << "still running at P = " << run.status().reducedPressure;
    const ProtocolStatus& status = run.status();
    EXPECT_LT(status.reducedPressure, run.parameters().pressureFinal);
    ASSERT_TRUE(status.jam.has_value());
    EXPECT_FALSE(status.jam->jammed);
    ASSERT_TRUE(status.jam->chain.has_value()) << status.jam->verdict;
    EXPECT_NE(status.jam->verdict.find("wraps around the periodic box"), std::string::npos);
}

/// One window of the checkpoint of p = 5, N = 1000, seed 2 at its plateau (P about 5e10 after
/// 57.3 M collisions, jammed by the check: bench/RESULTS.md, "p = 5 seed 2 creeps below the final
/// pressure"), edited so that the stall watch checks after it (its 3200th stalled window) and
/// its longest doubling is `longest` windows (and, if given, its switch pressure `pressureSwitch`);
/// returns the resumed run after that window.
JammingProtocol plateauWindow(std::int64_t longest, double pressureSwitch = 1e6) {
    const std::string file = std::string(SBPACK_DATA_DIR) + "/plateau-p5-n1000-s2.h5";
    Packing checkpoint = readPacking(file);
    checkpoint.resumeState["stalled_windows"] = std::int64_t{3199};
    checkpoint.resumeState["longest_doubling"] = longest;
    checkpoint.provenance["pressure_switch"] = pressureSwitch;
    JammingProtocol run(checkpoint, file);
    StopRequest once;
    run.run([&](const ProtocolStatus&) { once.request(); }, once);
    return run;
}

// docs/design.md §3, "Plateaus": a stall four times the run's longest doubling whose check says
// jammed doubles the growth rate, written in the provenance and the growth clock; the same stall
// within four longest doublings, or below the switch pressure, leaves the rate and the files as
// they were.
TEST(StiffJamming, APlateauWhoseCheckSaysJammedDoublesTheGrowthRate) {
    const JammingProtocol raised = plateauWindow(500);
    EXPECT_EQ(raised.status().phase, Phase::Slow);
    EXPECT_EQ(raised.status().stallSpeed, 2.0);
    EXPECT_EQ(raised.status().stall.stalledWindows, 0);
    const Packing written = raised.checkpoint();
    EXPECT_EQ(std::get<double>(written.provenance.at("stall_speed")), 2.0);
    EXPECT_EQ(std::get<double>(written.resumeState.at("growth_rate")), 2.0 * 1e-2);
    EXPECT_EQ(JammingProtocol(written, "raised.h5").status().stallSpeed, 2.0);

    const JammingProtocol kept = plateauWindow(1000); // a plateau only from 4000 windows
    EXPECT_EQ(kept.status().phase, Phase::Slow);
    EXPECT_EQ(kept.status().stallSpeed, 1.0);
    EXPECT_EQ(kept.status().stall.stalledWindows, 3200);
    EXPECT_EQ(kept.checkpoint().provenance.count("stall_speed"), 0u);
    EXPECT_EQ(std::get<double>(kept.checkpoint().resumeState.at("growth_rate")), 1e-2);

    const JammingProtocol below = plateauWindow(500, 5e11); // P about 2.5e10 < 5e11
    EXPECT_EQ(below.status().stallSpeed, 1.0);
    EXPECT_EQ(below.status().stall.stalledWindows, 3200);
}

} // namespace
} // namespace sbpack

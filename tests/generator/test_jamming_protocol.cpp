// The protocol: bad parameters, determinism, and exact checkpoint/resume through the HDF5 file.
#include "io/packing_io.hpp"
#include "protocol/checkpoint_entries.hpp"
#include "protocol/final_packing.hpp"
#include "protocol/jamming_protocol.hpp"
#include "protocol/paper_rates.hpp"
#include "protocol/protocol_advice.hpp"
#include "small_runs.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <limits>
#include <optional>
#include <thread>

namespace sbpack {
namespace {

using testing::smallRun;

/// A small superball run (p = 1.5, rotating engine).
ProtocolParameters smallSuperballRun(std::uint64_t seed) {
    ProtocolParameters p = smallRun(seed);
    p.particles = 27;
    p.shape = sbpack::ShapeSpec::superball(1.5);
    p.pressureSwitch = 1e2;
    p.pressureFinal = 1e4;
    return p;
}

void expectIdentical(const Packing& a, const Packing& b) {
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a.semiAxis, b.semiAxis);
    EXPECT_EQ(*a.reducedPressure, *b.reducedPressure);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.positions[i], b.positions[i]) << i;
        EXPECT_EQ(a.velocities[i], b.velocities[i]) << i;
        EXPECT_EQ(a.orientations[i].coeffs(), b.orientations[i].coeffs()) << i;
    }
    EXPECT_EQ(a.angularVelocities, b.angularVelocities);
    ASSERT_EQ(a.pairRecords.size(), b.pairRecords.size());
    for (std::size_t k = 0; k < a.pairRecords.size(); ++k) // NaN: an angle without a witness
        EXPECT_TRUE(a.pairRecords[k] == b.pairRecords[k] ||
                    (std::isnan(a.pairRecords[k]) && std::isnan(b.pairRecords[k])))
            << k;
    for (const auto& [key, value] : a.provenance)
        if (key != "wall_time_s" && key != "cpu_time_s") {
            EXPECT_EQ(value, b.provenance.at(key)) << key;
        }
}

/// The protocol resumed from `checkpoint` through a file, as sbgen --resume reads it (`name` in
/// the temporary folder, removed after).
JammingProtocol resumedThroughAFile(const Packing& checkpoint, const std::string& name) {
    const auto file = std::filesystem::temp_directory_path() / name;
    writePacking(checkpoint, file); // validated on the way
    JammingProtocol resumed(readPacking(file), file.string());
    std::filesystem::remove(file);
    return resumed;
}

TEST(JammingProtocol, RejectsBadParametersNamingTheParameter) {
    const auto expectBad = [](auto change, const char* option) {
        ProtocolParameters p;
        change(p);
        try {
            p.validate();
            ADD_FAILURE() << option << " accepted";
        } catch (const ProtocolParameterError& e) {
            EXPECT_EQ(e.parameter(), option) << e.what();
        }
    };
    expectBad([](auto& p) { p.particles = 1; }, "n_particles");
    expectBad([](auto& p) { p.shape = sbpack::ShapeSpec::superball(0.49); }, "p");
    expectBad([](auto& p) { p.shape = sbpack::ShapeSpec::superball(NAN); }, "p");
    expectBad([](auto& p) { p.phiInit = 0.5; }, "phi_init");
    expectBad([](auto& p) { p.phiInit = 0.0; }, "phi_init");
    expectBad([](auto& p) { p.phiInit = 1e-300; }, "phi_init"); // once wrote L = 2.2e100
    expectBad([](auto& p) { p.phiInit = std::nextafter(1e-3, 0.0); }, "phi_init");
    expectBad([](auto& p) { p.gammaFast = -0.01; }, "gamma_fast");
    expectBad([](auto& p) { p.gammaSlow = NAN; }, "gamma_slow");
    expectBad([](auto& p) { p.pressureSwitch = INFINITY; }, "pressure_switch");
    expectBad([](auto& p) { p.pressureFinal = p.pressureSwitch; }, "pressure_final");
    expectBad([](auto& p) { p.collisionsPerWindow = 1e30; }, "collisions_per_window");
    expectBad([](auto& p) { p.collisionsPerWindow = 1e-4; }, "collisions_per_window");
    expectBad([](auto& p) { p.costLimit = -1.0; }, "cost_limit");
    expectBad([](auto& p) { p.costLimit = NAN; }, "cost_limit");
    expectBad([](auto& p) { p.speed = 0.5; }, "speed"); // slower than the paper: --gamma-slow
    expectBad([](auto& p) { p.speed = NAN; }, "speed");
    expectBad([](auto& p) { p.speed = 2e3; }, "speed");
    expectBad(
        [](auto& p) {
            p.speed = 10.0;
            p.gammaSlow = 1e-3;
        },
        "speed");
    expectBad([](auto& p) { p.pressureFinish = 1e5; }, "pressure_finish");  // below the switch
    expectBad([](auto& p) { p.pressureFinish = 1e12; }, "pressure_finish"); // at the final
    expectBad([](auto& p) { p.pressureFinish = NAN; }, "pressure_finish");
    expectBad([](auto& p) { p.finishSpeed = 10.0; }, "finish_speed"); // no pressure_finish
    expectBad(
        [](auto& p) {
            p.pressureFinish = 1e8;
            p.finishSpeed = 0.5;
        },
        "finish_speed");
}

TEST(JammingProtocol, SameSeedGivesIdenticalPacking) {
    JammingProtocol a(smallRun(5)), b(smallRun(5)), c(smallRun(6));
    ASSERT_TRUE(a.run([](const ProtocolStatus&) {}));
    ASSERT_TRUE(b.run([](const ProtocolStatus&) {}));
    ASSERT_TRUE(c.run([](const ProtocolStatus&) {}));
    expectIdentical(a.checkpoint(), b.checkpoint());
    EXPECT_NE(a.checkpoint().positions[0], c.checkpoint().positions[0]);
    EXPECT_GE(a.status().reducedPressure, 1e7);
}

TEST(JammingProtocol, ResumingFromACheckpointFileGivesTheUninterruptedResult) {
    JammingProtocol uninterrupted(smallRun(9));
    std::optional<Packing> saved;
    ASSERT_TRUE(uninterrupted.run([&](const ProtocolStatus& s) {
        if (s.windows == 40) saved = uninterrupted.checkpoint();
    }));
    ASSERT_TRUE(saved.has_value());
    JammingProtocol resumed = resumedThroughAFile(*saved, "sbgen-test-checkpoint.h5");
    EXPECT_EQ(resumed.status().windows, 40u);
    ASSERT_TRUE(resumed.run([](const ProtocolStatus&) {}));
    expectIdentical(uninterrupted.checkpoint(), resumed.checkpoint());
}

TEST(JammingProtocol, AStopRequestEndsTheWindowAndResumesExactly) {
    // A stop (SIGINT or SIGTERM in sbgen) raised mid-window takes effect at the window's end, so
    // the checkpoint written then resumes bit for bit (p = 1.5: the rotating engine).
    ProtocolParameters parameters = smallRun(11);
    parameters.particles = 27;
    parameters.shape = sbpack::ShapeSpec::superball(1.5);
    parameters.pressureSwitch = 1e2;
    parameters.pressureFinal = 1e4;
    JammingProtocol uninterrupted(parameters);
    ASSERT_TRUE(uninterrupted.run([](const ProtocolStatus&) {}));
    StopRequest stop;
    JammingProtocol stopped(parameters);
    ASSERT_FALSE(stopped.run(
        [&](const ProtocolStatus& s) {
            if (s.windows == 25) stop.request(SIGINT); // as the handler would, between two events
        },
        stop));
    EXPECT_EQ(stop.signal(), SIGINT);
    EXPECT_EQ(stopped.status().windows, 25u);
    JammingProtocol resumed = resumedThroughAFile(stopped.checkpoint(), "sbgen-test-stop.h5");
    ASSERT_TRUE(resumed.run([](const ProtocolStatus&) {}));
    expectIdentical(uninterrupted.checkpoint(), resumed.checkpoint());
}

// A repeated request stops the window at its next event: nothing runs after the window in
// which both came (sbgen's second SIGTERM).
TEST(JammingProtocol, ARepeatedStopRequestEndsTheRunAtItsNextEvent) {
    ProtocolParameters parameters = smallRun(11);
    parameters.particles = 27;
    StopRequest stop;
    std::uint64_t collisionsThen = 0;
    JammingProtocol stopped(parameters);
    ASSERT_FALSE(stopped.run(
        [&](const ProtocolStatus& s) {
            if (s.windows != 5) return;
            collisionsThen = s.collisions;
            stop.request(SIGTERM);
            stop.request(SIGTERM);
        },
        stop));
    EXPECT_TRUE(stop.repeated());
    EXPECT_EQ(stopped.status().windows, 5u);
    EXPECT_EQ(stopped.status().collisions, collisionsThen);
}

// Issue 65 item 3: a second request midway through a window (sbgen's second SIGTERM, sent here
// from another thread as the handler would) stops the run at its next event, and the state kept
// at that window's start resumes bit for bit (a mid-window checkpoint did not).
TEST(JammingProtocol, ARepeatedStopMidWindowResumesFromTheWindowStartBitForBit) {
    ProtocolParameters parameters = smallSuperballRun(5);
    parameters.collisionsPerWindow = 2000; // 54000 collisions: the requests land midway
    JammingProtocol uninterrupted(parameters);
    ASSERT_TRUE(uninterrupted.run([](const ProtocolStatus&) {}));
    StopRequest stop;
    std::atomic<bool> third{false};
    std::thread signaller([&] {
        while (!third.load())
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        stop.request(SIGTERM);
        stop.request(SIGTERM);
    });
    JammingProtocol stopped(parameters);
    const bool done = stopped.run(
        [&](const ProtocolStatus& s) {
            if (s.windows == 3) third.store(true);
        },
        stop);
    signaller.join();
    ASSERT_FALSE(done);
    const std::optional<Packing> resume = stopped.resumeCheckpoint();
    ASSERT_TRUE(resume.has_value());
    const std::uint64_t kept = readCheckpoint(*resume, "resume").status.collisions;
    EXPECT_GT(stopped.status().collisions, kept) << "the requests landed between two windows";
    EXPECT_LT(stopped.status().collisions - kept, 54000u);
    JammingProtocol resumed = resumedThroughAFile(*resume, "sbgen-test-mid-window.h5");
    ASSERT_TRUE(resumed.run([](const ProtocolStatus&) {}));
    expectIdentical(uninterrupted.checkpoint(), resumed.checkpoint());
}

// Issue 65 item 3: both signals before the first window ends (sbgen's double SIGTERM during
// its start): no pressure is measured yet, and the checkpoint must still be a valid packing
// (none recorded, not 0) that resumes and jams.
TEST(JammingProtocol, ARepeatedStopBeforeTheFirstWindowLeavesAResumableCheckpoint) {
    for (const double p : {1.0, 1.5}) {
        ProtocolParameters parameters = smallRun(11);
        parameters.particles = 27;
        parameters.shape = sbpack::ShapeSpec::superball(p);
        StopRequest stop;
        stop.request(SIGTERM);
        stop.request(SIGTERM);
        JammingProtocol stopped(parameters);
        ASSERT_FALSE(stopped.run([](const ProtocolStatus&) {}, stop));
        EXPECT_EQ(stopped.status().windows, 0u);
        EXPECT_FALSE(stopped.resumeCheckpoint().has_value()); // sbgen writes nothing
        const Packing checkpoint = stopped.checkpoint();
        EXPECT_FALSE(checkpoint.reducedPressure.has_value());
        JammingProtocol resumed = resumedThroughAFile(checkpoint, "sbgen-test-first-window.h5");
        ASSERT_TRUE(resumed.run([](const ProtocolStatus&) {})) << "p = " << p;
        EXPECT_GE(resumed.status().reducedPressure, parameters.pressureFinal);
    }
}

TEST(JammingProtocol, SuperballRunsAreDeterministicAndResumeExactly) {
    JammingProtocol uninterrupted(smallSuperballRun(4));
    std::optional<Packing> saved;
    ASSERT_TRUE(uninterrupted.run([&](const ProtocolStatus& s) {
        if (s.windows == 20) saved = uninterrupted.checkpoint();
    }));
    ASSERT_TRUE(saved.has_value());
    // The pair records survive the window's end (the normals and witnesses in flight) and must
    // resume with the particles (issue 40).
    EXPECT_GT(saved->pairRecords.size(), kPairRecordColumns * saved->size());
    EXPECT_GE(uninterrupted.status().reducedPressure, 1e4);
    JammingProtocol resumed = resumedThroughAFile(*saved, "sbgen-test-superball-checkpoint.h5");
    ASSERT_TRUE(resumed.run([](const ProtocolStatus&) {}));
    expectIdentical(uninterrupted.checkpoint(), resumed.checkpoint());
    JammingProtocol again(smallSuperballRun(4));
    ASSERT_TRUE(again.run([](const ProtocolStatus&) {}));
    expectIdentical(uninterrupted.checkpoint(), again.checkpoint());
}

TEST(JammingProtocol, AFinishedRunContinuesToAHigherFinalPressure) {
    JammingProtocol run(smallRun(3));
    ASSERT_TRUE(run.run([](const ProtocolStatus&) {}));
    JammingProtocol more(run.checkpoint(), "memory");
    more.setPressureFinal(1e9);
    ASSERT_TRUE(more.run([](const ProtocolStatus&) {}));
    EXPECT_GE(more.status().reducedPressure, 1e9);
    EXPECT_GT(more.status().collisions, run.status().collisions);
}

TEST(JammingProtocol, ARunStopsAtItsCostLimitNotJammedAndGoesOnWithALargerOne) {
    // The limit is costLimit times expectedCost's collisions (docs/design.md §3, "Cost limit");
    // set here to stop halfway. The output says why, keeps its phase, and resumes bit for bit.
    ProtocolParameters parameters = smallSuperballRun(4);
    parameters.costLimit = 0.0;
    JammingProtocol uninterrupted(parameters);
    ASSERT_TRUE(uninterrupted.run([](const ProtocolStatus&) {}));
    const double all = static_cast<double>(uninterrupted.status().collisions);
    parameters.costLimit = 0.5 * all / expectedCost(parameters).collisions;
    JammingProtocol limited(parameters);
    ASSERT_TRUE(limited.run([](const ProtocolStatus&) {}));
    const ProtocolStatus& s = limited.status();
    EXPECT_NE(s.phase, Phase::Done);
    EXPECT_GE(s.collisions, parameters.collisionLimit());
    EXPECT_LT(static_cast<double>(s.collisions), all);
    EXPECT_LT(s.reducedPressure, parameters.pressureFinal);
    ASSERT_TRUE(s.jam.has_value());
    EXPECT_FALSE(s.jam->jammed);
    EXPECT_NE(s.jam->verdict.find("cost limit"), std::string::npos) << s.jam->verdict;

    const auto file = std::filesystem::temp_directory_path() / "sbgen-test-cost-limit.h5";
    writePacking(finalPacking(limited), file);
    const Packing written = readPacking(file);
    std::filesystem::remove(file);
    EXPECT_EQ(written.provenance.at("jammed"), ProvenanceValue(std::int64_t{0}));
    JammingProtocol same(written, "memory"); // the same limit: stops before any window
    ASSERT_TRUE(same.run([](const ProtocolStatus&) {}));
    EXPECT_EQ(same.status().collisions, s.collisions);
    JammingProtocol resumed(written, "memory");
    resumed.setCostLimit(0.0);
    ASSERT_TRUE(resumed.run([](const ProtocolStatus&) {}));
    EXPECT_TRUE(resumed.status().jam->jammed);
    expectIdentical(uninterrupted.checkpoint(), resumed.checkpoint());
}

TEST(JammingProtocol, RefusesToResumeFromOverlappingParticles) {
    JammingProtocol run(smallRun(3));
    ASSERT_TRUE(run.run([](const ProtocolStatus&) {}));
    Packing overlapping = run.checkpoint();
    overlapping.positions[1] = overlapping.positions[0] + Vector3d(0.1, 0.0, 0.0);
    try {
        JammingProtocol resumed(overlapping, "tampered.h5");
        ADD_FAILURE() << "resumed from overlapping particles";
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("tampered.h5': "), std::string::npos) << message;
        EXPECT_NE(message.find("overlapping pair(s), the worst (0, 1) by "), std::string::npos)
            << message;
    }
}

TEST(JammingProtocol, APackingWithoutGeneratorStateIsNotACheckpoint) {
    Packing plain;
    plain.positions = {{0.1, 0.1, 0.1}, {0.6, 0.6, 0.6}};
    plain.orientations.assign(2, Quaterniond::Identity());
    plain.velocities.assign(2, Vector3d::Zero());
    plain.semiAxis = 0.1;
    try {
        JammingProtocol(plain, "plain.h5");
        FAIL() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("plain.h5': not an sbgen checkpoint"),
                  std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace sbpack

namespace sbpack {
namespace {

// The protocol's defaults (issue 18): the switch happens when two windows in a row reach 1e6,
// and the slow rate actually used is slowGrowthRate()'s default for p, unless set.
TEST(JammingProtocol, DefaultsSwitchAtTheirPressureAndUseTheSlowRateOfTheirShape) {
    ProtocolParameters spheres;
    EXPECT_EQ(spheres.slowGrowthRate(), 1e-4);
    spheres.gammaSlow = 3e-3;
    EXPECT_EQ(spheres.slowGrowthRate(), 3e-3);

    ProtocolParameters superballs; // every default but the size and the end
    superballs.shape = sbpack::ShapeSpec::superball(1.5);
    superballs.particles = 27;
    superballs.pressureFinal = 1e7;
    EXPECT_EQ(superballs.slowGrowthRate(), paperSlowRate(1.5));
    JammingProtocol protocol(superballs);
    std::vector<std::pair<Phase, double>> windows; // phase after each window, and its pressure
    ASSERT_TRUE(protocol.run([&](const ProtocolStatus& s) {
        windows.emplace_back(s.phase, s.reducedPressure);
        // The rate the engine grows at from here: the paper's fast rate, then the slow one.
        const double rate = std::get<double>(protocol.checkpoint().resumeState.at("growth_rate"));
        EXPECT_EQ(rate, s.phase == Phase::Fast ? paperFastRate(1.5) : paperSlowRate(1.5))
            << windows.size();
    }));
    std::size_t first = 0;
    while (first < windows.size() && windows[first].first == Phase::Fast)
        ++first;
    ASSERT_GE(first, 1u);
    ASSERT_LT(first, windows.size());
    EXPECT_GE(windows[first].second, 1e6); // the switch pressure, two windows in a row
    EXPECT_GE(windows[first - 1].second, 1e6);
    for (std::size_t k = 0; k + 1 < first; ++k) // not earlier
        EXPECT_FALSE(windows[k].second >= 1e6 && windows[k + 1].second >= 1e6) << k;
    const Packing out = protocol.checkpoint();
    EXPECT_EQ(std::get<double>(out.provenance.at("gamma_fast")), paperFastRate(1.5));
    EXPECT_EQ(std::get<double>(out.provenance.at("gamma_slow")), paperSlowRate(1.5));
    EXPECT_EQ(std::get<double>(out.resumeState.at("growth_rate")), paperSlowRate(1.5)); // in use
}

// The default rates (issue 18) are the measured tables': at each of the paper's p values from
// 0.85 to 1.5 the fast rate in its range (0.005, 0.05) that gives its phi and the slow rate that
// gives its Z (of the order of its "gamma ~ 0.001"), linear in between, the end values outside;
// spheres keep 1e-4; an explicit rate wins.
void expectAMeasuredTable(const std::vector<MeasuredAtP>& table, double (*rate)(double), double low,
                          double high) {
    ASSERT_GE(table.size(), 2U);
    EXPECT_EQ(table.front().p, 0.85);
    EXPECT_EQ(table.back().p, 1.5);
    for (std::size_t k = 0; k < table.size(); ++k) {
        EXPECT_EQ(rate(table[k].p), table[k].value) << table[k].p;
        EXPECT_GT(table[k].value, low) << table[k].p;
        EXPECT_LE(table[k].value, high) << table[k].p;
        if (k + 1 == table.size()) continue;
        EXPECT_LT(table[k].p, table[k + 1].p);
        EXPECT_NEAR(rate(0.5 * (table[k].p + table[k + 1].p)),
                    0.5 * (table[k].value + table[k + 1].value), 1e-15);
    }
    EXPECT_EQ(rate(0.6), table.front().value);
    EXPECT_EQ(rate(10.0), table.back().value);
}

TEST(JammingProtocol, TheDefaultRatesAreTheMeasuredPaperRatesOfTheirP) {
    expectAMeasuredTable(paperFastRates(), paperFastRate, 0.005, 0.05);
    expectAMeasuredTable(paperSlowRates(), paperSlowRate, 1e-3, 1e-2);
    for (const MeasuredAtP& r : paperSlowRates()) // slower than the fast phase at every p
        EXPECT_LT(r.value, paperFastRate(r.p)) << r.p;

    ProtocolParameters spheres;
    EXPECT_EQ(spheres.fastGrowthRate(), paperFastRate(1.0));
    EXPECT_EQ(spheres.slowGrowthRate(), 1e-4);
    spheres.gammaFast = 0.05;
    EXPECT_EQ(spheres.fastGrowthRate(), 0.05);
    ProtocolParameters superballs;
    superballs.shape = sbpack::ShapeSpec::superball(1.1);
    EXPECT_EQ(superballs.slowGrowthRate(), paperSlowRate(1.1));
    superballs.gammaSlow = 2e-3;
    EXPECT_EQ(superballs.slowGrowthRate(), 2e-3);
}

// Issue 66 item 3: the speed knob scales the default slow rate for every p, and the slow phase's
// expected collisions by its inverse (docs/design.md §3, "Speed" and "Expected cost").
TEST(JammingProtocol, TheSpeedKnobScalesTheDefaultSlowRateForEveryP) {
    for (const double p : {1.0, 1.3, 3.0}) {
        ProtocolParameters paper, faster;
        paper.shape = faster.shape = sbpack::ShapeSpec::superball(p);
        faster.speed = 10.0;
        EXPECT_DOUBLE_EQ(faster.slowGrowthRate(), 10.0 * paper.slowGrowthRate()) << p;
        EXPECT_EQ(faster.fastGrowthRate(), paper.fastGrowthRate()) << p;
        // Collisions: the same fast phase, a tenth of the slow phase's.
        ProtocolParameters fastOnly = paper;
        fastOnly.pressureFinal = std::nextafter(paper.pressureSwitch, INFINITY);
        const double fast = expectedCost(fastOnly).collisions;
        EXPECT_NEAR(expectedCost(faster).collisions - fast,
                    (expectedCost(paper).collisions - fast) / 10.0,
                    1e-9 * expectedCost(paper).collisions)
            << p;
    }
    ProtocolParameters spheres;
    spheres.speed = 10.0;
    EXPECT_EQ(spheres.slowGrowthRate(), 1e-3); // the demo's --speed 10 is its old --gamma-slow 1e-3
}

// Issue 64: the finish grows finishSpeed times faster than the slow rate from pressureFinish on
// (the engine's rate checked after every window), costs fewer collisions than the slow rate to
// the end, is written with the packing (and only by a run that has one) and may be given to a
// finished run that continues, as sbgen --resume takes it.
TEST(JammingProtocol, TheFinishGrowsFasterFromItsPressureOn) {
    ProtocolParameters parameters = smallRun(7);
    parameters.pressureFinish = 1e5;
    parameters.finishSpeed = 10.0;
    JammingProtocol protocol(parameters);
    bool finished = false;
    ASSERT_TRUE(protocol.run([&](const ProtocolStatus& s) {
        const double rate = std::get<double>(protocol.checkpoint().resumeState.at("growth_rate"));
        if (rate == 0.1 && !finished) { // the finish begins where this window reached 1e5
            finished = true;
            EXPECT_GE(s.reducedPressure, 1e5);
        }
        EXPECT_EQ(rate, s.phase == Phase::Fast ? 0.05 : finished ? 0.1 : 0.01) << s.windows;
    }));
    EXPECT_TRUE(finished);
    JammingProtocol paper(smallRun(7));
    ASSERT_TRUE(paper.run([](const ProtocolStatus&) {}));
    EXPECT_LT(protocol.status().collisions, paper.status().collisions);
    EXPECT_GE(protocol.status().reducedPressure, 1e7);
    const Packing out = protocol.checkpoint();
    EXPECT_EQ(std::get<double>(out.provenance.at("pressure_finish")), 1e5);
    EXPECT_EQ(std::get<double>(out.provenance.at("finish_speed")), 10.0);
    EXPECT_EQ(paper.checkpoint().provenance.count("pressure_finish"), 0u);
    EXPECT_EQ(paper.checkpoint().provenance.count("finish_speed"), 0u);
    JammingProtocol resumed = resumedThroughAFile(out, "sbgen-test-finish.h5");
    EXPECT_EQ(resumed.parameters().pressureFinish, 1e5);
    EXPECT_EQ(resumed.parameters().finishSpeed, 10.0);

    // A run of the paper's protocol stopped at 1e5 and continued with the finish from there.
    ProtocolParameters early = smallRun(7);
    early.pressureFinal = 1e5;
    JammingProtocol first(early);
    ASSERT_TRUE(first.run([](const ProtocolStatus&) {}));
    JammingProtocol more(first.checkpoint(), "memory");
    more.setPressureFinal(1e7);
    EXPECT_THROW(more.setFinish(1e8, 10.0), ProtocolParameterError); // past the final pressure
    more.setFinish(1e5, 10.0);
    ASSERT_TRUE(more.run([](const ProtocolStatus&) {}));
    EXPECT_EQ(std::get<double>(more.checkpoint().resumeState.at("growth_rate")), 0.1);
    EXPECT_LT(more.status().collisions, paper.status().collisions);
}

// The expected cost counts the finish's decades at its own rate.
TEST(JammingProtocol, TheExpectedCostOfAFinishCountsItsDecadesAtItsRate) {
    ProtocolParameters paper, finish;
    finish.pressureFinish = 1e8; // 2 of the 6 slow decades at the slow rate, 4 at 100 times it
    finish.finishSpeed = 100.0;
    ProtocolParameters fastOnly = paper;
    fastOnly.pressureFinal = std::nextafter(paper.pressureSwitch, INFINITY);
    const double fast = expectedCost(fastOnly).collisions;
    const double slow = expectedCost(paper).collisions - fast;
    EXPECT_NEAR(expectedCost(finish).collisions - fast, slow * (2.0 + 4.0 / 100.0) / 6.0,
                1e-9 * slow);
}

// A checkpoint whose engine state was tampered with is refused, naming it (issue 20, defect 7).
TEST(JammingProtocol, RefusesATamperedGrowthClock) {
    JammingProtocol run(smallRun(3));
    run.run([](const ProtocolStatus&) {});
    const Packing good = run.checkpoint();
    const auto refused = [&](auto edit, const std::string& words) {
        Packing bad = good;
        edit(bad);
        try {
            JammingProtocol resumed(bad, "bad.h5");
            ADD_FAILURE() << "accepted: " << words;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    refused([](Packing& p) { p.resumeState["growth_rate"] = -0.01; },
            "'bad.h5': checkpoint state growth_rate must be positive");
    refused([](Packing& p) { p.resumeState["base_diameter"] = 0.0; },
            "base_diameter must be positive");
    refused([](Packing& p) { p.semiAxis *= 0.99; }, "not 2 semi_axis");
    EXPECT_NO_THROW(JammingProtocol(good, "good.h5"));
}

// Pair records that cannot be the engine's are refused, naming the row (issue 40).
TEST(JammingProtocol, RefusesTamperedPairRecords) {
    JammingProtocol run(smallSuperballRun(4));
    run.run([](const ProtocolStatus&) {});
    const Packing good = run.checkpoint();
    ASSERT_GT(good.pairRecords.size(), kPairRecordColumns);
    const auto refused = [&](std::size_t column, double value, const std::string& words) {
        Packing bad = good;
        bad.pairRecords[kPairRecordColumns + column] = value;
        try {
            JammingProtocol resumed(bad, "bad.h5");
            ADD_FAILURE() << "accepted: " << words;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    refused(1, static_cast<double>(good.size()), "pair_records row 1: the particles must be");
    refused(0, 0.5, "row 1: the particles must be indices");
    refused(2, std::numeric_limits<double>::infinity(), "row 1: normal and points must be finite");
    refused(2, 7.0, "row 1: the normal must be a unit vector or zero");
    EXPECT_NO_THROW(JammingProtocol(good, "good.h5"));
}

} // namespace
} // namespace sbpack

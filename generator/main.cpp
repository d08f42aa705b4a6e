// sbgen: serial generator of MRJ packings (Donev-Torquato-Stillinger event-driven MD).
#include "cli/options.hpp"
#include "io/atomic_file.hpp"
#include "io/packing_io.hpp"
#include "io/read_guard.hpp"
#include "order/order_metrics.hpp"
#include "protocol/checkpoint_entries.hpp"
#include "protocol/final_packing.hpp"
#include "protocol/jamming_protocol.hpp"
#include "protocol/protocol_advice.hpp"
#include "version.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>

namespace {

/// Exit status of a run whose output fails the jam check (docs/design.md §3).
constexpr int kNotJammed = 3;

const char* phaseName(sbpack::Phase phase) {
    switch (phase) {
    case sbpack::Phase::Fast:
        return "fast";
    case sbpack::Phase::Slow:
        return "slow";
    case sbpack::Phase::Done:
        return "done";
    }
    return "?";
}

void printProgress(const sbpack::ProtocolStatus& s, double runSeconds,
                   std::uint64_t runCollisions) {
    std::fprintf(stderr, "sbgen: %s  phi %.6f  P %.3e  collisions %.4g  (%.3g M/s)  wall %.1f s",
                 phaseName(s.phase), s.packingFraction, s.reducedPressure,
                 static_cast<double>(s.collisions),
                 runSeconds > 0.0 ? runCollisions / runSeconds * 1e-6 : 0.0, s.wallSeconds);
    // docs/design.md §3, "Plateaus"
    if (s.stallSpeed > 1.0) std::fprintf(stderr, "  (growth x%g at a plateau)", s.stallSpeed);
    std::fputc('\n', stderr);
}

std::filesystem::path interruptCheckpointPath(const sbpack::GeneratorOptions& o) {
    if (o.checkpoint) return *o.checkpoint;
    std::filesystem::path path = o.out;
    return path.replace_extension(".checkpoint.h5");
}

/// A resumed run's changes (--pressure-final, --cost-limit, --pressure-finish, --finish-speed),
/// each refusal named by its option.
void applyResumeOptions(sbpack::JammingProtocol& protocol, const sbpack::GeneratorOptions& o) {
    try {
        if (o.pressureFinal) protocol.setPressureFinal(*o.pressureFinal);
        if (o.costLimit) protocol.setCostLimit(*o.costLimit);
        if (o.pressureFinish || o.finishSpeed)
            protocol.setFinish(o.pressureFinish.value_or(protocol.parameters().pressureFinish),
                               o.finishSpeed.value_or(protocol.parameters().finishSpeed));
    } catch (const sbpack::ProtocolParameterError& e) {
        throw sbpack::optionError(e);
    }
}

/// The protocol of the options, or of the file resumed (with the changes a resume may make);
/// its warnings printed.
sbpack::JammingProtocol startProtocol(const sbpack::GeneratorOptions& o,
                                      const sbpack::PlacementWatch& placed) {
    sbpack::JammingProtocol protocol =
        o.resume ? sbpack::JammingProtocol(sbpack::readPacking(*o.resume), o.resume->string())
                 : sbpack::JammingProtocol(o.protocol, placed);
    if (o.resume) applyResumeOptions(protocol, o);
    for (const std::string& warning : sbpack::protocolWarnings(protocol.parameters()))
        std::cerr << "sbgen: warning: " << warning << '\n';
    return protocol;
}

/// From this N on, sbgen says it is setting up and how far it is (the random start takes about
/// 30 s at N = 1e6 and p = 1.5, 2 s for spheres).
constexpr int kLargeSetup = 100000;

/// The random start's watch: stops it on a signal (nothing to keep yet) and, at large N, prints
/// the count placed every 2 s (issue 65 item 3).
sbpack::PlacementWatch setupWatch(const sbpack::GeneratorOptions& o,
                                  const sbpack::StopRequest& stop) {
    const bool report = !o.quiet && o.protocol.particles >= kLargeSetup;
    auto last = std::chrono::steady_clock::now();
    return [&stop, report, last, n = o.protocol.particles](int placed) mutable {
        if (stop.requested()) return false;
        const auto now = std::chrono::steady_clock::now();
        if (report && now - last > std::chrono::seconds(2)) {
            std::fprintf(stderr, "sbgen: setting up: %d of %d particles placed\n", placed, n);
            last = now;
        }
        return true;
    };
}

/// A signal before the first window ended: nothing to keep (issue 65 item 3).
int stoppedBeforeAState(const sbpack::StopRequest& stop) {
    std::cerr << "sbgen: stopped by signal " << stop.signal()
              << " before the first window ended: no state to keep, nothing written (a new run "
                 "starts from the beginning)\n";
    return 128 + stop.signal();
}

/// A run stopped by a signal: its checkpoint at the end of the last window completed, which
/// resumes bit for bit (after a second signal, the end of the window before: issue 65 item 3).
int writeStopCheckpoint(const sbpack::GeneratorOptions& o, const sbpack::JammingProtocol& protocol,
                        const sbpack::StopRequest& stop) {
    const std::optional<sbpack::Packing> checkpoint = protocol.resumeCheckpoint();
    if (!checkpoint) return stoppedBeforeAState(stop);
    const std::filesystem::path path = interruptCheckpointPath(o);
    sbpack::writePacking(*checkpoint, path);
    const std::uint64_t lost = protocol.status().collisions -
                               sbpack::readCheckpoint(*checkpoint, path.string()).status.collisions;
    std::cerr << "sbgen: stopped by signal " << stop.signal();
    if (lost > 0)
        std::cerr << " twice, midway through a window: the checkpoint is the window's start ("
                  << lost << " collisions back)";
    else
        std::cerr << " at the end of a window";
    std::cerr << "; it resumes bit for bit; written to " << path.string()
              << " (continue with --resume " << path.string() << ")\n";
    return 128 + stop.signal();
}

int generate(const sbpack::GeneratorOptions& o) {
    using Clock = std::chrono::steady_clock;
    // Installed first: a signal during the set-up stops the run after its first window. The
    // first SIGINT or SIGTERM stops the run at the end of its window (an exact checkpoint); a
    // second one stops it at its next event (common/stop/stop_request.hpp).
    sbpack::installStopHandler();
    const sbpack::StopRequest& stop = sbpack::processStopRequest();
    // No other run may write this run's output or checkpoint while it lasts (io/atomic_file.hpp).
    const sbpack::OutputLock outputLock(o.out), checkpointLock(interruptCheckpointPath(o));
    if (!o.quiet && !o.resume && o.protocol.particles >= kLargeSetup)
        std::cerr << "sbgen: setting up " << o.protocol.particles
                  << " particles (the random start and its event lists)\n";
    std::optional<sbpack::JammingProtocol> started;
    try {
        started.emplace(startProtocol(o, setupWatch(o, stop)));
    } catch (const sbpack::PlacementStopped&) {
        return stoppedBeforeAState(stop);
    }
    sbpack::JammingProtocol& protocol = *started;
    if (stop.requested() && protocol.status().windows == 0) return stoppedBeforeAState(stop);

    const auto start = Clock::now();
    auto lastProgress = start, lastCheckpoint = start;
    const std::uint64_t startCollisions = protocol.status().collisions;
    const bool done = protocol.run(
        [&](const sbpack::ProtocolStatus& s) {
            const auto now = Clock::now();
            if (!o.quiet &&
                (now - lastProgress > std::chrono::seconds(2) || s.phase == sbpack::Phase::Done)) {
                printProgress(s, std::chrono::duration<double>(now - start).count(),
                              s.collisions - startCollisions);
                lastProgress = now;
            }
            if (o.checkpoint && std::chrono::duration<double>(now - lastCheckpoint).count() >=
                                    o.checkpointInterval) {
                sbpack::writePacking(protocol.checkpoint(), *o.checkpoint);
                lastCheckpoint = now;
            }
        },
        stop);
    if (!done) return writeStopCheckpoint(o, protocol, stop);
    const sbpack::Packing packing = sbpack::finalPacking(protocol);
    sbpack::writePacking(packing, o.out);
    if (!o.quiet)
        std::fprintf(stderr,
                     "sbgen: wrote %s: phi %.6f  P %.3e  Z %.4f  phi_R %.4f  (contacts: gap < "
                     "%.0e D)\n",
                     o.out.c_str(), packing.packingFraction(), *packing.reducedPressure,
                     std::get<double>(packing.provenance.at("z_mean")),
                     std::get<double>(packing.provenance.at("rattler_fraction")),
                     std::get<double>(packing.provenance.at("contact_tolerance")));
    if (const sbpack::OrderVerdict order = sbpack::orderVerdict(sbpack::measureOrder(packing));
        order.ordered)
        std::cerr << "sbgen: warning: " << o.out.string() << " has ordered (" << order.reason
                  << "; docs/order-metrics.md §5): jammed or not, it is not MRJ\n";
    const sbpack::JamCheck& jam = *protocol.status().jam;
    if (jam.jammed) {
        // The jam check tests local jamming of translations only (docs/jamming.md §1); sbgen
        // links no LP solver, so the categories with rotations are sbanalyze's to test.
        if (!o.quiet && packing.isMixture())
            std::fprintf(stderr,
                         "sbgen: %s; the jamming categories: sbanalyze info --jamming %s "
                         "(docs/mixtures.md)\n",
                         jam.verdict.c_str(), o.out.c_str());
        else if (!o.quiet)
            std::fprintf(stderr,
                         "sbgen: jammed by the jam check (translations: %.1f %% of the particles "
                         "rattlers or free, at most %.0f %%); the jamming categories, rotations "
                         "included: sbanalyze info --jamming %s (docs/jamming.md §7)\n",
                         100.0 * jam.untrappedFraction,
                         100.0 * protocol.parameters().jamCheck.maxRattlerFraction, o.out.c_str());
        return EXIT_SUCCESS;
    }
    std::cerr << "sbgen: " << o.out.string() << " (written, marked jammed = 0): " << jam.verdict
              << '\n';
    return kNotJammed;
}

} // namespace

int main(int argc, char** argv) {
    try {
        sbpack::armReadGuard("sbgen", 60.0); // io/read_guard.hpp
    } catch (const std::invalid_argument& e) {
        std::cerr << "sbgen: error: " << e.what() << '\n';
        return EXIT_FAILURE;
    }
    if (argc == 1) {
        std::cerr << sbpack::generatorUsage();
        return EXIT_FAILURE;
    }
    try {
        const sbpack::GeneratorOptions o =
            sbpack::parseGeneratorOptions(std::vector<std::string>(argv + 1, argv + argc));
        if (o.help) {
            std::cout << sbpack::generatorUsage();
            return EXIT_SUCCESS;
        }
        if (o.version) {
            std::cout << "sbgen " << sbpack::kVersion << '\n';
            return EXIT_SUCCESS;
        }
        return generate(o);
    } catch (const std::exception& e) {
        std::cerr << "sbgen: error: " << e.what() << '\n';
        return EXIT_FAILURE;
    }
}

#include "protocol/jamming_protocol.hpp"

#include "contacts/contact_network.hpp"
#include "initial/random_start.hpp"
#include "protocol/checkpoint_entries.hpp"
#include "protocol/protocol_advice.hpp"
#include "version.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>

namespace sbpack {
namespace {

void require(bool ok, const std::string& parameter, const std::string& problem) {
    if (!ok) throw ProtocolParameterError(parameter, problem);
}

/// A run cannot go on from overlapping particles: the event-driven dynamics assumes none.
void refuseOverlaps(const Packing& packing, const std::string& source) {
    const ContactResult c = ContactNetwork({}).compute(packing);
    if (c.overlappingPairs > 0)
        throw std::invalid_argument("'" + source +
                                    "': " + describeOverlaps(c, packing.shape().diameter()) +
                                    ": cannot resume from overlapping particles");
}

bool positiveFinite(double x) {
    return std::isfinite(x) && x > 0.0;
}

AnyEngine freshEngine(const ProtocolParameters& parameters, const PlacementWatch& placed) {
    Random random(parameters.seed);
    const int n = parameters.particles;
    std::vector<double> sizes = parameters.relativeSizes();
    const double box =
        boxLengthFor(n, ParticleShape(parameters.shape, 0.5).volume() * meanCubedSize(sizes),
                     parameters.phiInit);
    const GrowthClock clock{1.0, 0.0, parameters.fastGrowthRate()};
    return std::visit(
        [&](const auto& shape) -> AnyEngine {
            using Shape = std::decay_t<decltype(shape)>;
            const RandomPlacement placement = randomPlacement(shape, n, box, random, placed, sizes);
            const std::vector<Vector3d> velocities = maxwellVelocities(n, random);
            std::vector<ParticleState> state(n);
            for (int i = 0; i < n; ++i)
                state[i] = {placement.positions[i], velocities[i], placement.orientations[i]};
            if constexpr (Shape::kRotates) {
                const std::vector<Vector3d> spins =
                    maxwellAngularVelocities(n, shape.inertiaPerMass(1.0), random);
                for (int i = 0; i < n; ++i) // a mixture's particle of size s: inertia s^2 I
                    state[i].angularVelocity = sizes.empty() ? spins[i] : spins[i] / sizes[i];
            }
            return EventDrivenMd(shape, box, std::move(state), clock, std::move(sizes));
        },
        shapeFor(parameters.shape));
}

/// The engine of a checkpoint's particles and pair records, refused without velocities or with
/// overlaps.
AnyEngine resumedEngine(const Packing& packing, const std::string& source,
                        const CheckpointFields& fields) {
    const bool rotates = rotating(packing.shapeSpec);
    if (packing.velocities.size() != packing.size() ||
        (rotates && packing.angularVelocities.size() != packing.size()))
        throw std::invalid_argument("'" + source + "': checkpoint without velocities");
    refuseOverlaps(packing, source);
    std::vector<ParticleState> state(packing.size());
    for (std::size_t i = 0; i < packing.size(); ++i) {
        state[i] = {packing.positions[i], packing.velocities[i], packing.orientations[i]};
        if (rotates) state[i].angularVelocity = packing.angularVelocities[i];
    }
    AnyEngine engine = makeEngine(packing.shapeSpec, packing.boxLength, std::move(state),
                                  fields.clock, packing.relativeSizes());
    restorePairRecords(engine, fields.pairRecords, source);
    return engine;
}

} // namespace

double ProtocolParameters::fastGrowthRate() const {
    return gammaFast.value_or(measuredProtocol(shape).fastRate);
}

double ProtocolParameters::slowGrowthRate() const {
    return gammaSlow.value_or(speed * measuredProtocol(shape).slowRate);
}

std::vector<double> ProtocolParameters::relativeSizes() const {
    if (polydispersity != 0.0) { // uniform on [1 - a, 1 + a], a = sqrt(3) s: quantile k
        const double a = std::sqrt(3.0) * polydispersity;
        std::vector<double> sizes(particles);
        for (int k = 0; k < particles; ++k)
            sizes[k] = (1.0 + a - 2.0 * a * (k + 0.5) / particles) / (1.0 + a - a / particles);
        return sizes; // sizes[0] = 1 exactly (x / x)
    }
    if (sizeRatio == 1.0) return {};
    const auto large = static_cast<int>(std::lround(largeFraction * particles));
    std::vector<double> sizes(particles, 1.0 / sizeRatio);
    std::fill(sizes.begin(), sizes.begin() + large, 1.0);
    return sizes;
}

std::uint64_t ProtocolParameters::collisionLimit() const {
    if (costLimit == 0.0) return 0;
    return static_cast<std::uint64_t>(std::ceil(costLimit * expectedCost(*this).collisions));
}

void ProtocolParameters::validate() const {
    require(particles >= 2, "n_particles", "need at least 2 particles");
    if (const auto problem = measuredProtocol(shape).problem)
        throw ProtocolParameterError(problem->parameter, problem->message);
    static_assert(kLeastPhiInit == 1e-3, "the message below names it");
    require(std::isfinite(phiInit) && phiInit >= kLeastPhiInit && phiInit < 0.5, "phi_init",
            "must be in [0.001, 0.5) (a more dilute start only adds growth time)");
    require(!gammaFast || positiveFinite(*gammaFast), "gamma_fast", "must be positive and finite");
    require(!gammaSlow || positiveFinite(*gammaSlow), "gamma_slow", "must be positive and finite");
    require(std::isfinite(speed) && speed >= 1.0 && speed <= 1e3, "speed",
            "must be in [1, 1000] (times the default slow rate; 1: the paper's protocol)");
    require(speed == 1.0 || !gammaSlow, "speed",
            "scales the default slow rate, which gamma_slow (--gamma-slow) replaces: give one");
    require(positiveFinite(pressureSwitch), "pressure_switch", "must be positive and finite");
    require(pressureFinish == 0.0 ||
                (positiveFinite(pressureFinish) && pressureFinish >= pressureSwitch &&
                 pressureFinish < pressureFinal),
            "pressure_finish",
            "must be 0 (no finish) or in [the switch pressure, the final pressure)");
    require(std::isfinite(finishSpeed) && finishSpeed >= 1.0 && finishSpeed <= 1e3, "finish_speed",
            "must be in [1, 1000] (times the slow rate past pressure_finish)");
    require(finishSpeed == 1.0 || pressureFinish > 0.0, "finish_speed",
            "needs pressure_finish (--pressure-finish), the pressure it starts at");
    require(positiveFinite(pressureFinal), "pressure_final", "must be positive and finite");
    require(pressureFinal > pressureSwitch, "pressure_final",
            "must be larger than the switch pressure");
    // A window is ceil(W N) collisions, an integer: W N in [1, 2^53].
    require(positiveFinite(collisionsPerWindow) && collisionsPerWindow * particles >= 1.0 &&
                collisionsPerWindow <= 1e6,
            "collisions_per_window", "must be in (0, 1e6] with at least one collision a window");
    require(std::isfinite(costLimit) && costLimit >= 0.0 && costLimit <= 1e6, "cost_limit",
            "must be in [0, 1e6] (times the expected collisions; 0: no limit)");
    require(forceWindows >= 0 && forceWindows <= 10'000, "force_windows",
            "must be in [0, 10000] (0: no contact forces)");
    require(std::isfinite(sizeRatio) && sizeRatio >= 1.0 && sizeRatio <= 10.0, "size_ratio",
            "must be in [1, 10] (the large particles' diameter over the small ones'; 1: "
            "identical particles)");
    const double large = std::round(largeFraction * particles);
    require(sizeRatio == 1.0 || (large >= 1.0 && large < particles), "large_fraction",
            "must leave at least one large and one small particle (a number fraction in (0, 1))");
    require(std::isfinite(polydispersity) && polydispersity >= 0.0 && polydispersity <= 0.3,
            "polydispersity",
            "must be in [0, 0.3] (the diameters' standard deviation over their mean)");
    require(polydispersity == 0.0 || sizeRatio == 1.0, "polydispersity",
            "cannot be given with size_ratio (--size-ratio): each makes a mixture");
}

JammingProtocol::JammingProtocol(const ProtocolParameters& parameters, const PlacementWatch& placed)
    : parameters_((parameters.validate(), parameters)), engine_(freshEngine(parameters, placed)),
      forceWindows_(parameters.forceWindows) {
    status_.packingFraction = packingFraction();
    adaptSkin();
}

JammingProtocol::JammingProtocol(const Packing& packing, const std::string& source)
    : JammingProtocol(packing, source, readCheckpoint(packing, source)) {}

JammingProtocol::JammingProtocol(const Packing& packing, const std::string& source,
                                 const CheckpointFields& fields)
    : parameters_(fields.parameters), status_(fields.status),
      engine_(resumedEngine(packing, source, fields)),
      forceWindows_(fields.parameters.forceWindows) {
    status_.packingFraction = packing.packingFraction();
    adaptSkin(); // as the run that wrote the checkpoint did at the end of its window
}

void JammingProtocol::adaptSkin() {
    // From the engine's own diameter, so that a resumed run picks the same skin bit for bit.
    const double skin = neighbourSkin(packingFraction());
    std::visit([&](auto& engine) { engine.setSkin(skin); }, engine_);
}

void JammingProtocol::setPressureFinal(double pressure) {
    ProtocolParameters changed = parameters_;
    changed.pressureFinal = pressure;
    changed.validate();
    parameters_ = changed;
    if (status_.phase == Phase::Done && status_.reducedPressure < pressure)
        status_.phase = Phase::Slow;
}

void JammingProtocol::setFinish(double pressure, double speed) {
    ProtocolParameters changed = parameters_;
    changed.pressureFinish = pressure;
    changed.finishSpeed = speed;
    changed.validate();
    parameters_ = changed;
}

bool JammingProtocol::finishing(double sustained) const {
    return parameters_.pressureFinish > 0.0 && sustained >= parameters_.pressureFinish;
}

void JammingProtocol::setCostLimit(double limit) {
    ProtocolParameters changed = parameters_;
    changed.costLimit = limit;
    changed.validate();
    parameters_ = changed;
}

bool JammingProtocol::stopAtCostLimit() {
    const std::uint64_t limit = parameters_.collisionLimit();
    if (limit == 0 || status_.collisions < limit) return false;
    JamCheck check = checkJam(checkpoint(), status_.reducedPressure, parameters_.jamCheck);
    char line[512];
    std::snprintf(line, sizeof line,
                  "stopped at the cost limit before the final pressure: %.3g collisions, %g "
                  "times the expected %.3g (docs/design.md §3, \"Cost limit\"), at reduced "
                  "pressure %.3g < %.3g; its jam check at that pressure: ",
                  static_cast<double>(status_.collisions), parameters_.costLimit,
                  expectedCost(parameters_).collisions, status_.reducedPressure,
                  parameters_.pressureFinal);
    check.verdict = line + check.verdict + "; resume with a larger cost limit to go on";
    check.jammed = false;
    status_.jam = std::move(check);
    return true;
}

bool JammingProtocol::run(const std::function<void(const ProtocolStatus&)>& onWindow,
                          const StopRequest& stop) {
    using Clock = std::chrono::steady_clock;
    const std::uint64_t perWindow = static_cast<std::uint64_t>(
        std::ceil(parameters_.collisionsPerWindow * parameters_.particles));
    stoppedMidWindow_ = false;
    while (status_.phase != Phase::Done) {
        if (stopAtCostLimit()) return true;
        // The state a repeated stop midway through this window resumes from (issue 65 item 3).
        if (status_.windows > 0) windowStart_ = checkpoint();
        const auto start = Clock::now();
        const std::clock_t cpuStart = std::clock();
        const bool recorded = recordsForces();
        if (!recorded) forceWindows_.clear(); // the windows kept are the last ones in a row
        impulses_.clear();
        // Before the first window ends there is no state to keep: any request stops at once
        // (issue 65 item 3: a first window at N = 1e6 can last minutes).
        const bool firstWindow = status_.windows == 0;
        const RunReport report = std::visit(
            [&](auto& engine) {
                return engine.run(perWindow, INFINITY, &stop, recorded ? &impulses_ : nullptr,
                                  firstWindow);
            },
            engine_);
        status_.collisions += report.collisions;
        status_.relists += report.relists;
        status_.staleEvents += report.staleEvents;
        status_.rechecks += report.rechecks;
        std::visit([&](auto& engine) { status_.predictor += engine.takePredictorStats(); },
                   engine_);
        status_.wallSeconds += std::chrono::duration<double>(Clock::now() - start).count();
        status_.cpuSeconds += static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        if (report.interrupted) {
            stoppedMidWindow_ = true;
            return false;
        }
        if (!(report.duration > 0.0))
            throw std::runtime_error("no time passed over a window of " +
                                     std::to_string(report.collisions) +
                                     " collisions (collisions repeating at one instant): the "
                                     "reduced pressure (virial / duration) is undefined");
        watchJam(report.participants, finishWindow(report.virial, report.duration, recorded));
        onWindow(status_);
        if (stop.requested() && status_.phase != Phase::Done) return false;
    }
    if (!status_.jam)
        status_.jam = checkJam(checkpoint(), status_.reducedPressure, parameters_.jamCheck);
    return true;
}

bool JammingProtocol::recordsForces() const {
    // From half the final pressure on: in the slow phase hundreds of windows before the end,
    // whose last forceWindows are kept (docs/jamming.md, "Contact forces").
    return parameters_.forceWindows > 0 &&
           status_.reducedPressure >= 0.5 * parameters_.pressureFinal;
}

double JammingProtocol::finishWindow(double virial, double duration, bool recorded) {
    // The window started at kT = 1 (rescaled); average with its end for the virial (docs/design.md
    // §3). The virial theorem's kT is the translational one. A phase ends when two windows in a row
    // reach its pressure: one window's estimate spikes when a cluster of rotating near-cubes
    // chatters through its collision budget in almost no time.
    const double previous = status_.reducedPressure;
    double sustained = previous; // the lower of this window's pressure and the last one's
    std::visit(
        [&](auto& engine) {
            const double kTEnd = engine.kineticTemperature();
            const double kT = 0.5 * (1.0 + kTEnd);
            status_.reducedPressure = 1.0 + virial / (3.0 * parameters_.particles * kT * duration);
            if (recorded)
                forceWindows_.push(impulses_, duration, kT, status_.reducedPressure,
                                   status_.windows + 1); // this window's number
            engine.scaleVelocities(1.0 / std::sqrt(kTEnd));
            const double kTRotation = engine.rotationalTemperature();
            if (kTRotation > 0.0) engine.scaleAngularVelocities(1.0 / std::sqrt(kTRotation));
            sustained = std::min(previous, status_.reducedPressure);
            if (status_.phase == Phase::Fast && sustained >= parameters_.pressureSwitch) {
                status_.phase = Phase::Slow;
                engine.setGrowthRate(parameters_.slowGrowthRate());
            }
            if (status_.phase == Phase::Slow && finishing(sustained))
                engine.setGrowthRate(parameters_.finishGrowthRate() * status_.stallSpeed);
        },
        engine_);
    ++status_.windows;
    if (status_.phase == Phase::Slow && sustained >= parameters_.pressureFinal)
        status_.phase = Phase::Done;
    status_.packingFraction = packingFraction();
    adaptSkin();
    return sustained;
}

void JammingProtocol::watchJam(std::uint64_t participants, double sustained) {
    // A subset carries the pressure after this many windows in a row, and checks the jam then
    // and at 2, 4, 8, ... times as many windows; the stall watch likewise from its own count
    // (docs/design.md §3, "Jam check on the way").
    constexpr std::int64_t kSubsetWindows = 3;
    const bool subset = status_.reducedPressure >= parameters_.pressureSwitch &&
                        2 * participants < static_cast<std::uint64_t>(parameters_.particles);
    status_.subsetWindows = subset ? status_.subsetWindows + 1 : 0;
    if (status_.phase == Phase::Slow) status_.stall.observe(sustained);
    const bool stallCheck = status_.phase == Phase::Slow && status_.stall.checkDue();
    if (status_.phase == Phase::Done ||
        !(dueAt(status_.subsetWindows, kSubsetWindows) || stallCheck))
        return;
    JamCheck check = checkJam(checkpoint(), status_.reducedPressure, parameters_.jamCheck);
    if (check.chain) {
        status_.phase = Phase::Done;
        status_.jam = std::move(check);
    } else if (stallCheck && check.jammed &&
               StallWatch::raisable(sustained, parameters_.pressureSwitch) &&
               status_.stall.plateau(expectedDoubling())) {
        raiseGrowthRate(sustained);
    }
}

double JammingProtocol::expectedDoubling() const {
    const double rate = std::visit([](const auto& engine) { return engine.clock().rate; }, engine_);
    return expectedWindowsPerDoubling(parameters_, rate);
}

void JammingProtocol::raiseGrowthRate(double sustained) {
    // A jammed network whose pressure no longer rises at this rate creeps: it makes room as fast
    // as the particles grow (bench/RESULTS.md, "Plateaus"). Twice the rate outruns the creep
    // with the least change to the gaps the slow rate refines. Only where the rate no longer
    // shapes the packing (StallWatch::raisable): below the switch pressure the pressure falls
    // after the fast phase's overshoot while the packing still rearranges, and below 1e10 a
    // creep is the slow rate's own climb, whose speed-up costs Z.
    status_.stallSpeed *= 2.0;
    std::visit([&](auto& engine) { engine.setGrowthRate(2.0 * engine.clock().rate); }, engine_);
    status_.stall.restart(sustained);
}

double JammingProtocol::packingFraction() const {
    return std::visit(
        [&](const auto& engine) {
            return parameters_.particles * meanCubedSize(engine.sizes()) *
                   ParticleShape(parameters_.shape, 0.5 * engine.diameter()).volume() /
                   std::pow(engine.boxLength(), 3);
        },
        engine_);
}

std::optional<Packing> JammingProtocol::resumeCheckpoint() const {
    if (stoppedMidWindow_) return windowStart_;
    if (status_.windows == 0) return std::nullopt;
    return checkpoint();
}

Packing JammingProtocol::checkpoint() const {
    Packing packing;
    packing.shapeSpec = parameters_.shape;
    CheckpointFields fields{parameters_, status_, {}, {}};
    std::visit(
        [&](const auto& engine) {
            fields.clock = engine.clock();
            packing.semiAxis = 0.5 * engine.diameter();
            for (const double size : engine.sizes())
                packing.semiAxes.push_back(packing.semiAxis * size);
            packing.boxLength = engine.boxLength();
            const bool rotates = rotating(parameters_.shape);
            for (const ParticleState& s : engine.particles()) {
                packing.positions.push_back(s.position);
                packing.orientations.push_back(s.orientation);
                packing.velocities.push_back(s.velocity);
                if (rotates) packing.angularVelocities.push_back(s.angularVelocity);
            }
        },
        engine_);
    fields.pairRecords = pairRecordRows(engine_);
    // None measured before the first window ends (a second signal can stop the run there):
    // the packing then has none, as any packing without a pressure (docs/design.md §4).
    if (status_.reducedPressure > 0.0) packing.reducedPressure = status_.reducedPressure;
    packing.seed = parameters_.seed;
    packing.generatorVersion = kVersion;
    writeCheckpoint(fields, packing);
    return packing;
}

} // namespace sbpack

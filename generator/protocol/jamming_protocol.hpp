#pragma once
// The DTS jamming protocol (paper Sec. III A, docs/design.md §3): grow fast (gamma_fast) until the
// reduced pressure reaches pressureSwitch, then slowly (gamma_slow) until pressureFinal (each in
// two windows in a row, so one window's spike does not end a phase). Work
// proceeds in windows of `collisionsPerWindow * N` collisions; after each window the collision
// virial gives the reduced pressure, velocities are rescaled to kT = 1, and the whole state is
// synchronised, so it can be checkpointed and resumed bit for bit. Spheres (p = 1) run on the
// exact sphere engine; any other p on the rotating superball engine, whose thermostat rescales
// translational and rotational kinetic energy separately to kT = 1 (equipartition).
//
// No jam is declared from the pressure alone (docs/design.md §3, "Jam check" and "Jam check on
// the way"): at the final pressure the contact network must hold (few rattlers at gaps of order
// D / P). The jam is also checked on the way, when a subset carries the pressure (fewer than half
// the particles colliding in several windows in a row past the switch pressure) or when the slow
// phase's pressure stalls (no doubling over many windows while the particles grow); a failed check
// that finds a chain wrapping around the periodic box ends the run early, not jammed: such a chain
// is rigid, and the rest cannot grow into a jam. A stall that outlasts the run's doublings and
// whose check says jammed is a plateau, where growth and a slow creep balance: the growth rate is
// doubled there (docs/design.md §3, "Plateaus").

#include "contacts/jam_check.hpp"
#include "engine/event_driven_md.hpp"
#include "initial/random_start.hpp"
#include "packing/packing.hpp"
#include "protocol/force_windows.hpp"
#include "protocol/stall_watch.hpp"
#include "shapes/registry.hpp"
#include "stop/stop_request.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

namespace sbpack {

struct CheckpointFields;

struct ProtocolParameters {
    /// The range of N that sbgen --n and sbpack.generate accept.
    static constexpr int kFewestParticles = 2, kMostParticles = 100'000'000;
    int particles = 1000;
    /// The particles' shape (shapes/registry picks its engine; --p sets the superball's p).
    ShapeSpec shape;
    std::uint64_t seed = 1;
    double phiInit = 0.2;
    /// The least phi_init: the particles start at D = 1 in a box of (N v1 / phi_init)^(1/3) and
    /// grow at dD/dt = gamma to D_J = (phi_J / phi_init)^(1/3), so a dilute start only adds
    /// growth time (8 / gamma at 1e-3, 1e100 / gamma at 1e-300, which wrote L = 2.2e100 with
    /// the particles never grown: issue 65).
    static constexpr double kLeastPhiInit = 1e-3;
    /// Unset: fastGrowthRate()'s default for p.
    std::optional<double> gammaFast;
    /// Unset: slowGrowthRate()'s default for p.
    std::optional<double> gammaSlow;
    /// The speed knob (docs/design.md §3, "Speed"): the default slow rate times speed, >= 1, for
    /// every p; about speed times fewer slow-phase collisions at the cost tabulated there. Only
    /// with gammaSlow unset (a checkpoint stores the rate it resolved to).
    double speed = 1.0;
    double pressureSwitch = 1e6;
    double pressureFinal = 1e12;
    /// The finish (issue 64, docs/design.md §3, "Finish"): from this reduced pressure on, the
    /// slow phase grows finishSpeed times faster (finishGrowthRate); 0: no finish, the slow
    /// rate to the end (the paper's protocol).
    double pressureFinish = 0.0;
    double finishSpeed = 1.0;
    /// A binary mixture (docs/mixtures.md): the large particles' diameter over the small ones'
    /// (1: identical particles) and the large ones' number fraction; every particle grows by the
    /// same factor, as in the Lubachevsky-Stillinger code.
    double sizeRatio = 1.0;
    double largeFraction = 0.5;
    /// A polydisperse mixture (docs/mixtures.md): the diameters' standard deviation over their
    /// mean, in [0, 0.3]; the diameters are the N equally spaced quantiles of the uniform
    /// distribution of that mean and deviation (0: none; not with sizeRatio).
    double polydispersity = 0.0;
    double collisionsPerWindow = 10.0; ///< per particle, between thermostat rescalings
    /// The run stops, written as not jammed and resumable, once its collisions exceed costLimit
    /// times the expected ones (expectedCost, docs/design.md §3, "Cost limit"); 0: no limit.
    /// 40 is 2.6 times the largest ratio measured in a run that jammed (bench/RESULTS.md, "The
    /// creep of p = 10 seed 2 and the cost limit").
    double costLimit = 40.0;
    /// The contact-network criterion of the jam, checked before a jam is declared.
    JamCheckParameters jamCheck{};
    /// The contact forces average over the run's last windows since the last multiple of
    /// forceWindows but one (forceWindows to 2 forceWindows - 1 of them), recorded once the
    /// reduced pressure has reached half the final one (docs/jamming.md, "Contact forces");
    /// 0: none.
    std::int64_t forceWindows = 50;

    /// The fast rate used: gammaFast if set, else the shape's measured default (shapes/registry:
    /// measuredProtocol), for superballs the paper's protocol at p (paperFastRate:
    /// the rate in the paper's range (0.005, 0.05) that reproduces its phi, bench/RESULTS.md,
    /// "Fidelity", E8).
    double fastGrowthRate() const;

    /// The slow rate used: gammaSlow if set, else speed times the shape's measured default:
    /// 1e-4 for spheres (Z = 5.978 +-
    /// 0.005 at N = 1000, where 1e-3 leaves 5.94) and for superballs the paper's protocol at p
    /// (paperSlowRate: the rate that reproduces its Z, whose superball Z keeps rising as the slow
    /// phase slows; bench/RESULTS.md, "Fidelity", E11).
    double slowGrowthRate() const;

    /// The rate of the finish: finishSpeed times slowGrowthRate().
    double finishGrowthRate() const { return finishSpeed * slowGrowthRate(); }

    /// Each particle's diameter over the largest (relativeSizes()[i] for particle i): of a binary
    /// mixture the first round(largeFraction N) particles large (1), the others 1 / sizeRatio; of
    /// a polydisperse one the quantiles (polydispersity), largest first; empty where the
    /// particles are identical.
    std::vector<double> relativeSizes() const;
    bool isMixture() const { return sizeRatio != 1.0 || polydispersity != 0.0; }

    /// The collisions after which the run stops (costLimit times the expected ones); 0: none.
    std::uint64_t collisionLimit() const;

    /// Throws ProtocolParameterError naming the first bad parameter (by its provenance name,
    /// e.g. "phi_init"; the command line maps it to its option).
    void validate() const;
};

/// A protocol parameter out of its range.
class ProtocolParameterError : public std::invalid_argument {
  public:
    ProtocolParameterError(std::string parameter, const std::string& problem)
        : std::invalid_argument(parameter + ": " + problem), parameter_(std::move(parameter)),
          problem_(problem) {}
    /// The parameter's name in the provenance, e.g. "collisions_per_window".
    const std::string& parameter() const { return parameter_; }
    const std::string& problem() const { return problem_; }

  private:
    std::string parameter_, problem_;
};

enum class Phase { Fast, Slow, Done };

struct ProtocolStatus {
    Phase phase = Phase::Fast;
    double reducedPressure = 0.0;
    double packingFraction = 0.0;
    std::uint64_t collisions = 0;
    std::uint64_t relists = 0; ///< neighbour-list rebuilds of single particles
    std::uint64_t staleEvents = 0;
    std::uint64_t rechecks = 0; ///< superball predictions that stopped at a safe time
    std::uint64_t windows = 0;
    PredictorStats predictor; ///< the superball predictor's work, summed over the run
    /// Windows in a row, past the switch pressure, in which fewer than half the particles
    /// collided: the pressure may come from a subset (then the jam is checked).
    std::int64_t subsetWindows = 0;
    /// The slow phase's pressure that stops rising while the particles grow (then the jam is
    /// checked, and a plateau's growth rate raised).
    StallWatch stall;
    /// The slow phase's growth rate over its protocol's (the slow rate, or the finish's): doubled
    /// at each plateau whose jam check passes (docs/design.md §3, "Plateaus"); 1: never.
    double stallSpeed = 1.0;
    /// The jam check, made when the final pressure is reached, or on the way when it finds a
    /// chain that wraps around the box (then the run ends, not jammed), or the refusal of a run
    /// that reached its cost limit (then the phase stays, so the output resumes).
    std::optional<JamCheck> jam;
    double wallSeconds = 0.0; ///< summed over the run and every resumed part
    double cpuSeconds = 0.0;  ///< process CPU time, likewise (throughput on a shared machine)
};

class JammingProtocol {
  public:
    /// A fresh run: random start from the seed. `placed`, if given, is called with the count
    /// placed every kPlacementPoll trials of the random start (the set-up's long part: about 30 s
    /// at N = 1e6, p = 1.5); returning false stops it (PlacementStopped).
    explicit JammingProtocol(const ProtocolParameters& parameters,
                             const PlacementWatch& placed = {});
    /// Continues from a checkpoint written by checkpoint(); throws std::invalid_argument naming
    /// `source` if the packing carries no sbgen state.
    JammingProtocol(const Packing& checkpoint, const std::string& source);

    /// Runs windows until Phase::Done, the cost limit (status().jam then says why) or a stop;
    /// calls onWindow after every window (with the protocol synchronised, so checkpoint() may be
    /// called there). A `stop` request is looked at after each window, so a run stopped by it is
    /// synchronised and its checkpoint resumes bit for bit like a periodic one; a repeated one
    /// interrupts the window at its next event (a checkpoint then resumes the run, but not bit
    /// for bit, but resumeCheckpoint() gives the window's start, which does). Returns true when
    /// done or at the cost limit.
    bool run(const std::function<void(const ProtocolStatus&)>& onWindow,
             const StopRequest& stop = processStopRequest());

    const ProtocolParameters& parameters() const { return parameters_; }
    /// Only the final pressure, the cost limit and the finish may change on resume (e.g. to
    /// continue from 1e12 to 1e14, a run stopped at its cost limit, or a run past a pressure
    /// with a faster finish from there: issue 64's measurement).
    void setPressureFinal(double pressure);
    void setCostLimit(double limit);
    void setFinish(double pressure, double speed);
    const ProtocolStatus& status() const { return status_; }

    /// The synchronised state as a packing whose provenance holds every parameter and the exact
    /// engine state (readable by the resume constructor).
    Packing checkpoint() const;
    /// The state a stopped run resumes from bit for bit: checkpoint() after a stop at a window's
    /// end, the window's start after a repeated stop ended a window midway (kept at every
    /// window's start), none before the first window has ended (issue 65 item 3).
    std::optional<Packing> resumeCheckpoint() const;

    /// The windows recorded for the contact forces: the run's last ones in a row (at most
    /// 2 forceWindows - 1), since its pressure reached half the final one or since its resume
    /// (docs/jamming.md, "Contact forces"); none before.
    const ForceWindows& forceWindows() const { return forceWindows_; }

  private:
    /// The resume constructor's work, from the checkpoint's entries (checkpoint_entries.hpp).
    JammingProtocol(const Packing& checkpoint, const std::string& source,
                    const CheckpointFields& fields);
    /// The reduced pressure from the window's virial, the thermostat and the phase, and the
    /// window's impulses into forceWindows_ when `recorded`; returns the sustained pressure (the
    /// lower of this window's and the last one's).
    double finishWindow(double virial, double duration, bool recorded);
    /// True where the finish has begun: pressureFinish set and reached by `sustained`.
    bool finishing(double sustained) const;
    /// Whether the next window's impulses are recorded for the contact forces.
    bool recordsForces() const;
    /// The neighbour-list skin for the current packing fraction (neighbourSkin), for the next
    /// window's rebuild.
    void adaptSkin();
    /// After a window in which `participants` particles collided: the jam check on the way, when
    /// a subset has carried the pressure or the sustained pressure has stalled for a while, and
    /// the growth rate doubled at a plateau.
    void watchJam(std::uint64_t participants, double sustained);
    /// Doubles the slow phase's growth rate (a plateau at `sustained`).
    void raiseGrowthRate(double sustained);
    /// The windows a doubling of the pressure takes at the present growth rate by the cost
    /// model (expectedWindowsPerDoubling).
    double expectedDoubling() const;
    /// Past the cost limit: status_.jam says the run stopped there, with the contact network at
    /// its pressure; returns whether it did.
    bool stopAtCostLimit();
    /// phi = N v1 / L^3 at the current diameter.
    double packingFraction() const;

    ProtocolParameters parameters_;
    ProtocolStatus status_;
    AnyEngine engine_;
    ContactImpulses impulses_; ///< the window's, while recorded
    ForceWindows forceWindows_;
    std::optional<Packing> windowStart_; ///< checkpoint() at the running window's start
    bool stoppedMidWindow_ = false;      ///< the last run() ended midway through a window
};

} // namespace sbpack

#pragma once
// Event-driven molecular dynamics of identical growing hard bodies in a cubic periodic box
// (Donev-Torquato-Stillinger; docs/design.md §3). Layers (docs/design.md §7): EventQueue (no
// physics), NeighbourLists (which pairs to test), the Shape (predictor and contact),
// resolveCollision (impulse). Each particle holds its earliest predicted collision and the time it
// leaves its neighbour-list sphere; a collision is stale when the partner's event counter has moved
// on since the prediction.
//
// The shape (shapes/shape.hpp, one concept: spheres simply do not rotate) advances orientations,
// orders and answers the predictions, finds the contact and applies the impulse. Each pair keeps
// what the shape's predictor remembers of it (engine/pair_memories.hpp: for superballs the last
// contact normal as the warm start, and a lower bound on that normal's plane gap, usable while
// neither particle's motion has changed since), and each prediction is asked only up to the
// earliest event of the two particles (a later contact would be stale by then, and the particle
// predicted last before it finds it). A prediction that hits its work limit schedules a recheck
// of the particle instead of a collision.
//
// Particles are advanced lazily (each has its own time stamp). run() ends synchronised: every
// particle is advanced to the final time, wrapped into [0, L), and that time becomes the new time
// origin, folded into the growth clock; the pair memories keep across it what holds whatever
// the motions (PairMemory::synchronised: the normal and the witness record) and are pruned to
// the rebuilt lists. The synchronised state, the clock and those records are the whole state:
// rebuilding the events from them is deterministic, which makes checkpoints exact
// (pairRecords, restorePairRecords).

#include "engine/contact_impulses.hpp"
#include "engine/growth_clock.hpp"
#include "engine/pair_memories.hpp"
#include "events/event_queue.hpp"
#include "neighbours/neighbour_lists.hpp"
#include "packing/packing.hpp"
#include "shapes/pair_motion.hpp"
#include "shapes/shape.hpp"
#include "stop/stop_request.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace sbpack {

struct EngineParameters {
    /// Lists are built for diameters up to D (1 + growthMargin); the engine synchronises and
    /// rebuilds them when the growing diameter gets there.
    double growthMargin = 0.02;
    /// Neighbour-list skin in units of D: a particle is relisted after moving skin D / 2 (the
    /// protocol sets it from the packing fraction: neighbourSkin).
    double skin = 0.1;
};

/// What one run() did.
struct RunReport {
    double duration = 0.0; ///< engine time advanced
    std::uint64_t collisions = 0;
    std::uint64_t relists = 0; ///< neighbour-list exits
    std::uint64_t staleEvents = 0;
    std::uint64_t rechecks = 0; ///< predictions that stopped at a safe time, then redone
    /// sum over collisions of r_ij . Delta p_j (the collision virial, docs/design.md §3)
    double virial = 0.0;
    /// Particles that took part in at least one collision (the jam watch of the protocol).
    std::uint64_t participants = 0;
    bool interrupted = false;
};

template <EngineShape Shape> class EventDrivenMd {
  public:
    /// `sizes`: a mixture's diameters over the clock's D (docs/mixtures.md), each in (0, 1] and
    /// one per particle; empty: identical bodies of diameter D.
    EventDrivenMd(Shape shape, double boxLength, std::vector<ParticleState> particles,
                  GrowthClock clock, std::vector<double> sizes = {},
                  EngineParameters parameters = {})
        : shape_(shape), box_(boxLength), state_(std::move(particles)), clock_(clock),
          sizes_(std::move(sizes)), parameters_(parameters),
          memories_(static_cast<int>(state_.size())), collidedInRun_(state_.size(), 0) {
        if (!sizes_.empty() && sizes_.size() != state_.size())
            throw std::invalid_argument("event-driven engine: one size per particle");
    }

    int size() const { return static_cast<int>(state_.size()); }
    double boxLength() const { return box_; }
    const GrowthClock& clock() const { return clock_; }
    double diameter() const { return clock_.diameter(); }
    /// The mixture's diameters over diameter() (empty: identical bodies).
    const std::vector<double>& sizes() const { return sizes_; }
    /// The synchronised particles (valid between runs).
    const std::vector<ParticleState>& particles() const { return state_; }
    const Shape& shape() const { return shape_; }
    /// The pair records of the synchronised state (valid between runs; empty for a shape that
    /// remembers nothing), and their restoration into an engine of the same particles before
    /// its first run (a resumed checkpoint).
    using PairRecord = typename PairMemories<typename Shape::Memory>::Entry;
    std::vector<PairRecord> pairRecords() const { return memories_.records(); }
    void restorePairRecords(const std::vector<PairRecord>& records) { memories_.restore(records); }
    /// The predictor's counters since the last call.
    PredictorStats takePredictorStats() { return shape_.takeStats(); }

    /// Translational kT = m <v^2> / 3 with m = 1.
    double kineticTemperature() const {
        double sum = 0.0;
        for (const ParticleState& s : state_)
            sum += s.velocity.squaredNorm();
        return sum / (3.0 * size());
    }
    /// Rotational kT = <I omega^2> / 3 (0 for shapes that do not rotate); a mixture's particle
    /// of size s has the inertia s^2 I.
    double rotationalTemperature() const {
        double sum = 0.0;
        for (int k = 0; k < size(); ++k)
            sum += (sizes_.empty() ? 1.0 : sizes_[k] * sizes_[k]) *
                   state_[k].angularVelocity.squaredNorm();
        return shape_.inertiaPerMass(diameter()) * sum / (3.0 * size());
    }
    void scaleVelocities(double factor) {
        for (ParticleState& s : state_)
            s.velocity *= factor;
        dirty_ = true;
    }
    void scaleAngularVelocities(double factor) {
        for (ParticleState& s : state_)
            s.angularVelocity *= factor;
        dirty_ = true;
    }
    void setGrowthRate(double gamma) {
        clock_.setRate(gamma);
        dirty_ = true;
    }
    /// The neighbour-list skin (units of D) of the next rebuild (neighbourSkin).
    void setSkin(double skin) {
        if (skin == parameters_.skin) return;
        parameters_.skin = skin;
        dirty_ = true;
    }

    /// Processes events until `maxCollisions` collisions, engine time `maxDuration`, or a
    /// repeated `stop` request (checked every event: a second request stops at once, the first
    /// waits for the window's end, JammingProtocol::run), or with `firstRequestStops` any
    /// request; then synchronises. Growth past the lists' design diameter synchronises and
    /// rebuilds them on the way. With `impulses`, each collision's impulse is also added to its
    /// pair there (the contact forces' windows).
    RunReport run(std::uint64_t maxCollisions, double maxDuration = kNever,
                  const StopRequest* stop = nullptr, ContactImpulses* impulses = nullptr,
                  bool firstRequestStops = false) {
        RunReport report;
        ++run_;
        impulses_ = impulses;
        while (report.collisions < maxCollisions && !report.interrupted) {
            if (dirty_) rebuild();
            const double limit = std::min(horizon_, maxDuration - report.duration);
            double now = 0.0;
            bool limitReached = false;
            while (report.collisions < maxCollisions) {
                if (stop != nullptr &&
                    (stop->repeated() || (firstRequestStops && stop->requested()))) {
                    report.interrupted = true;
                    break;
                }
                const int i = queue_.top();
                const double t = queue_.topTime();
                if (t > limit) {
                    limitReached = true;
                    if (limit != kNever) now = limit;
                    break;
                }
                now = t;
                if (exit_[i] <= collision_[i].time) {
                    relist(i, t);
                    ++report.relists;
                } else if (collision_[i].partner < 0) {
                    predict(i, t);
                    ++report.rechecks;
                } else {
                    collide(i, t, report);
                }
            }
            synchronize(now);
            report.duration += now;
            if (limitReached && (limit < horizon_ || limit == kNever))
                break; // maxDuration, or no event ever
        }
        impulses_ = nullptr;
        return report;
    }

  private:
    static constexpr double kNever = std::numeric_limits<double>::infinity();

    struct PredictedCollision {
        double time = kNever;
        int partner = -1; ///< -1: a recheck of the particle itself
        std::uint64_t partnerCounter = 0;
    };
    void advance(int i, double t) {
        ParticleState& s = state_[i];
        s.position += s.velocity * (t - time_[i]);
        s.orientation = shape_.turned(s.orientation, s.angularVelocity, t - time_[i]);
        if constexpr (kWitnessClock) turned_[i] = turnedAt(i, t);
        time_[i] = t;
    }
    /// i's accumulated rotation angle at time t (since the last rebuild).
    double turnedAt(int i, double t) const {
        return turned_[i] + state_[i].angularVelocity.norm() * (t - time_[i]);
    }
    /// Only a shape that keeps pair memories reads the accumulated angles (its witness
    /// records); the sphere's fast path pays nothing for them.
    static constexpr bool kWitnessClock = !std::is_same_v<typename Shape::Memory, NoPairMemory>;

    /// The pair at time t in its local frame: the minimum-image displacement of the stored
    /// positions first, then each particle's own flight since its time stamp.
    PairMotion motion(int i, int j, double t) const {
        PairMotion m;
        m.displacement = minimumImage(state_[j].position - state_[i].position, box_) +
                         state_[j].velocity * (t - time_[j]) - state_[i].velocity * (t - time_[i]);
        m.relativeVelocity = state_[j].velocity - state_[i].velocity;
        m.diameter = clock_.diameter(t);
        m.growthRate = clock_.rate;
        if (!sizes_.empty()) { // a mixture's pair: its mean diameter, each body's about it
            const double pairSize = 0.5 * (sizes_[i] + sizes_[j]);
            m.diameter *= pairSize;
            m.growthRate *= pairSize;
            m.sizeI = sizes_[i] / pairSize;
            m.sizeJ = sizes_[j] / pairSize;
        }
        shape_.orient(m, state_[i], t - time_[i], state_[j], t - time_[j]);
        if constexpr (kWitnessClock) {
            m.turnedI = turnedAt(i, t);
            m.turnedJ = turnedAt(j, t);
        }
        return m;
    }

    void schedule(int i) { queue_.set(i, std::min(collision_[i].time, exit_[i])); }

    /// Predicts the pair, moving as `m` from time t, up to the earliest of i's best so far, j's
    /// next event, i's list exit and the lists' growth horizon.
    void consider(int i, int j, double t, const PairMotion& m) {
        const double limit =
            std::min(std::min(collision_[i].time, exit_[i]), std::min(queue_.time(j), horizon_));
        const Prediction next = memories_.predictWith(
            i, j, t, {counter_, changedAt_}, [&](auto& memory, const auto* resolved) {
                return shape_.collisionTime(m, limit - t, memory, resolved);
            });
        const double when = t + next.time;
        if (when < collision_[i].time)
            collision_[i] = next.contact ? PredictedCollision{when, j, counter_[j]}
                                         : PredictedCollision{when, -1, 0};
    }

    /// i's earliest collision with any listed neighbour, predicted at time t, the neighbours
    /// asked in the shape's order.
    void predict(int i, double t) {
        collision_[i] = {};
        const std::vector<int>& list = lists_.of(i);
        shape_.inPredictionOrder(
            static_cast<int>(list.size()), [&](int k) { return motion(i, list[k], t); },
            [&](int k, const PairMotion& m) { consider(i, list[k], t, m); });
        schedule(i);
    }

    /// When i gets skin D / 2 away from its anchor: |e + v tau| = s with e = r_i - anchor, the
    /// positive root of v.v tau^2 + 2 e.v tau + (e.e - s^2) = 0 in cancellation-free form.
    void predictExit(int i) {
        const Vector3d e = state_[i].position - lists_.anchor(i);
        const Vector3d& v = state_[i].velocity;
        const double a = v.squaredNorm(), b = e.dot(v),
                     c = e.squaredNorm() - exitRadius_ * exitRadius_;
        const double root = std::sqrt(std::max(0.0, b * b - a * c));
        exit_[i] = a == 0.0
                       ? kNever
                       : time_[i] + (b > 0.0 ? std::max(0.0, -c) / (b + root) : (root - b) / a);
    }

    void relist(int i, double t) {
        advance(i, t);
        lists_.reanchor(i, state_[i].position);
        predictExit(i);
        predict(i, t);
    }

    void collide(int i, double t, RunReport& report) {
        const PredictedCollision event = collision_[i];
        const int j = event.partner;
        if (counter_[j] != event.partnerCounter) {
            ++report.staleEvents;
            predict(i, t);
            return;
        }
        advance(i, t);
        advance(j, t);
        const PairMotion m = motion(i, j, t);
        const PairContact contact =
            memories_.collideWith(i, j, t, [&](auto& memory, auto& resolved) {
                return shape_.contact(m, memory, resolved);
            });
        const double impulse = shape_.resolve(m, contact, state_[i], state_[j]);
        report.virial += impulse * contact.normal.dot(m.displacement);
        if (impulses_ != nullptr) impulses_->add(i, j, impulse, contact);
        ++report.collisions;
        for (const int k : {i, j})
            if (collidedInRun_[k] != run_) {
                collidedInRun_[k] = run_;
                ++report.participants;
            }
        ++counter_[i];
        ++counter_[j];
        changedAt_[i] = changedAt_[j] = t;
        predictExit(i);
        predictExit(j);
        predict(i, t);
        predict(j, t);
    }

    void synchronize(double t) {
        for (int i = 0; i < size(); ++i) {
            advance(i, t);
            state_[i].position = wrapIntoBox(state_[i].position, box_);
            state_[i].orientation.normalize();
        }
        memories_.synchronise(turned_);
        clock_.advance(t);
        dirty_ = true;
    }

    /// Lists and every prediction from the synchronised state (time origin 0).
    void rebuild() {
        const double d = clock_.diameter();
        const double maximum = d * (1.0 + parameters_.growthMargin);
        if (!(2.0 * shape_.circumscribedRatio() * maximum < box_))
            throw std::runtime_error("the particle diameter reached half the box length: too few "
                                     "particles for a periodic packing (use more)");
        horizon_ = clock_.rate > 0.0 ? (maximum - d) / clock_.rate : kNever;
        exitRadius_ = 0.5 * parameters_.skin * d;
        std::vector<Vector3d> anchors(size());
        for (int i = 0; i < size(); ++i)
            anchors[i] = state_[i].position;
        lists_ = NeighbourLists(box_, shape_.circumscribedRatio() * maximum + 2.0 * exitRadius_,
                                std::move(anchors));
        memories_.rebuilt(lists_);
        time_.assign(size(), 0.0);
        turned_.assign(size(), 0.0);
        counter_.assign(size(), 0);
        changedAt_.assign(size(), -kNever);
        collision_.assign(size(), {});
        exit_.assign(size(), kNever);
        queue_ = EventQueue(size());
        for (int i = 0; i < size(); ++i)
            predictExit(i);
        for (int i = 0; i < size(); ++i)
            predict(i, 0.0);
        dirty_ = false;
    }

    Shape shape_;
    double box_;
    std::vector<ParticleState> state_;
    GrowthClock clock_;
    std::vector<double> sizes_;
    EngineParameters parameters_;
    NeighbourLists lists_;
    EventQueue queue_;
    std::vector<double> time_;
    std::vector<double> turned_; ///< accumulated rotation angle at time_ (witness records' clock)
    std::vector<std::uint64_t> counter_;
    std::vector<PredictedCollision> collision_;
    std::vector<double> exit_;      ///< time each particle leaves its neighbour-list sphere
    std::vector<double> changedAt_; ///< time of each particle's last collision
    PairMemories<typename Shape::Memory> memories_;
    ContactImpulses* impulses_ = nullptr;      ///< the current run()'s, if it keeps them
    std::uint64_t run_ = 0;                    ///< serial number of the current run()
    std::vector<std::uint64_t> collidedInRun_; ///< the last run() each particle collided in
    double horizon_ = kNever;
    double exitRadius_ = 0.0;
    bool dirty_ = true;
};

} // namespace sbpack

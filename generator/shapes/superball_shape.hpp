#pragma once
// The superball as a shape of the event-driven engine (docs/design.md §2-3): collision prediction
// for two translating, rotating, growing superballs that never misses a contact. Its contract: a
// predicted time is no later than the pair's first contact, and a prediction that reaches its step
// limit returns a time up to which nothing touches (Prediction::contact = false). How: tiers from
// the circumscribed spheres and the cached plane to the shape-independent first-contact search on
// the pair's plane gaps and exact distances, with the bounds that certify each step
// (docs/architecture.md, "generator/: the engine and the superball predictor").

#include "pair/pair_geometry.hpp"
#include "shapes/collision_resolver.hpp"
#include "shapes/pair_motion.hpp"
#include "shapes/predictor_stats.hpp"
#include "shapes/sphere.hpp"
#include "shapes/superball/predictor_limits.hpp"
#include "shapes/witness_bound.hpp"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace sbpack {

struct PlaneGap;
namespace superball {
class SuperballPairGap;
} // namespace superball

class SuperballShape {
  public:
    using Memory = PairMemory;
    static constexpr bool kRotates = true;

    /// Throws std::invalid_argument unless 0.5 <= p < inf.
    explicit SuperballShape(double p);

    double p() const { return p_; }
    /// Circumradius over semi-axis, c = max(1, 3^{1/2 - 1/(2p)}).
    double circumscribedRatio() const { return c_; }
    /// Inradius over semi-axis, min(1, 3^{1/2 - 1/(2p)}).
    double inscribedRatio() const { return cIn_; }
    /// I / m of a body of diameter D (isotropic inertia, docs/design.md §1).
    double inertiaPerMass(double diameter) const;

    /// Whether the pair's bodies overlap now: unless their scale factor mu exceeds 1
    /// (docs/design.md §2; the random start's test).
    bool overlapping(const PairMotion& m) const;

    /// Free flight of the orientation (constant lab-frame omega, isotropic inertia).
    Quaterniond turned(const Quaterniond& q, const Vector3d& omega, double tau) const {
        return advancedOrientation(q, omega, tau);
    }
    /// The pair's orientations after each body's flight since its time stamp, and its spins.
    void orient(PairMotion& m, const ParticleState& i, double tauI, const ParticleState& j,
                double tauJ) const {
        m.orientationI = advancedOrientation(i.orientation, i.angularVelocity, tauI);
        m.orientationJ = advancedOrientation(j.orientation, j.angularVelocity, tauJ);
        m.angularVelocityI = i.angularVelocity;
        m.angularVelocityJ = j.angularVelocity;
    }

    /// The neighbours in the order in which their inscribed spheres would touch (by then the
    /// bodies certainly have): the earliest contact tends to come first, and the horizon it
    /// sets lets the cheap tiers reject the rest (fewer exact evaluations per collision:
    /// bench/RESULTS.md, "Warm Newton on the normal: zero crossings and carried normals").
    template <class MotionOf, class Consider>
    void inPredictionOrder(int count, MotionOf&& motionOf, Consider&& consider);

    /// Earliest delay in [0, horizon] at which the pair touches, or +inf if none; a safe recheck
    /// delay when the step limit is reached. `memory` (in/out): the pair's cached unit normal
    /// from i to j (zero when unknown), updated when the pair is evaluated exactly, and the bound
    /// on its plane gap now (its own or the last one's, moved on), left for the next prediction;
    /// where the answer is a contact, its normal there (atContact) for contact().
    /// `resolved` (else null): the engine has just applied this pair's impulse at this very state,
    /// which left the surfaces separating at the resolver's contact point, so touching now is no
    /// contact (on near-flat faces a re-evaluation can pick another point of the face and see it
    /// closing: zero impulses would repeat at one instant, and no time would pass); its contact,
    /// where known, is the sample at that state.
    Prediction collisionTime(const PairMotion& m, double horizon, PairMemory& memory,
                             const PairMemory::Resolved* resolved = nullptr);

    /// Contact of touching bodies now: normal from i to j, arms to the midpoint of the two support
    /// points (the same point for both, so impulses conserve angular momentum). The normal is
    /// memory.normal where the pair's last prediction found this contact there (atContact) and
    /// its plane still touches, else the exact one warm-started from it; it is left there, its gap
    /// bound dropped, and the contact in `resolved` for the pair's predictions at this instant
    /// (collisionTime's `resolved`).
    PairContact contact(const PairMotion& m, PairMemory& memory, PairMemory::Resolved& resolved);

    /// The elastic impulse at the contact point, spins included (collision_resolver.hpp).
    double resolve(const PairMotion& m, const PairContact& c, ParticleState& i,
                   ParticleState& j) const {
        return resolveCollision(m, c, inertiaPerMass(m.diameter), {i.velocity, i.angularVelocity},
                                {j.velocity, j.angularVelocity});
    }

    /// The counters since the last call.
    PredictorStats takeStats() { return std::exchange(stats, {}); }

    SuperballPredictorLimits limits{};
    PredictorStats stats{};

  private:
    /// Tier 2 of collisionTime: none where a plane of the pair's normal separates it up to
    /// `end` (`remembered`: the memory's gap bound moved on to now), else that
    /// plane's gap now; leaves the plane's bounds and witness record in `memory`.
    std::optional<PlaneGap> separatingPlane(const PairMotion& m,
                                            const superball::SuperballPairGap& gap, double end,
                                            double remembered, PairMemory& memory);

    double p_;
    double c_;
    double cIn_;
    double lever_; ///< sqrt(c^2 - c_in^2): bound on a support point's offset from its normal
    std::optional<SupportHolderBound> witness_; ///< none for the octahedron
    double inertiaPerMassUnit_;                 ///< I / m at semi-axis 1
    std::vector<PairMotion> motions_;           ///< inPredictionOrder's scratch: the motions
    std::vector<std::pair<double, int>> order_; ///< and when the inscribed spheres touch
};

// --- implementation of the template ---

template <class MotionOf, class Consider>
void SuperballShape::inPredictionOrder(int count, MotionOf&& motionOf, Consider&& consider) {
    motions_.clear();
    order_.clear();
    for (int k = 0; k < count; ++k) {
        motions_.push_back(motionOf(k));
        PairMotion inscribed = motions_.back();
        inscribed.diameter *= cIn_;
        inscribed.growthRate *= cIn_;
        order_.emplace_back(SphereShape{}.collisionTime(inscribed), k);
    }
    std::sort(order_.begin(), order_.end());
    for (const auto& [touch, k] : order_)
        consider(k, motions_[k]);
}

} // namespace sbpack

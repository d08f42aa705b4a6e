#pragma once
// The momentum each pair exchanges in collisions, kept per pair while the protocol records
// contact forces (its last windows; docs/jamming.md, "Contact forces"): the collision virial of
// RunReport, kept per pair. Only those windows pay for the hash map.

#include "shapes/pair_motion.hpp"

#include <cstdint>
#include <unordered_map>

namespace sbpack {

/// What pair (i, j), i < j, exchanged: sums over its collisions of the impulse J n (what j
/// received, n from i to j), of J times i's lever arm (the contact point minus r_i) and of J.
struct PairImpulse {
    int i = 0;
    int j = 0;
    Vector3d impulse = Vector3d::Zero();
    Vector3d moment = Vector3d::Zero();
    double magnitude = 0.0;
};

class ContactImpulses {
  public:
    /// Collision of i and j with impulse J >= 0 along `contact`'s normal (from i to j).
    void add(int i, int j, double impulse, const PairContact& contact) {
        const bool ordered = i < j;
        PairImpulse& sum = pairs_[key(ordered ? i : j, ordered ? j : i)];
        sum.i = ordered ? i : j;
        sum.j = ordered ? j : i;
        sum.impulse += (ordered ? impulse : -impulse) * contact.normal;
        sum.moment += impulse * (ordered ? contact.armI : contact.armJ);
        sum.magnitude += impulse;
    }
    void clear() { pairs_.clear(); }
    /// Calls visit(pair) for every pair, in no particular order.
    template <class Visit> void forEach(Visit&& visit) const {
        for (const auto& entry : pairs_)
            visit(entry.second);
    }

  private:
    static std::uint64_t key(int i, int j) {
        return (static_cast<std::uint64_t>(i) << 32) | static_cast<std::uint32_t>(j);
    }
    std::unordered_map<std::uint64_t, PairImpulse> pairs_;
};

} // namespace sbpack

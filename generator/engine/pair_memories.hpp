#pragma once
// What the engine keeps of each pair between predictions: the shape's Memory (shapes/shape.hpp;
// the superball predictor's warm-start normal, the bound on its plane gap and its witness
// record), when it was left
// and both particles' collision counters then. A memory is handed to the predictor as seen from
// the particle predicted (the normal from i to j) and stored as seen from the lower index. A
// shape that remembers nothing (NoPairMemory: the sphere) stores nothing and pays no lookup.

#include "engine/pair_table.hpp"
#include "shapes/pair_motion.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sbpack {

/// The particles' collision counters and the times of their last collisions (the engine's).
struct ParticleClocks {
    const std::vector<std::uint64_t>& counter;
    const std::vector<double>& changedAt;
};

template <class Memory> class PairMemories {
  public:
    /// Forgets every pair (a rebuild: predictions restart from the synchronised state).
    void reset(int particles) {
        particles_ = static_cast<std::uint64_t>(particles);
        records_.clear();
    }

    /// use(memory) with the pair's memory for a prediction of i against j at time t, as seen from
    /// i: its gap bound moved on to t while both particles still fly as they did when it was left
    /// (their counters unchanged, or advanced by one collision at t itself), else the normal
    /// alone; what use leaves in it is kept, stamped with t and the counters now.
    template <class Use>
    auto predictWith(int i, int j, double t, ParticleClocks clocks, Use&& use) {
        Record& record = records_[key(i, j)];
        const auto unchanged = [&](int k, std::uint64_t counter) {
            return clocks.counter[k] == counter ||
                   (clocks.counter[k] == counter + 1 && clocks.changedAt[k] == t);
        };
        const auto [low, high] = std::minmax(i, j);
        Memory memory = unchanged(low, record.counterLow) && unchanged(high, record.counterHigh)
                            ? record.memory.after(t - record.time)
                            : record.memory.normalOnly();
        if (i > j) memory.flip();
        const auto answer = use(memory);
        if (i > j) memory.flip();
        record = {memory, t, clocks.counter[low], clocks.counter[high]};
        return answer;
    }

    /// use(memory) with the pair's memory as seen from i at their collision; what use leaves in
    /// it replaces the memory (its stamp is kept).
    template <class Use> auto collideWith(int i, int j, Use&& use) {
        Record& record = records_[key(i, j)];
        Memory& memory = record.memory;
        if (i > j) memory.flip();
        const auto answer = use(memory);
        if (i > j) memory.flip();
        return answer;
    }

  private:
    struct Record {
        Memory memory;
        double time = 0.0;
        std::uint64_t counterLow = 0, counterHigh = 0;
    };
    std::uint64_t key(int i, int j) const { return pairKey(i, j, particles_); }

    std::uint64_t particles_ = 0;
    PairTable<Record> records_;
};

/// Nothing to keep: the memory is an empty value, made for each use.
template <> class PairMemories<NoPairMemory> {
  public:
    void reset(int /*particles*/) {}
    template <class Use>
    auto predictWith(int /*i*/, int /*j*/, double /*t*/, ParticleClocks /*clocks*/, Use&& use) {
        NoPairMemory memory;
        return use(memory);
    }
    template <class Use> auto collideWith(int /*i*/, int /*j*/, Use&& use) {
        NoPairMemory memory;
        return use(memory);
    }
};

} // namespace sbpack

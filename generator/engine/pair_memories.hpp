#pragma once
// What the engine keeps of each pair between predictions: the shape's Memory (shapes/shape.hpp;
// the superball predictor's warm-start normal, the bound on its plane gap and its witness
// record), when it was left and both particles' collision counters then. Records survive a
// window's end in what holds whatever the motions (synchronise) and go into the checkpoint
// (records, restore). A memory is handed to the predictor as seen from
// the particle predicted (the normal from i to j) and stored as seen from the lower index. A
// shape that remembers nothing (NoPairMemory: the sphere) stores nothing and pays no lookup.

#include "engine/pair_table.hpp"
#include "shapes/pair_motion.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace sbpack {

/// The particles' collision counters and the times of their last collisions (the engine's).
struct ParticleClocks {
    const std::vector<std::uint64_t>& counter;
    const std::vector<double>& changedAt;
};

template <class Memory> class PairMemories {
  public:
    explicit PairMemories(int particles = 0) : particles_(static_cast<std::uint64_t>(particles)) {}

    /// At a synchronisation, where the particles' accumulated rotation angles were `turned` and
    /// become zero: every record keeps what its Memory keeps across one (Memory::synchronised),
    /// stamped as unchanged at time 0. The records then depend on the synchronised state alone,
    /// as the checkpoint does (records(), restore()).
    void synchronise(const std::vector<double>& turned) {
        records_.forEach([&](std::uint64_t key, Record& record) {
            const auto [low, high] = pair(key);
            record = {record.memory.synchronised(turned[low], turned[high]), 0.0, 0, 0};
        });
    }

    /// At a rebuild: keeps the records of the pairs in `lists` (its neighbour lists,
    /// `lists.of(i)`), forgets the others, and no collision is the last one any more (the
    /// rebuild's predictions start afresh).
    template <class Lists> void rebuilt(const Lists& lists) {
        PairTable<Record> kept;
        for (int i = 0; i < static_cast<int>(particles_); ++i)
            for (const int j : lists.of(i))
                if (i < j)
                    if (const Record* record = records_.find(key(i, j))) kept[key(i, j)] = *record;
        records_ = std::move(kept);
        resolvedAt_ = -std::numeric_limits<double>::infinity();
    }

    /// Every synchronised record as (i, j, memory seen from i), i < j, in ascending order.
    struct Entry {
        int i, j;
        Memory memory;
    };
    std::vector<Entry> records() const {
        std::vector<Entry> entries;
        records_.forEach([&](std::uint64_t key, const Record& record) {
            const auto [low, high] = pair(key);
            entries.push_back({low, high, record.memory});
        });
        std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
            return std::pair(a.i, a.j) < std::pair(b.i, b.j);
        });
        return entries;
    }
    /// The records of records() back, stamped as synchronise() leaves them.
    void restore(const std::vector<Entry>& entries) {
        records_.clear();
        for (const Entry& e : entries)
            records_[key(e.i, e.j)] = {e.memory, 0.0, 0, 0};
    }

    /// use(memory, resolved) with the pair's memory for a prediction of i against j at time t, as
    /// seen from i: its gap bound moved on to t while both particles still fly as they did when it
    /// was left (their counters unchanged, or advanced by one collision at t itself), else the
    /// normal alone; what use leaves in it is kept, stamped with t and the counters now.
    /// `resolved` (seen from i) where the pair's collision was the last one and at t, else null.
    template <class Use>
    auto predictWith(int i, int j, double t, ParticleClocks clocks, Use&& use) {
        const std::uint64_t k = key(i, j);
        std::optional<Resolved> resolved;
        if (k == resolvedKey_ && t == resolvedAt_)
            resolved = i > j ? resolved_.seenFromOther() : resolved_;
        Record& record = records_[k];
        const auto unchanged = [&](int k, std::uint64_t counter) {
            return clocks.counter[k] == counter ||
                   (clocks.counter[k] == counter + 1 && clocks.changedAt[k] == t);
        };
        const auto [low, high] = std::minmax(i, j);
        Memory& memory = record.memory; // used in place: no copy of the record
        if (unchanged(low, record.counterLow) && unchanged(high, record.counterHigh))
            memory.moveOn(t - record.time);
        else
            memory.forgetMotions();
        if (i > j) memory.flip();
        const auto answer = use(memory, resolved ? &*resolved : nullptr);
        if (i > j) memory.flip();
        record.time = t;
        record.counterLow = clocks.counter[low];
        record.counterHigh = clocks.counter[high];
        return answer;
    }

    /// use(memory, resolved) with the pair's memory as seen from i at their collision at time t;
    /// what use leaves in the memory replaces it (its stamp is kept), and what it leaves in
    /// `resolved` (seen from i) is handed to the pair's predictions at t (predictWith).
    template <class Use> auto collideWith(int i, int j, double t, Use&& use) {
        resolvedKey_ = key(i, j);
        resolvedAt_ = t;
        Record& record = records_[resolvedKey_];
        Memory& memory = record.memory;
        Resolved resolved;
        if (i > j) memory.flip();
        const auto answer = use(memory, resolved);
        if (i > j) memory.flip();
        resolved_ = i > j ? resolved.seenFromOther() : resolved;
        return answer;
    }

  private:
    using Resolved = typename Memory::Resolved;
    struct Record {
        Memory memory;
        double time = 0.0;
        std::uint64_t counterLow = 0, counterHigh = 0;
    };
    std::uint64_t key(int i, int j) const { return pairKey(i, j, particles_); }
    std::pair<int, int> pair(std::uint64_t key) const {
        return {static_cast<int>(key / particles_), static_cast<int>(key % particles_)};
    }

    std::uint64_t particles_ = 0;
    PairTable<Record> records_;
    /// The last collision's pair, time and contact (seen from the lower index).
    std::uint64_t resolvedKey_ = 0;
    double resolvedAt_ = -std::numeric_limits<double>::infinity();
    Resolved resolved_;
};

/// Nothing to keep: the memory is an empty value, made for each use.
template <> class PairMemories<NoPairMemory> {
  public:
    explicit PairMemories(int /*particles*/ = 0) {}
    void synchronise(const std::vector<double>& /*turned*/) {}
    template <class Lists> void rebuilt(const Lists& /*lists*/) {}
    struct Entry {
        int i, j;
        NoPairMemory memory;
    };
    std::vector<Entry> records() const { return {}; }
    void restore(const std::vector<Entry>& /*entries*/) {}
    template <class Use>
    auto predictWith(int /*i*/, int /*j*/, double /*t*/, ParticleClocks /*clocks*/, Use&& use) {
        NoPairMemory memory;
        return use(memory, static_cast<const NoPairMemory::Resolved*>(nullptr));
    }
    template <class Use> auto collideWith(int /*i*/, int /*j*/, double /*t*/, Use&& use) {
        NoPairMemory memory;
        NoPairMemory::Resolved resolved;
        return use(memory, resolved);
    }
};

} // namespace sbpack

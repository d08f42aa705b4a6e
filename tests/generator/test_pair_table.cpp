// The engine's pair table against std::unordered_map: the same records under random inserts and
// lookups, across growth and clear(); and the pair memories kept in it.
#include "engine/pair_memories.hpp"
#include "engine/pair_table.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

using namespace sbpack;

TEST(PairTable, HoldsTheSameRecordsAsAStandardMap) {
    std::mt19937_64 rng(3);
    PairTable<std::uint64_t> table;
    std::unordered_map<std::uint64_t, std::uint64_t> reference;
    for (int round = 0; round < 3; ++round) {
        // Keys as the engine forms them, min N + max for N = 5000, with many repeats.
        std::uniform_int_distribution<std::uint64_t> index(0, 4999);
        for (int k = 0; k < 200000; ++k) {
            const std::uint64_t i = index(rng), j = index(rng) % 64;
            const std::uint64_t key = std::min(i, j) * 5000 + std::max(i, j);
            if (k % 3 == 0) {
                EXPECT_EQ(table[key], reference[key]) << key; // absent: both value-initialised
            } else {
                table[key] = reference[key] = rng();
            }
        }
        EXPECT_EQ(table.size(), reference.size());
        for (const auto& [key, value] : reference)
            ASSERT_EQ(table[key], value) << key;
        EXPECT_EQ(table.size(), reference.size()); // lookups of present keys insert nothing
        table.clear();
        reference.clear();
        EXPECT_EQ(table.size(), 0u);
        EXPECT_EQ(table[12345], 0u); // a cleared record reads as new
        reference[12345];
    }
}

TEST(PairTable, FindsWithoutInsertingAndVisitsEveryRecord) {
    PairTable<int> table;
    EXPECT_EQ(table.find(7), nullptr); // an empty table
    for (int k = 0; k < 1000; ++k)
        table[static_cast<std::uint64_t>(3 * k)] = k;
    EXPECT_EQ(table.find(1), nullptr);
    ASSERT_NE(table.find(300), nullptr);
    EXPECT_EQ(*table.find(300), 100);
    EXPECT_EQ(table.size(), 1000u); // find inserts nothing
    long sum = 0;
    std::size_t visited = 0;
    table.forEach([&](std::uint64_t key, const int& value) {
        EXPECT_EQ(key, static_cast<std::uint64_t>(3 * value));
        sum += value;
        ++visited;
    });
    EXPECT_EQ(visited, 1000u);
    EXPECT_EQ(sum, 999L * 1000L / 2L);
}

// The pair records across a window's end (issue 40): what PairMemory::synchronised keeps (the
// normal and the witness, its angles counted from the new zero), the records pruned to the new
// neighbour lists, and records() / restore() as the checkpoint's round trip.
namespace {
struct Lists {
    std::vector<std::vector<int>> lists;
    const std::vector<int>& of(int i) const { return lists[i]; }
};
} // namespace

TEST(PairMemories, KeepTheNormalAndTheRebasedWitnessAcrossASynchronisation) {
    PairMemories<PairMemory> memories(4);
    const std::vector<std::uint64_t> counters(4, 0);
    const std::vector<double> changed(4, -1.0);
    const Vector3d n = Vector3d(1.0, 2.0, 2.0) / 3.0;
    for (const auto& [i, j] : {std::pair(0, 1), std::pair(3, 2), std::pair(1, 3)})
        memories.predictWith(
            i, j, 0.5, {counters, changed},
            [&](PairMemory& m, const PairMemory::Resolved* /*resolved*/) {
                m.normal = n;
                m.gap = 0.25;
                m.rate = -1.0;
                m.span = 1.0;
                m.atContact = true;
                m.witness = {Vector3d(0.1, 0.0, 0.0), Vector3d(0.0, 0.2, 0.0), 0.5 + i, 0.5 + j};
                return 0;
            });
    memories.synchronise({1.0, 2.0, 3.0, 4.0});
    memories.rebuilt(Lists{{{1}, {0}, {}, {}}}); // only the pair (0, 1) is still listed
    const auto records = memories.records();
    ASSERT_EQ(records.size(), 1u);
    EXPECT_EQ(records[0].i, 0);
    EXPECT_EQ(records[0].j, 1);
    const PairMemory& kept = records[0].memory;
    EXPECT_EQ(kept.normal, n);
    EXPECT_EQ(kept.gap, -std::numeric_limits<double>::infinity()); // the motions changed
    EXPECT_FALSE(kept.atContact);
    EXPECT_EQ(kept.witness.turnedI, 0.5 - 1.0); // turned 0.5 at the record, 1 at the window end
    EXPECT_EQ(kept.witness.turnedJ, 1.5 - 2.0);
    // Seen from j at the next prediction, and restored into another table, the same.
    PairMemories<PairMemory> restored(4);
    restored.restore(records);
    for (PairMemories<PairMemory>* table : {&memories, &restored})
        table->predictWith(1, 0, 0.0, {counters, changed},
                           [&](PairMemory& m, const PairMemory::Resolved* /*resolved*/) {
                               EXPECT_EQ(m.normal, -n);
                               EXPECT_EQ(m.witness.turnedI, 1.5 - 2.0);
                               EXPECT_EQ(m.witness.pointI, Vector3d(0.0, -0.2, 0.0));
                               return 0;
                           });
}

// The last collision's contact (issue 40, part 4): handed to the pair's predictions at that very
// time alone, from either side (mirrored for j), and no longer after a rebuild.
TEST(PairMemories, HandTheLastCollisionsContactToThePairsPredictionsAtThatTime) {
    PairMemories<PairMemory> memories(4);
    const std::vector<std::uint64_t> counters(4, 0);
    const std::vector<double> changed(4, -1.0);
    const Vector3d d(1.0, 0.0, 0.0);
    SignedDistanceResult contact;
    contact.normal = Vector3d::UnitX();
    contact.contactA = Vector3d(0.5, 0.1, 0.0);
    contact.contactB = Vector3d(0.5, 0.2, 0.0);
    memories.collideWith(2, 1, 0.75, [&](PairMemory& /*m*/, PairMemory::Resolved& resolved) {
        resolved = {d, contact}; // seen from 2
        return 0;
    });
    auto seen = [&](int i, int j, double t) {
        std::optional<PairMemory::Resolved> handed;
        memories.predictWith(i, j, t, {counters, changed},
                             [&](PairMemory& /*m*/, const PairMemory::Resolved* resolved) {
                                 if (resolved) handed = *resolved;
                                 return 0;
                             });
        return handed;
    };
    const auto fromTwo = seen(2, 1, 0.75);
    ASSERT_TRUE(fromTwo && fromTwo->contact);
    EXPECT_EQ(fromTwo->displacement, d);
    EXPECT_EQ(fromTwo->contact->contactB, contact.contactB);
    const auto fromOne = seen(1, 2, 0.75);
    ASSERT_TRUE(fromOne && fromOne->contact);
    EXPECT_EQ(fromOne->displacement, -d);
    EXPECT_EQ(fromOne->contact->normal, -contact.normal);
    EXPECT_EQ(fromOne->contact->contactA, contact.contactB - d);
    EXPECT_EQ(fromOne->contact->contactB, contact.contactA - d);
    EXPECT_FALSE(seen(1, 2, 0.8));               // another time
    EXPECT_FALSE(seen(1, 3, 0.75));              // another pair
    memories.rebuilt(Lists{{{}, {2}, {1}, {}}}); // the pair still listed, its contact forgotten
    EXPECT_FALSE(seen(1, 2, 0.75));
}

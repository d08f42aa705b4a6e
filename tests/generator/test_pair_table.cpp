// The engine's pair table against std::unordered_map: the same records under random inserts and
// lookups, across growth and clear().
#include "engine/pair_table.hpp"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

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

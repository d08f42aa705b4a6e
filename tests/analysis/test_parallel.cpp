#include "parallel/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace sbpack {
namespace {

TEST(Parallel, ThreadBudgetRejectsZeroAndTooMany) {
    EXPECT_THROW(ThreadBudget(0), std::invalid_argument);
    EXPECT_THROW(ThreadBudget(ThreadBudget::maxThreads() + 1), std::invalid_argument);
}

TEST(Parallel, SerialAndParallelVisitEveryIndexOnce) {
    const ThreadBudget budget(2);
    for (const bool serial : {true, false}) {
        LoopSchedule schedule;
        schedule.setSerial(serial);
        std::vector<std::atomic<int>> visits(1001);
        parallelFor(
            0, 1001, 7,
            [&](std::int64_t b, std::int64_t e) {
                for (std::int64_t i = b; i < e; ++i)
                    ++visits[i];
            },
            schedule);
        for (const auto& v : visits)
            ASSERT_EQ(v.load(), 1);
    }
}

TEST(Parallel, OrderedReduceFoldsInChunkOrderWhateverTheThreads) {
    // The running sum after each chunk, of terms of very different magnitudes: any other order
    // shows in the sequence and rounds differently.
    const auto term = [](std::int64_t c) { return c % 3 == 0 ? 1e16 : 1.0 + 1e-3 * c; };
    const auto add = [](std::vector<double>& seen, const std::vector<double>& part) {
        seen.push_back(seen.back() + part.front());
    };
    std::vector<double> expected{0.0};
    for (std::int64_t c = 0; c < 1000; ++c)
        expected.push_back(expected.back() + term(c));
    for (const int threads : {1, 2, 4})
        for (const bool serial : {true, false}) {
            const ThreadBudget budget(threads);
            LoopSchedule schedule;
            schedule.setSerial(serial);
            const std::vector<double> folded = orderedReduce(
                1000, std::vector<double>{0.0},
                [&](std::int64_t c) { return std::vector<double>{term(c)}; }, add, schedule);
            ASSERT_EQ(folded, expected) << threads << " threads, serial " << serial;
        }
}

TEST(Parallel, OrderedReduceOfNoChunksIsItsStart) {
    struct NoDefault { // partials need no default constructor
        explicit NoDefault(int v) : value(v) {}
        int value;
    };
    const NoDefault start = orderedReduce(
        0, NoDefault(7), [](std::int64_t) -> NoDefault { throw std::logic_error("mapped"); },
        [](NoDefault&, const NoDefault&) { throw std::logic_error("combined"); });
    EXPECT_EQ(start.value, 7);
    const NoDefault sum = orderedReduce(
        5, NoDefault(1), [](std::int64_t c) { return NoDefault(static_cast<int>(c)); },
        [](NoDefault& total, const NoDefault& part) {
            total.value = 10 * total.value + part.value;
        });
    EXPECT_EQ(sum.value, 101234);
}

} // namespace
} // namespace sbpack

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
        std::vector<std::atomic<int>> visits(1001);
        parallelFor(
            0, 1001, 7,
            [&](std::int64_t b, std::int64_t e) {
                for (std::int64_t i = b; i < e; ++i)
                    ++visits[i];
            },
            serial);
        for (const auto& v : visits)
            ASSERT_EQ(v.load(), 1);
    }
}

} // namespace
} // namespace sbpack

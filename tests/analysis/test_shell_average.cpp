#include "shells/shell_average.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sbpack {
namespace {

TEST(ShellAverage, ShellsHoldTheVectorsOfRoundedLength) {
    // Every integer vector with |n| < s_max + 1/2, once, with value |n|: counts and means
    // against a direct count per shell.
    const int maxShell = 6;
    const double boxLength = 3.0;
    ShellAccumulator shells(boxLength, maxShell);
    const std::int64_t maxN2 = maxSquaredIndex(maxShell);
    std::vector<std::int64_t> expectedCount(maxShell + 1, 0);
    for (int x = -maxShell; x <= maxShell; ++x)
        for (int y = -maxShell; y <= maxShell; ++y)
            for (int z = -maxShell; z <= maxShell; ++z) {
                const std::int64_t n2 = x * x + y * y + z * z;
                if (n2 == 0 || n2 > maxN2) continue;
                const double n = std::sqrt(static_cast<double>(n2));
                ++expectedCount[static_cast<int>(std::floor(n + 0.5))];
                shells.add(n2, n, 1);
            }
    const ShellAverage average = shells.average();
    ASSERT_EQ(average.size(), static_cast<std::size_t>(maxShell));
    EXPECT_EQ(average.count[0], 18); // 6 of |n| = 1, 12 of |n| = sqrt 2
    for (int s = 1; s <= maxShell; ++s) {
        EXPECT_EQ(average.count[s - 1], expectedCount[s]);
        EXPECT_NEAR(average.value[s - 1], s, 0.5);
        EXPECT_NEAR(average.q[s - 1], 2.0 * std::numbers::pi * average.value[s - 1] / boxLength,
                    1e-12);
    }
}

TEST(ShellAverage, WeightsAndMergesAreExact) {
    ShellAccumulator a(2.0, 2), b(2.0, 2);
    a.add(1, 3.0, 2); // shell 1
    b.add(2, 6.0, 1); // shell 1 (|n| = 1.41)
    b.add(4, 5.0, 2); // shell 2
    a.merge(b);
    const ShellAverage average = a.average();
    EXPECT_EQ(average.count[0], 3);
    EXPECT_DOUBLE_EQ(average.value[0], (2 * 3.0 + 6.0) / 3);
    EXPECT_DOUBLE_EQ(average.value[1], 5.0);
    EXPECT_THROW(a.add(7, 1.0, 1), std::out_of_range); // |n| = 2.65 rounds to shell 3
    EXPECT_THROW(a.add(0, 1.0, 1), std::out_of_range);
    EXPECT_THROW(ShellAccumulator(2.0, 0), std::invalid_argument);
    ShellAccumulator empty(2.0, 1);
    EXPECT_THROW(empty.average(), std::logic_error);
}

} // namespace
} // namespace sbpack

// The slow phase's stall watch (protocol/stall_watch.hpp, docs/design.md §3, "Jam check on the
// way" and "Plateaus"): when it checks the jam, what it counts as a doubling, and when a stall is
// a plateau.
#include "protocol/stall_watch.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sbpack {
namespace {

/// The windows (counted from 1) after which the watch checks the jam over `windows` windows of
/// constant pressure, and whether each check found a plateau (a doubling takes
/// `expectedDoubling` windows by the cost model).
std::vector<std::pair<int, bool>> checksAtConstantPressure(StallWatch& watch, int windows,
                                                           double expectedDoubling) {
    std::vector<std::pair<int, bool>> checks;
    for (int w = 1; w <= windows; ++w) {
        watch.observe(watch.stallPressure);
        if (watch.checkDue()) checks.emplace_back(w, watch.plateau(expectedDoubling));
    }
    return checks;
}

TEST(StallWatch, APressureThatDoublesIsNeverCheckedAndItsLongestDoublingIsKept) {
    StallWatch watch;
    double pressure = 1e6;
    for (int doubling = 0; doubling < 40; ++doubling)
        for (int w = 1; w <= 10 + doubling; ++w) { // each doubling one window longer
            watch.observe(w == 10 + doubling ? 2.0 * pressure : pressure);
            EXPECT_FALSE(watch.checkDue());
            if (w == 10 + doubling) pressure *= 2.0;
        }
    EXPECT_EQ(watch.longestDoubling, 49);
    EXPECT_EQ(watch.stalledWindows, 0);
    EXPECT_EQ(watch.stallPressure, pressure);
}

TEST(StallWatch, AStallIsCheckedAtPowersOfTwoAndIsAPlateauPastFourLongestDoublings) {
    // No doubling recorded (a fresh slow phase, or a checkpoint from before the watch kept it):
    // the cost model's doubling stands for the longest, 50 windows here.
    StallWatch fresh{0, 1e8, 0};
    const std::vector<std::pair<int, bool>> expected = {
        {50, false}, {100, false}, {200, true}, {400, true}};
    EXPECT_EQ(checksAtConstantPressure(fresh, 400, 50.0), expected);
    // Superballs at gamma_slow 1e-2 (51.2 windows by the model): four of them, 204.8, come
    // after the check at 200.
    StallWatch superballs{0, 1e8, 0};
    EXPECT_EQ(checksAtConstantPressure(superballs, 200, 51.2).back(), std::make_pair(200, false));
    // A run whose doublings took up to 300 windows: a plateau from 1200, checked at 1600.
    StallWatch slow{0, 1e8, 300};
    const std::vector<std::pair<int, bool>> later = {{50, false},  {100, false}, {200, false},
                                                     {400, false}, {800, false}, {1600, true}};
    EXPECT_EQ(checksAtConstantPressure(slow, 1600, 50.0), later);
    // Spheres at 1e-4 (about 1440 windows by the model): not before 5760 windows.
    StallWatch spheres{0, 1e8, 0};
    EXPECT_FALSE(checksAtConstantPressure(spheres, 3200, 1440.0).back().second);
}

// docs/design.md §3, "Plateaus": raised only from 1e10 and the switch pressure on.
TEST(StallWatch, APlateauIsRaisedOnlyWhereTheRateNoLongerShapesThePacking) {
    EXPECT_FALSE(StallWatch::raisable(1.77e6, 1e6)); // p = 2 seed 1's creep: Z 0.145 lower
    EXPECT_FALSE(StallWatch::raisable(9.9e9, 1e6));
    EXPECT_TRUE(StallWatch::raisable(1e10, 1e6));
    EXPECT_TRUE(StallWatch::raisable(2.5e10, 1e6));   // p = 5 seed 2's plateau
    EXPECT_FALSE(StallWatch::raisable(2.5e10, 5e11)); // below a switch pressure above P*
}

TEST(StallWatch, ARestartBeginsANewStallFromItsPressure) {
    StallWatch watch{250, 1e8, 60};
    watch.restart(1.5e8);
    EXPECT_EQ(watch.stalledWindows, 0);
    watch.observe(2.9e8); // not twice 1.5e8
    EXPECT_EQ(watch.stalledWindows, 1);
    watch.observe(3.0e8);
    EXPECT_EQ(watch.stalledWindows, 0);
    EXPECT_EQ(watch.longestDoubling, 60); // two windows: shorter than the longest
}

} // namespace
} // namespace sbpack

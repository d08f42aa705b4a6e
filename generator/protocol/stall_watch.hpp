#pragma once
// The slow phase's stall watch (docs/design.md §3, "Jam check on the way" and "Plateaus"): it
// counts the windows since the sustained reduced pressure last doubled, and remembers the most
// windows any doubling took. The jam is checked at 1, 2, 4, ... times kCheckWindows stalled
// windows; a plateau whose check says jammed raises the growth rate once the stall has lasted
// kRaiseRatio times the run's longest doubling, or the cost model's doubling if longer, where
// the rate no longer shapes the contact network (raisable).

#include <algorithm>
#include <cstdint>

namespace sbpack {

/// A watch that has counted `count` windows checks the jam at base, 2 base, 4 base, ... windows.
inline bool dueAt(std::int64_t count, std::int64_t base) {
    const std::int64_t multiple = count / base;
    return count % base == 0 && multiple > 0 && (multiple & (multiple - 1)) == 0;
}

struct StallWatch {
    /// The first jam check of a stall, in windows (then at 2, 4, 8, ... times as many).
    static constexpr std::int64_t kCheckWindows = 50;
    /// A stall this many times the run's longest doubling is a plateau (docs/design.md §3,
    /// "Plateaus": the doublings of p = 5 seed 2 took 70-520 windows, its plateau over 1900).
    static constexpr std::int64_t kRaiseRatio = 4;
    /// The least sustained pressure at which a plateau is raised: below the plateaus whose raise
    /// was measured to end like the unraised seeds (2.5e10-1.5e11, p = 5 and 10); lower down a
    /// creep is the slow rate's own climb and a raise costs Z (bench/RESULTS.md, "The plateau
    /// rule's lower bound": p = 2 seed 1 raised at 1.8e6 ends 0.145 lower).
    static constexpr double kLeastRaisedPressure = 1e10;

    /// Whether a plateau at the sustained pressure `sustained` may be raised: at or above both
    /// the switch pressure and kLeastRaisedPressure.
    static bool raisable(double sustained, double pressureSwitch) {
        return sustained >= std::max(pressureSwitch, kLeastRaisedPressure);
    }

    /// Slow-phase windows since the sustained pressure last doubled (reached twice
    /// stallPressure).
    std::int64_t stalledWindows = 0;
    double stallPressure = 0.0;
    /// The most windows a doubling of this run's slow phase took (0: none recorded yet, as in a
    /// checkpoint written before sbgen kept it).
    std::int64_t longestDoubling = 0;

    /// After a slow-phase window whose sustained pressure is `sustained`.
    void observe(double sustained) {
        if (sustained >= 2.0 * stallPressure) {
            if (stallPressure > 0.0 && stalledWindows + 1 > longestDoubling)
                longestDoubling = stalledWindows + 1;
            stallPressure = sustained;
            stalledWindows = 0;
        } else {
            ++stalledWindows;
        }
    }
    /// Whether the jam is checked after this window.
    bool checkDue() const { return dueAt(stalledWindows, kCheckWindows); }
    /// Whether the stall has lasted long enough to be a plateau (checked at checkDue()), given
    /// the windows a doubling takes at the present rate by the cost model
    /// (expectedWindowsPerDoubling: the run's own doublings are not known before its first).
    bool plateau(double expectedDoubling) const {
        const double longest = std::max(static_cast<double>(longestDoubling), expectedDoubling);
        return static_cast<double>(stalledWindows) >= kRaiseRatio * longest;
    }
    /// After the growth rate was raised at `sustained`: a new stall starts from there.
    void restart(double sustained) {
        stallPressure = sustained;
        stalledWindows = 0;
    }
};

} // namespace sbpack

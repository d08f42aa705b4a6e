#pragma once
// The contact forces' windows (docs/jamming.md, "Contact forces"): the momentum each pair
// exchanged in a run's last windows, each window's in units of its kT, from which the packing's
// time-averaged contact forces are made when it is written. Two blocks of windows, the one
// before and the one being filled, bound the memory to two sums per pair whatever their length;
// a block ends at the run's windows numbered by multiples of `blockWindows`, so which windows
// are kept depends on the run's window count alone (a resumed run's is the same).

#include "engine/contact_impulses.hpp"
#include "packing/packing.hpp"

#include <cstdint>
#include <map>
#include <utility>

namespace sbpack {

/// The sums over a block of windows.
struct ForceBlock {
    std::int64_t windows = 0;
    double duration = 0.0;         ///< sbgen's time
    double pressureDuration = 0.0; ///< sum of each window's reduced pressure times its duration
    std::map<std::pair<int, int>, PairImpulse> pairs; ///< impulses over each window's kT
};

/// The last windows pushed in a row: those after the run's window numbered by the last multiple
/// of blockWindows but one, at most 2 blockWindows - 1.
class ForceWindows {
  public:
    explicit ForceWindows(std::int64_t blockWindows) : blockWindows_(blockWindows) {}

    /// Adds the window just run, the run's window number `window`, its impulses in sbgen's
    /// units and kT the window's (the one of its reduced pressure, docs/design.md §3); at a
    /// multiple of blockWindows the block becomes the previous one.
    void push(const ContactImpulses& impulses, double duration, double kT, double reducedPressure,
              std::uint64_t window);
    void clear() { previous_ = current_ = {}; }
    bool empty() const { return previous_.windows + current_.windows == 0; }

    /// The forces over the windows kept (docs/jamming.md, "Contact forces"), with the contact
    /// points from `packing`'s centres: per pair F = (sum_w sum J n / kT_w) / sum_w T_w, so
    /// f = |F| D in kT / D along n = F / |F|, at x = r_i + sum J (x - r_i) / sum J.
    ContactForces forces(const Packing& packing) const;

  private:
    std::int64_t blockWindows_;
    ForceBlock previous_, current_;
};

} // namespace sbpack

#pragma once
// The growing diameter D(t) = D_base + gamma (elapsed + t), t being engine time since the last
// synchronisation (docs/design.md §3). The growth clock `elapsed` is kept apart from the base size
// and folded into it only once it is large (2^-20 D), so the tiny growth steps near jamming are
// never lost to the rounding of D (the stall of `R += dR` near reduced pressure 1e13).

#include <cmath>

namespace sbpack {

struct GrowthClock {
    double baseDiameter = 1.0;
    double elapsed = 0.0; ///< growth time not yet folded into baseDiameter
    double rate = 0.0;    ///< gamma = dD/dt

    double diameter(double t = 0.0) const { return baseDiameter + rate * (elapsed + t); }

    /// Moves the time origin forward by t (a synchronisation).
    void advance(double t) {
        elapsed += t;
        if (rate * elapsed > std::ldexp(baseDiameter, -20)) rebase();
    }

    void setRate(double gamma) {
        rebase();
        rate = gamma;
    }

  private:
    void rebase() {
        baseDiameter = diameter();
        elapsed = 0.0;
    }
};

} // namespace sbpack

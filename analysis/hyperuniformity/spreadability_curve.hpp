#pragma once
// The excess spreadability of periodic boxes as an exact lattice sum (paper Eq. 21,
// eq:FT_spread, docs/design.md §5): with int d^3Q / (2 pi)^3 -> (1 / V) sum_Q on the box's wave
// vectors,
//   E(t) = S(inf) - S(t) = (1 / (phi V)) sum_{Q != 0} chi_V(Q) exp(-Q^2 D_diff t),
// exp(-Q^2 D_diff t) being the Fourier transform of the diffusion kernel (4 pi D_diff t)^{-3/2}
// exp(-r^2 / (4 D_diff t)). Time in units of w^2 / D_diff (w the mean width): t below means t
// D_diff / w^2 and Q^2 D_diff t = (Q w)^2 t. Its logarithmic derivative needs no finite
// differences:
//   nu(t) = d ln E / d ln t = -t <(Q w)^2>_t, weights chi_V(Q) exp(-(Q w)^2 t),
//   d nu / d ln t = nu + t^2 Var_t((Q w)^2).
// Several boxes (an ensemble) pool as the mean of their E(t).

#include "hyperuniformity/discrete_spectrum.hpp"

#include <span>
#include <vector>

namespace sbpack {

class SpreadabilityCurve {
  public:
    /// At one time: ln E, the local exponent nu and its slope d nu / d ln t.
    struct Point {
        double logExcess;
        double exponent;
        double exponentSlope;
    };

    /// Throws std::invalid_argument if there is no member, or a member has phi outside (0, 1),
    /// a non-positive box or width, or no positive weight.
    explicit SpreadabilityCurve(std::span<const DiscreteSpectrum> members);

    /// ln E, nu and d nu / d ln t at t >= 0 (ln E at t = 0 is that of the sum rule).
    Point at(double t) const;
    double excess(double t) const;
    /// Bound on what the wave vectors left out add to E(t): the mean over members of
    /// missingWeight exp(-(cutoffQ w)^2 t) (every one left out has |Q| >= cutoffQ).
    double truncationBound(double t) const;
    /// t_c = 1 / (Q_min w)^2 = (L / (2 pi w))^2, the smallest over the members: beyond it the
    /// box's smallest wave vector dominates and E decays exponentially.
    double cutoffTime() const { return cutoffTime_; }
    std::size_t members() const { return members_.size(); }

  private:
    /// One box: (Q w)^2 of each |n|^2 with a positive sum (ascending) and its weight
    /// sum chi / (phi V) (dimensionless).
    struct Member {
        std::vector<double> q2, weight;
        double missingWeight, cutoffQ2;
    };
    /// ln of sum w e^{-q2 t}, and the mean and variance of q2 under those weights.
    struct Moments {
        double logSum, mean, variance;
    };
    static Moments moments(const Member& m, double t);

    std::vector<Member> members_;
    double cutoffTime_ = 0.0;
};

} // namespace sbpack

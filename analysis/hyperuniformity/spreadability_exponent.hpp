#pragma once
// The hyperuniformity exponent alpha from the long-time decay of the excess spreadability,
// E(t) ~ t^{-(3 + alpha)/2} (paper Eq. PLF; docs/hyperuniformity.md, "alpha"). In a window
// [t_1, t_2] the local exponent alpha(t) = -3 - 2 d ln E / d ln t still carries the finite-time
// correction of chi_V = a1 Q^alpha (1 + b Q^2 + ...): alpha(t) = alpha + c / t + O(1/t^2). alpha
// is the straight line of alpha(t) against 1/t through the window, taken at 1/t = 0; the window's
// mean local alpha (the paper's estimate),
//   -3 - 2 ln(E(t_2) / E(t_1)) / ln(t_2 / t_1),
// is kept beside it. On fixtures with known exponents the mean is biased by -0.33 (perturbed
// lattices, alpha = 2) and +0.25 (RSA, alpha = 0), the extrapolation by -0.09 and +0.07, within
// its uncertainty, a Poisson bootstrap over the wave vectors (each one's chi_V is a random
// variable around its mean): bench/RESULTS.md, "alpha on fixtures with known exponents". Times
// are t D_diff / w^2.
//
// The window the code finds: it starts when the peak of chi_V has decayed away,
// t_1 = kPeakDecay / (Q_peak w)^2 (the microscopic transient: the wave vectors near the peak
// weigh exp(-(Q_peak w)^2 t) = e^{-10} of what they did), and ends at t_2 = t_c / 4, with
// t_c = 1 / (Q_min w)^2 the finite box's cutoff, beyond which the lattice sum drifts from the
// continuum and the decay turns exponential.

#include "hyperuniformity/discrete_spectrum.hpp"
#include "hyperuniformity/spreadability_curve.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace sbpack {

struct ExponentWindow {
    double tMin = 0.0;
    double tMax = 0.0;
};

/// (Q_peak w)^2 t at which the window starts.
inline constexpr double kPeakDecay = 10.0;
/// The window ends at t_c / kCutoffFraction.
inline constexpr double kCutoffFraction = 4.0;
/// A window narrower than this many decades in t gives no alpha.
inline constexpr double kMinWindowDecades = 0.2;

/// The window above for the curve's cutoff time and the peak at Q_peak w = peakQw. Throws
/// std::domain_error when it is narrower than kMinWindowDecades (the box is too small, or
/// the grid too coarse, for a long-time regime), naming both ends.
ExponentWindow findExponentWindow(const SpreadabilityCurve& curve, double peakQw);

/// The window's mean local alpha, -3 - 2 ln(E(t_2) / E(t_1)) / ln(t_2 / t_1), of a curve or of
/// any ln E(t) (e.g. a continuum reference).
double windowExponent(const SpreadabilityCurve& curve, const ExponentWindow& window);
double windowExponent(const std::function<double(double)>& logExcess, const ExponentWindow& window);

/// Time points of the extrapolation in a window (log-spaced, ends included).
inline constexpr int kExtrapolationPoints = 24;

/// The least-squares line local alpha = alpha + slope / t of the local alpha,
/// -3 - 2 d ln E / d ln t (exact, SpreadabilityCurve::at), at kExtrapolationPoints log-spaced
/// times of the window: alpha is its value at 1/t = 0.
struct ExponentLine {
    double alpha = 0.0, slope = 0.0;
};
ExponentLine extrapolatedExponent(const SpreadabilityCurve& curve, const ExponentWindow& window);

/// The same from E sampled at times t (ascending; e.g. an ensemble's mean E(t)): the local
/// alpha of each pair of neighbouring samples inside the window, at their geometric mean time.
/// Throws std::domain_error if fewer than three samples lie in the window.
ExponentLine sampledExponent(const std::vector<double>& t, const std::vector<double>& excess,
                             const ExponentWindow& window);

struct ExponentEstimate {
    double alpha = 0.0; ///< extrapolatedExponent
    double slope = 0.0; ///< ... and its line's slope in 1/t
    /// Standard deviation of alpha over the bootstrap replicas (0 when replicas = 0).
    double standardError = 0.0;
    int replicas = 0;
    /// The least and largest alpha over the windows that end at t_2 / 2, t_2 and 2 t_2 (same
    /// t_1): how much alpha owes to where the window ends.
    double endLow = 0.0, endHigh = 0.0;
    /// windowExponent, the paper's estimate, and its standard deviation over the same replicas.
    double windowMean = 0.0, windowMeanError = 0.0;
};

/// alpha (and the window's mean) of the pooled members in `window` from their `curve`
/// (SpreadabilityCurve(members), made once by the caller), with the Poisson bootstrap: each wave
/// vector listed
/// one by one (DiscreteSpectrum::modes) is weighted by an independent Poisson(1) count in each
/// replica (seeded; the same seed gives the same result).
ExponentEstimate estimateExponent(const SpreadabilityCurve& curve,
                                  std::span<const DiscreteSpectrum> members,
                                  const ExponentWindow& window, int replicas,
                                  std::uint64_t seed = 1);

} // namespace sbpack

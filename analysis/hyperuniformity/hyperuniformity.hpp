#pragma once
// The paper's hyperuniformity analysis of one spectrum or a pooled ensemble (Sec. II A, V B;
// docs/hyperuniformity.md): the excess spreadability E(t) as a lattice sum over the box's wave
// vectors (spreadability_curve.hpp), its local exponent, alpha from the long-time window with a
// bootstrap error (spreadability_exponent.hpp), the fit a0 + a1 Q^alpha at that alpha and the
// free fit (small_q_fit.hpp), H = a0 / chi_V(Q_peak), and the Debye medium on the same time axis
// (debye_medium.hpp).

#include "hyperuniformity/discrete_spectrum.hpp"
#include "hyperuniformity/small_q_fit.hpp"
#include "hyperuniformity/spreadability_exponent.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace sbpack {

struct HyperuniformityParameters {
    /// Times t D_diff / w^2, log-spaced from tMin to tMax, pointsPerDecade per decade.
    double tMin = 1e-3, tMax = 1e4;
    int pointsPerDecade = 20;
    /// The fit of chi_V over 0 < Q w <= fitQmaxW (the paper's 1.4).
    double fitQmaxW = 1.4;
    /// Bootstrap replicas of alpha (0: none).
    int replicas = 200;
    std::uint64_t seed = 1;
    /// The alpha window, t D_diff / w^2; unset: found (findExponentWindow).
    std::optional<ExponentWindow> window;
    /// The hyper stage's spectrum: chi_V exact (ExactSpectralDensity, no voxels) at Q w <= this,
    /// where the fit and alpha read it, the voxel grid's beyond; 0: the voxel grid's alone.
    double chiExactQw = ExactSpectralDensityParameters{}.maxQw;
};

/// The principal peak of chi_V (from a shell average), in the paper's units.
struct SpectralPeak {
    double qw = 0.0;  ///< Q_peak w
    double chi = 0.0; ///< chi_V(Q_peak) / w^3
};

struct HyperuniformityResult {
    HyperuniformityParameters parameters;
    std::vector<double> t;             ///< t D_diff / w^2
    std::vector<double> excess;        ///< E(t) = S(inf) - S(t)
    std::vector<double> localExponent; ///< nu = d ln E / d ln t
    std::vector<double> localAlpha;    ///< -3 - 2 nu
    std::vector<double> truncation;    ///< bound on what the omitted wave vectors add to E(t)
    std::vector<double> debyeExcess;   ///< Debye medium of the same phi at t D_diff / a^2 = t
    double cutoffTime = 0.0;           ///< t_c D / w^2
    ExponentWindow window;
    ExponentEstimate alpha;
    PowerLawFit fit;     ///< at alpha.alpha
    SmallQPoints fitted; ///< the wave vectors it fits
    FreeFit freeFit;
    SpectralPeak peak;
    double h = 0.0; ///< a0 / chi_peak
    IndexSpread hSpread;
    double runtimeSeconds = 0.0;
};

class Hyperuniformity {
  public:
    /// Throws std::invalid_argument unless 0 < tMin < tMax, pointsPerDecade >= 1,
    /// fitQmaxW > 0, replicas >= 0 and a given window has 0 < tMin < tMax.
    explicit Hyperuniformity(HyperuniformityParameters parameters);

    /// The analysis of `members` pooled (one member: one box): E(t) is their mean, and the fits
    /// of chi_V take the wave vectors of every member together. Throws std::domain_error when
    /// there is no alpha window, a given one ends past the box's cutoff time, or the fit window
    /// holds wave vectors at one |Q| only (the box or the grid is too small; the message names
    /// the option to change).
    HyperuniformityResult compute(std::span<const DiscreteSpectrum> members,
                                  const SpectralPeak& peak) const;

    const HyperuniformityParameters& parameters() const { return parameters_; }

  private:
    HyperuniformityParameters parameters_;
};

/// chi_V of individual wave vectors (modePoints) averaged in bins of Q w of width `binWidthQw`
/// (bin k: [k, k + 1) times the width), in units of w.
struct ChiBin {
    double qw = 0.0;  ///< the mean Q w of its wave vectors
    double chi = 0.0; ///< their mean chi_V / w^3
    int modes = 0;    ///< wave vectors (one of each +-Q)
};
std::vector<ChiBin> binnedChi(const SmallQPoints& points, double binWidthQw);
/// The bin of largest mean chi_V (`bins` not empty).
const ChiBin& largestBin(const std::vector<ChiBin>& bins);

/// The principal peak of chi_V from `bins`: the top of the least-squares Gaussian (a parabola in
/// ln chi_V) through the bins within `halfWidthQw` of the largest mean, weighted by their wave
/// vectors, which the bins' scatter does not bias upward as their maximum is; the largest bin
/// itself where the parabola is not concave or its vertex leaves that range.
SpectralPeak fittedPeak(const std::vector<ChiBin>& bins, double halfWidthQw);

/// The peak H is divided by (paper Eq. HX; docs/hyperuniformity.md, "Fit and H"): fittedPeak
/// over bins of Q w kPeakBinQw within kPeakHalfWidthQw of the largest.
inline constexpr double kPeakBinQw = 0.05;
inline constexpr double kPeakHalfWidthQw = 0.4;
SpectralPeak principalPeak(const DiscreteSpectrum& s);

} // namespace sbpack

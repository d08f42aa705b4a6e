#pragma once
// The small-Q fit chi_V(Q) = a0 + a1 Q^alpha (paper Eq. fit) and the hyperuniformity index
// H = chi_V(0) / chi_V(Q_peak) (Eq. HX) with a0 as chi_V(0) (docs/hyperuniformity.md, "Fit and
// H"). Least squares over the individual wave vectors with 0 < Q w <= qMaxW (each one of a pair
// +-n), in the paper's units: Q w and chi_V / w^3. a0 is reported as fitted, never clamped.

#include "hyperuniformity/discrete_spectrum.hpp"

#include <limits>
#include <vector>

namespace sbpack {

struct SmallQPoints {
    std::vector<double> qw;  ///< Q w
    std::vector<double> chi; ///< chi_V / w^3

    /// Those with Q w <= qMaxW.
    SmallQPoints upTo(double qMaxW) const;
    void append(const SmallQPoints& other);
};

/// The wave vectors `spectrum` lists one by one (its modes, up to its individualQw) with
/// 0 < Q w <= qMaxW (default: every one), in units of w.
SmallQPoints modePoints(const DiscreteSpectrum& spectrum,
                        double qMaxW = std::numeric_limits<double>::infinity());

/// The same for the small-Q fit, which must not reach beyond them. Throws
/// std::domain_error if qMaxW reaches beyond them (the message names the options to change).
SmallQPoints smallQPoints(const DiscreteSpectrum& spectrum, double qMaxW);

struct PowerLawFit {
    double alpha = 0.0;
    double a0 = 0.0, a1 = 0.0;           ///< w^3 and w^{3 + alpha}
    double a0Error = 0.0, a1Error = 0.0; ///< standard errors of least squares
    double residual = 0.0;               ///< sum of squared residuals
    int points = 0;
};

/// a0, a1 at fixed alpha (linear least squares). Throws std::domain_error where the points lie at
/// one |Q| (a0 and a1 not determined) or are fewer than 3 (the message names --fit-qmax).
PowerLawFit fitFixedExponent(const SmallQPoints& points, double alpha);

/// The free three-parameter fit: alpha scanned over [0, 4] by 0.005, a0 and a1 linear at each.
/// alphaLow and alphaHigh bound the alphas whose residual is within a factor 1 + 1 / (n - 3) of the
/// least (about one standard deviation); `degenerate` when that range exceeds 0.5 or the least is
/// at an end of the scan: the data do not fix alpha.
struct FreeFit {
    PowerLawFit best;
    double alphaLow = 0.0, alphaHigh = 0.0;
    bool degenerate = false;
};
FreeFit fitFreeExponent(const SmallQPoints& points);

/// H for the fit windows (0, f qMaxW] with f in kWindowFactors: the spread of H with the window
/// (the paper's p = 1.5 example moves the upper end from 1.16 to 2.07 at qMaxW = 1.4).
struct IndexSpread {
    double hMin = 0.0, hMax = 0.0;
};
inline constexpr double kWindowFactors[] = {0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5};
/// `points` must reach 1.5 qMaxW.
IndexSpread indexSpread(const SmallQPoints& points, double qMaxW, double alpha, double chiPeak);

} // namespace sbpack

#pragma once
// The local volume-fraction variance sigma_V^2(R) of spherical windows of radius R
// (docs/local-structure.md §2; Zachary and Torquato 2009; Torquato, Phys. Rep. 745 (2018)), by
// two independent routes:
//   (a) sampled: windows centred at random in the periodic box, the solid voxel centres inside
//       each counted on the voxel grid, the variance of their fraction about phi_voxel with a
//       batch-means error bar;
//   (b) spectral: sigma_V^2(R) = (1 / V) sum_{Q != 0} chi_V(Q) F(Q R)^2, F(x) = 3 (sin x -
//       x cos x) / x^3 the window's form factor over its volume (the lattice sum of
//       int d^3Q / (2 pi)^3 chi_V(Q) |m(Q; R)|^2 / v(R)^2), over the box's wave vectors.
// For chi_V ~ Q^alpha at small Q, sigma_V^2 ~ R^-(3 + alpha) for alpha < 1 and R^-4 beyond: the
// tail gives a second estimate of alpha (below 1) beside the spreadability's.

#include "hyperuniformity/discrete_spectrum.hpp"
#include "progress/progress.hpp"
#include "voxels/voxelization.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sbpack {

struct VarianceParameters {
    /// Window radii R / w: minRadiusW 10^(k / radiiPerDecade), k = 0, 1, ..., up to L / (2 w).
    double minRadiusW = 0.5;
    int radiiPerDecade = 24;
    /// Random windows per radius of the sampled route (--variance-windows); 0: spectral only.
    int windows = 1000;
    /// Batches of the sampled route's error bar (batch means of the squared deviations).
    int batches = 20;
    std::uint64_t seed = 1;
    /// The tail fit over fitMinRadiusW w <= R <= L / 4.
    double fitMinRadiusW = 2.0;
};

/// The tail's exponent: sigma_V^2 = A R^-(3 + alpha) + B R^-4 fitted to the spectral route.
struct VarianceExponent {
    double alpha = 0.0;
    double standardError = 0.0; ///< half the profile interval (docs/local-structure.md §2)
    /// The best fit is the grid's top, just below 1: the surface term R^-4 dominates, alpha >= 1.
    bool saturated = false;
    double minRadius = 0.0; ///< the radii fitted (length)
    double maxRadius = 0.0;
    int points = 0;
};

struct VarianceResult {
    std::vector<double> radius;               ///< R (length)
    std::vector<double> spectral;             ///< sigma_V^2 by the spectral route
    std::vector<double> truncation;           ///< bound on what the wave vectors left out add to it
    std::vector<double> sampled;              ///< by the sampled route (empty without windows)
    std::vector<double> sampledError;         ///< its standard error (batch means)
    std::optional<VarianceExponent> exponent; ///< of the spectral route; none below 4 radii
    std::string spectrumSource;
    double phi = 0.0; ///< the phi the spectral route's spectrum is normalised by
    int windows = 0;
    double runtimeSeconds = 0.0;
};

/// F(x) = 3 (sin x - x cos x) / x^3, the Fourier transform of a sphere of radius R over its
/// volume at x = Q R (its Taylor series below x = 0.1).
double sphereWindowFactor(double x);

/// sigma_V^2(R) by the spectral route over the wave vectors of `spectrum`.
double spectralVariance(const DiscreteSpectrum& spectrum, double radius);

/// The tail fit sigma^2 = A R^-(3 + alpha) + B R^-4 over the radii in [minRadius, maxRadius]
/// (docs/local-structure.md §2); none below four radii there.
std::optional<VarianceExponent> fitVarianceTail(std::span<const double> radius,
                                                std::span<const double> sigma2, double minRadius,
                                                double maxRadius);

/// The radii of `parameters` for a box of edge L and particles of mean width w.
std::vector<double> windowRadii(double boxLength, double meanWidth,
                                const VarianceParameters& parameters);

/// Compute object (docs/design.md §7).
class VolumeFractionVariance {
  public:
    /// Throws std::invalid_argument unless minRadiusW > 0, radiiPerDecade >= 1, windows >= 0,
    /// batches >= 2 (where windows > 0) and windows >= batches.
    explicit VolumeFractionVariance(VarianceParameters parameters);

    /// Both routes at windowRadii: the spectral route over `spectrum`, the sampled route over
    /// `voxels` (none where it is nullptr or windows is 0). Throws std::invalid_argument where
    /// the spectrum's box or width is not positive, or the voxels' box is not the spectrum's.
    VarianceResult compute(const DiscreteSpectrum& spectrum, const Voxelization* voxels,
                           const Progress& progress) const;

    /// Bytes the sampled route holds at M voxels per side (row prefix sums and the mask).
    static double memoryBytes(int voxels);

    const VarianceParameters& parameters() const { return parameters_; }

  private:
    VarianceParameters parameters_;
};

} // namespace sbpack

#pragma once
// Exact spectral density chi_V(Q) of a packing at individual wave vectors, without voxels (paper
// Eq. 12, eq:spD, with each particle's own form factor): chi_V(Q) = |sum_j m(R_j^T Q; R)
// exp(-i Q.r_j)|^2 / V at Q = 2 pi n / L != 0. Spheres by the collective-density kernel of S(Q)
// times the sphere's closed form; any p by the superball form factor's series in each particle's
// body frame. The values at individual wave vectors, not shell averages, are what the
// hyperuniformity fits and the spreadability sum use (docs/design.md §5).

#include "packing/packing.hpp"
#include "progress/progress.hpp"
#include "shells/shell_average.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sbpack {

/// chi_V at one wave vector of each pair +-n (chi_V(-Q) = chi_V(Q)): the half space n_x > 0, or
/// n_x = 0 and n_y > 0, or n_x = n_y = 0 and n_z > 0; ordered by |n|^2, then by n.
struct WaveVectorSpectrum {
    double boxLength = 0.0;
    /// Every wave vector with 1 <= |n|^2 <= maxN2 is listed (the largest listed |n|^2 can be
    /// less: not every integer is a sum of three squares).
    std::int64_t maxN2 = 0;
    std::vector<std::array<int, 3>> n;
    std::vector<double> chi; ///< length^3

    std::size_t size() const { return n.size(); }
    std::int64_t n2(std::size_t i) const { return squaredIndex(n[i]); }
};

/// Every n of the half space with 1 <= |n|^2 <= maxN2, in WaveVectorSpectrum's order.
std::vector<std::array<int, 3>> halfSpaceWaveVectors(std::int64_t maxN2);

/// Shells 1..maxShell (shells/shell_average.hpp) of the wave vectors with
/// |n|^2 <= maxSquaredIndex(maxShell), each standing for +-n. Throws std::invalid_argument if
/// the spectrum does not reach that far.
ShellAverage shellAverage(const WaveVectorSpectrum& spectrum, int maxShell);

/// Whether the exact chi_V of `packing` sums each particle's form factor
/// (formFactorWaveVectors): every packing but one of identical spheres, which takes the collective
/// density and one closed form (sphereWaveVectors).
bool sumsFormFactors(const Packing& packing);

/// Identical spheres: |sum_j exp(-i Q.r_j)|^2 m_sphere(Q)^2 / V, 1 <= |n|^2 <= maxN2, by the
/// collective density kernel. Throws std::invalid_argument unless the particles are identical
/// spheres and maxN2 >= 1.
WaveVectorSpectrum sphereWaveVectors(const Packing& packing, std::int64_t maxN2,
                                     const Progress& progress);

/// Any shape: |sum_j m(R_j^T Q) exp(-i Q.r_j)|^2 / V, 1 <= |n|^2 <= maxN2, with the series of
/// the body's form factor (spectral/form_factors.hpp: SuperballFormFactor, accurate to 1e-16 v1
/// at these Q); a mixture's particle of size
/// s_j = R_j / R with its own, s_j^3 m(s_j R_j^T Q) (docs/mixtures.md). Parallel over tiles of wave
/// vectors, each summed over the particles in order (the result does not depend on the number
/// of threads). Throws std::invalid_argument unless maxN2 >= 1 and |Q| R_c stays within the
/// series' range.
WaveVectorSpectrum formFactorWaveVectors(const Packing& packing, std::int64_t maxN2,
                                         const Progress& progress);

struct ExactSpectralDensityParameters {
    /// Every wave vector with 0 < Q w <= maxQw (w the mean width).
    double maxQw = 3.0;
};

struct ExactSpectralDensityResult {
    ExactSpectralDensityParameters parameters;
    double boxLength = 0.0;
    double meanWidth = 0.0;
    double phi = 0.0; ///< N v1 / V
    std::int64_t maxN2 = 0;
    WaveVectorSpectrum modes;
    double runtimeSeconds = 0.0;
};

/// Compute object (docs/design.md §7): parameters validated at construction.
class ExactSpectralDensity {
  public:
    /// Throws std::invalid_argument unless 0 < maxQw < inf.
    explicit ExactSpectralDensity(ExactSpectralDensityParameters parameters);

    /// Largest |n|^2 with Q w = 2 pi |n| w / L <= maxQw.
    static std::int64_t maxN2For(double maxQw, double boxLength, double meanWidth);

    /// Identical spheres by sphereWaveVectors, other shapes and mixtures by
    /// formFactorWaveVectors. Throws
    /// std::invalid_argument if no wave vector of the box has Q w <= maxQw, or if maxQw is beyond
    /// the form factor's series range for this shape (both messages name maxQw).
    ExactSpectralDensityResult compute(const Packing& packing, const Progress& progress) const;

    const ExactSpectralDensityParameters& parameters() const { return parameters_; }

  private:
    ExactSpectralDensityParameters parameters_;
};

} // namespace sbpack

#pragma once
// The spectral density of one periodic box as the hyperuniformity analysis uses it: chi_V at the
// box's own wave vectors Q = 2 pi n / L, not shell averages (docs/design.md §5). The excess
// spreadability is a lattice sum over them (paper Eq. 21, eq:FT_spread, with
// int d^3Q / (2 pi)^3 -> (1 / V) sum_Q), in which only |n|^2 matters: so every wave vector is kept
// as a sum per |n|^2 (exact, not a binning), and those at small Q also one by one, for the
// fits of chi_V and the bootstrap.

#include "spectral/exact_spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "voxels/voxelization.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace sbpack {

struct DiscreteSpectrum {
    std::string source;         ///< "voxel", "exact" or "exact+voxel"
    double boxLength = 0.0;     ///< L
    double meanWidth = 0.0;     ///< w, the unit of Q (Q w) and of t (t D_diff / w^2)
    double phi = 0.0;           ///< normalises E: phi_voxel for voxel data, N v1 / V otherwise
    double cutoffQ = 0.0;       ///< every wave vector with |Q| < cutoffQ is included (1 / length)
    double missingWeight = 0.0; ///< (1/(phi V)) sum of chi_V over the wave vectors left out
    /// [|n|^2]: sum of chi_V (length^3) over every included wave vector with that |n|^2, both
    /// of each pair +-n.
    std::vector<double> sumByN2;
    /// The included wave vectors with |n|^2 <= individualMaxN2, one of each pair +-n.
    WaveVectorSpectrum modes;
    std::int64_t individualMaxN2 = 0;
};

struct VoxelSpectrumOptions {
    /// chi_V of the medium of voxel cubes, |F|^2 times the cube form factor squared (paper
    /// Eq. 12 applied to the voxels, as SpectralDensity). false: the grid's discrete transform
    /// alone, |F|^2 a^6 / V, whose sum over the grid obeys Parseval exactly.
    bool cubeFormFactor = true;
    /// Wave vectors with Q w <= individualQw are also kept one by one.
    double individualQw = 16.0;
};

/// Every wave vector of the voxel grid (the M^3 - 1 of the discrete transform, n_i in
/// (-M/2, M/2]), phi = phi_voxel. cutoffQ = 2 pi ceil(M/2) / L (no omitted alias is closer to
/// the origin). With the cube form factor, missingWeight = (1 - phi_voxel) - E(0): the weight
/// of the aliases beyond the grid, by Parseval for the voxel medium (the form factor moves
/// weight out of the grid; summed over every alias it restores it exactly); without, the sum is
/// complete: E(0) = 1 - phi_voxel exactly and missingWeight = 0, cutoffQ = inf.
/// Throws std::invalid_argument if the transform is not of these voxels.
DiscreteSpectrum voxelSpectrum(const VoxelFourierTransform& transform, const Voxelization& voxels,
                               double meanWidth, const VoxelSpectrumOptions& options,
                               const Progress& progress);

/// Per axis and DFT index k of an M-grid of voxel edge a: [a sinc(pi n / M)]^2 (the cube form
/// factor along that axis, Q a / 2 = pi n / M), or a^2 without the form factor.
std::vector<double> axisFactors(int m, double a, bool cubeFormFactor);

/// The largest |n|^2 kept one by one: Q w <= individualQw and |n_i| < M/2.
std::int64_t individualMaxN2(int voxels, double boxLength, double meanWidth,
                             const VoxelSpectrumOptions& options);

/// The grid a voxel spectrum is of.
struct VoxelGridFigures {
    int voxels;
    double boxLength;
    double phiVoxel;
};
/// |F(kx, ky, kz)|^2 of the indicator's DFT, 0 <= kz <= M/2.
using PowerAt = std::function<double(int kx, int ky, int kz)>;

/// voxelSpectrum from its parts, wherever the transform was made (the CPU's, or the GPU's,
/// gpu/cuda_grid.hpp): the sums of chi per |n|^2 over the whole grid (the form factors of
/// axisFactors and the weights of the half space applied, / V) and |F|^2 at the wave vectors
/// up to individualMaxN2.
DiscreteSpectrum voxelSpectrumFrom(std::vector<double> sumByN2, const PowerAt& power,
                                   const VoxelGridFigures& grid, double meanWidth,
                                   const VoxelSpectrumOptions& options);

/// The exact spectrum alone: wave vectors with |n|^2 <= maxN2, phi = N v1 / V,
/// missingWeight = (1 - phi) - E(0) (Parseval: chi_V sums to phi (1 - phi) V over every Q != 0).
DiscreteSpectrum exactSpectrum(const ExactSpectralDensityResult& exact);

/// The voxel spectrum with the exact values in place of the voxel ones at |n|^2 <= exact.maxN2;
/// phi = N v1 / V (missingWeight rescaled to it). Throws std::invalid_argument unless the
/// boxes agree and the voxel spectrum lists those wave vectors one by one.
DiscreteSpectrum withExactSmallQ(const DiscreteSpectrum& voxel,
                                 const ExactSpectralDensityResult& exact);

} // namespace sbpack

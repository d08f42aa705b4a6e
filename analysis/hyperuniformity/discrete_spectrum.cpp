#include "hyperuniformity/discrete_spectrum.hpp"

#include "grid/wave_index.hpp"
#include "parallel/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// Blocks of k_x planes summed apart and merged in order: the sums do not depend on the
/// number of threads.
constexpr int kPlaneBlocks = 16;

using grid::signedIndex;

double sinc(double x) {
    return x == 0.0 ? 1.0 : std::sin(x) / x;
}

/// |n|^2 = 0 .. 3 (M/2)^2: the bins of the grid's sums.
std::size_t squaredIndexBins(int m) {
    const std::int64_t half = m / 2;
    return static_cast<std::size_t>(3 * half * half + 1);
}

/// sum of chi over the wave vectors of k_x planes block b of kPlaneBlocks, per |n|^2.
std::vector<double> blockSums(const VoxelFourierTransform& transform, const std::vector<double>& f,
                              double volume, std::int64_t b) {
    const int m = transform.voxels();
    std::vector<double> sum(squaredIndexBins(m), 0.0);
    for (int kx = static_cast<int>(b * m / kPlaneBlocks);
         kx < static_cast<int>((b + 1) * m / kPlaneBlocks); ++kx) {
        const std::int64_t nx = signedIndex(kx, m);
        for (int ky = 0; ky < m; ++ky) {
            const std::int64_t ny = signedIndex(ky, m);
            const double fxy = f[kx] * f[ky] / volume;
            for (int kz = 0; kz <= m / 2; ++kz) {
                const std::int64_t n2 = nx * nx + ny * ny + std::int64_t{kz} * kz;
                if (n2 == 0) continue;
                sum[n2] += transform.weight(kz) * transform.power(kx, ky, kz) * fxy * f[kz];
            }
        }
    }
    return sum;
}

/// sum of chi over every wave vector of the grid, per |n|^2: the blocks summed in order (into
/// zeros: every term is >= +0, so the first block's sums are its own bit for bit).
std::vector<double> gridSums(const VoxelFourierTransform& transform, const std::vector<double>& f,
                             double volume, const Progress& progress) {
    return orderedReduce(
        kPlaneBlocks, std::vector<double>(squaredIndexBins(transform.voxels()), 0.0),
        [&](std::int64_t b) { return blockSums(transform, f, volume, b); },
        [](std::vector<double>& sum, const std::vector<double>& block) {
            for (std::size_t i = 0; i < sum.size(); ++i)
                sum[i] += block[i];
        },
        progress);
}

double excessAtZero(const DiscreteSpectrum& s) {
    double sum = 0.0;
    for (const double v : s.sumByN2)
        sum += v;
    return sum / (s.phi * std::pow(s.boxLength, 3));
}

} // namespace

std::vector<double> axisFactors(int m, double a, bool cubeFormFactor) {
    std::vector<double> f(m);
    for (int k = 0; k < m; ++k) {
        const double s = cubeFormFactor ? sinc(std::numbers::pi * signedIndex(k, m) / m) : 1.0;
        f[k] = a * a * s * s;
    }
    return f;
}

DiscreteSpectrum voxelSpectrum(const VoxelFourierTransform& transform, const Voxelization& voxels,
                               double meanWidth, const VoxelSpectrumOptions& options,
                               const Progress& progress) {
    if (transform.voxels() != voxels.voxels())
        throw std::invalid_argument("voxel spectrum: the transform is of a different grid");
    const VoxelGridFigures grid{voxels.voxels(), voxels.boxLength(), voxels.phiVoxel()};
    const std::vector<double> f =
        axisFactors(grid.voxels, voxels.voxelSize(), options.cubeFormFactor);
    return voxelSpectrumFrom(
        gridSums(transform, f, std::pow(grid.boxLength, 3), progress),
        [&transform](int kx, int ky, int kz) { return transform.power(kx, ky, kz); }, grid,
        meanWidth, options);
}

std::int64_t individualMaxN2(int voxels, double boxLength, double meanWidth,
                             const VoxelSpectrumOptions& options) {
    const double reach = options.individualQw * boxLength / (2.0 * std::numbers::pi * meanWidth);
    const std::int64_t inside = (voxels + 1) / 2 - 1; // |n_i| < M/2: +-n both in the grid
    return std::min(static_cast<std::int64_t>(std::floor(reach * reach)), inside * inside);
}

DiscreteSpectrum voxelSpectrumFrom(std::vector<double> sumByN2, const PowerAt& power,
                                   const VoxelGridFigures& grid, double meanWidth,
                                   const VoxelSpectrumOptions& options) {
    const int m = grid.voxels;
    const double boxLength = grid.boxLength, volume = std::pow(boxLength, 3);
    const std::vector<double> f = axisFactors(m, boxLength / m, options.cubeFormFactor);
    DiscreteSpectrum s;
    s.source = "voxel";
    s.boxLength = boxLength;
    s.meanWidth = meanWidth;
    s.phi = grid.phiVoxel;
    s.sumByN2 = std::move(sumByN2);
    s.individualMaxN2 = individualMaxN2(m, boxLength, meanWidth, options);
    s.modes = {boxLength, s.individualMaxN2, halfSpaceWaveVectors(s.individualMaxN2), {}};
    for (const auto& n : s.modes.n) {
        // F(-n) is the conjugate of F(n): read the stored one with k_z >= 0.
        const int sign = n[2] < 0 ? -1 : 1;
        const int kx = (sign * n[0] + m) % m, ky = (sign * n[1] + m) % m, kz = sign * n[2];
        s.modes.chi.push_back(power(kx, ky, kz) * f[kx] * f[ky] * f[kz] / volume);
    }
    if (options.cubeFormFactor) {
        s.cutoffQ = 2.0 * std::numbers::pi * std::ceil(0.5 * m) / boxLength; // ceil(M/2)
        s.missingWeight = std::max(0.0, (1.0 - s.phi) - excessAtZero(s));
    } else {
        s.cutoffQ = std::numeric_limits<double>::infinity();
    }
    return s;
}

DiscreteSpectrum exactSpectrum(const ExactSpectralDensityResult& exact) {
    DiscreteSpectrum s;
    s.source = "exact";
    s.boxLength = exact.boxLength;
    s.meanWidth = exact.meanWidth;
    s.phi = exact.phi;
    s.cutoffQ =
        2.0 * std::numbers::pi * std::sqrt(static_cast<double>(exact.maxN2 + 1)) / exact.boxLength;
    s.sumByN2.assign(static_cast<std::size_t>(exact.maxN2) + 1, 0.0);
    for (std::size_t i = 0; i < exact.modes.size(); ++i)
        s.sumByN2[exact.modes.n2(i)] += 2.0 * exact.modes.chi[i]; // +-n
    s.modes = exact.modes;
    s.individualMaxN2 = exact.maxN2;
    s.missingWeight = std::max(0.0, (1.0 - s.phi) - excessAtZero(s));
    return s;
}

DiscreteSpectrum withExactSmallQ(const DiscreteSpectrum& voxel,
                                 const ExactSpectralDensityResult& exact) {
    if (voxel.boxLength != exact.boxLength)
        throw std::invalid_argument("spectrum: the exact and voxel spectra are of different boxes");
    if (exact.maxN2 > voxel.individualMaxN2)
        throw std::invalid_argument(
            "spectrum: the voxel spectrum lists wave vectors one by one only up to |n|^2 = " +
            std::to_string(voxel.individualMaxN2) + ", the exact one reaches " +
            std::to_string(exact.maxN2));
    DiscreteSpectrum s = voxel;
    s.source = "exact+voxel";
    s.phi = exact.phi;
    s.missingWeight = voxel.missingWeight * voxel.phi / exact.phi;
    for (std::int64_t n2 = 1; n2 <= exact.maxN2; ++n2)
        s.sumByN2[n2] = 0.0;
    for (std::size_t i = 0; i < exact.modes.size(); ++i) {
        if (s.modes.n[i] != exact.modes.n[i])
            throw std::logic_error("spectrum: wave vectors out of order");
        s.modes.chi[i] = exact.modes.chi[i];
        s.sumByN2[exact.modes.n2(i)] += 2.0 * exact.modes.chi[i];
    }
    return s;
}

} // namespace sbpack

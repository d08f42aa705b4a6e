#include "spectral/spectral_density.hpp"

#include "grid/wave_index.hpp"
#include "parallel/parallel.hpp"
#include "spectral/exact_spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "structure/structure_factor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

namespace {

/// sin(x) / x, with its Taylor series near 0.
double sinc(double x) {
    return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x;
}

using grid::signedIndex;

} // namespace

double cubeFormFactor(const Eigen::Vector3d& q, double edge) {
    return edge * sinc(0.5 * q.x() * edge) * edge * sinc(0.5 * q.y() * edge) * edge *
           sinc(0.5 * q.z() * edge);
}

double sphereFormFactor(double q, double radius) {
    const double x = q * radius;
    const double volume = 4.0 * std::numbers::pi * radius * radius * radius / 3.0;
    if (std::abs(x) < 0.1) { // 3 (sin x - x cos x) / x^3 by its series: no cancellation
        const double x2 = x * x;
        return volume * (1.0 - x2 / 10.0 + x2 * x2 / 280.0 - x2 * x2 * x2 / 15120.0);
    }
    return 4.0 * std::numbers::pi * (std::sin(x) - x * std::cos(x)) / (q * q * q);
}

SpectralDensity::SpectralDensity(SpectralDensityParameters parameters) : parameters_(parameters) {
    if (!(parameters.maxQw > 0.0) || !std::isfinite(parameters.maxQw))
        throw std::invalid_argument("spectral density: qmax must be positive and finite, not " +
                                    fmt::format("{:g}", parameters.maxQw));
}

int SpectralDensity::maxShellFor(double maxQw, double boxLength, double meanWidth, int voxels) {
    return std::min(StructureFactor::maxShellFor(maxQw, boxLength, meanWidth), (voxels - 1) / 2);
}

double SpectralDensity::memoryEstimateBytes(int voxels) {
    return VoxelFourierTransform::memoryBytes(voxels);
}

SpectralDensityResult SpectralDensity::compute(const Packing& packing, const Voxelization& voxels,
                                               const Progress& progress) const {
    const VoxelFourierTransform transform(voxels, parameters_.fft, progress);
    return compute(packing, voxels, transform, progress);
}

namespace {

/// [a sinc(Q_i a / 2)]^2 per axis, Q_i a / 2 = pi n_i / M, for n_i in [-s, s].
std::vector<double> voxelFormFactors(double voxelSize, int m, int s) {
    std::vector<double> formFactor2(2 * s + 1);
    for (int n = -s; n <= s; ++n) {
        const double f = voxelSize * sinc(std::numbers::pi * n / m);
        formFactor2[n + s] = f * f;
    }
    return formFactor2;
}

} // namespace

ShellAccumulator spectralShellSums(const SpectrumSlab& slab, double voxelSize, double boxLength,
                                   int s, const Progress& progress) {
    const int m = slab.voxels, rows = slab.rows;
    const std::int64_t half = slab.rowLength;
    const double volume = std::pow(boxLength, 3);
    const std::int64_t maxN2 = maxSquaredIndex(s);
    const std::vector<double> formFactor2 = voxelFormFactors(voxelSize, m, s);
    std::vector<int> planes;
    for (int outer = slab.outerBegin; outer < slab.outerEnd; ++outer)
        if (std::abs(signedIndex(outer, rows)) <= s) planes.push_back(outer);
    const auto planeShells = [&](std::int64_t p) {
        progress.checkInterrupt();
        ShellAccumulator shells(boxLength, s);
        const int no = signedIndex(planes[p], rows);
        const double* plane = slab.data + (planes[p] - slab.outerBegin) * rows * half * 2;
        for (int inner = 0; inner < rows; ++inner) {
            const int ni = signedIndex(inner, rows);
            const std::int64_t n2io = std::int64_t{no} * no + std::int64_t{ni} * ni;
            if (n2io > maxN2) continue;
            const double fxy = formFactor2[no + s] * formFactor2[ni + s];
            for (int kz = 0; kz <= s; ++kz) {
                const std::int64_t n2 = n2io + std::int64_t{kz} * kz;
                if (n2 > maxN2) break;
                if (n2 == 0) continue;
                const double* c = plane + (inner * half + kz) * 2;
                const double power = c[0] * c[0] + c[1] * c[1];
                const int weight = kz == 0 || 2 * kz == m ? 1 : 2;
                shells.add(n2, power * fxy * formFactor2[kz + s] / volume, weight);
            }
        }
        return shells;
    };
    return orderedReduce(
        static_cast<std::int64_t>(planes.size()), ShellAccumulator(boxLength, s), planeShells,
        [](ShellAccumulator& shells, const ShellAccumulator& plane) { shells.merge(plane); },
        progress);
}

namespace {

/// Spheres: the exact shells and the voxel path's largest error against them over their peak.
SphereComparison compareWithSpheres(const Packing& packing, const ShellAverage& voxel, int maxShell,
                                    const Progress& progress) {
    SphereComparison comparison;
    comparison.exact = sphereSpectralDensity(packing, maxShell, progress);
    double peak = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < comparison.exact.size(); ++i) {
        peak = std::max(peak, comparison.exact.value[i]);
        worst = std::max(worst, std::abs(voxel.value[i] - comparison.exact.value[i]));
    }
    comparison.maxErrorOverPeak = worst / peak;
    return comparison;
}

} // namespace

SpectralDensityResult SpectralDensity::start(const Packing& packing, int voxels,
                                             double phiVoxel) const {
    SpectralDensityResult result;
    result.parameters = parameters_;
    result.voxels = voxels;
    result.voxelSize = packing.boxLength / voxels;
    result.phiVoxel = phiVoxel;
    result.boxLength = packing.boxLength;
    result.meanWidth = packing.shape().meanWidth();
    result.maxShell = maxShellFor(parameters_.maxQw, packing.boxLength, result.meanWidth, voxels);
    if (result.maxShell < 1)
        throw std::invalid_argument(
            "spectral density: no shell with Q w <= " + fmt::format("{:g}", parameters_.maxQw) +
            " on a " + std::to_string(voxels) + "^3 grid of this box");
    return result;
}

void SpectralDensity::finish(const Packing& packing, ShellAverage shells, const Progress& progress,
                             SpectralDensityResult& result) const {
    const Stopwatch clock;
    result.shells = std::move(shells);
    if (packing.shape().isSphere() && !packing.isMixture()) { // one closed form for all
        const Stopwatch exactClock;
        result.exactSphere = compareWithSpheres(packing, result.shells, result.maxShell, progress);
        result.exactSeconds = exactClock.seconds();
    }
    result.runtimeSeconds += clock.seconds();
}

SpectralDensityResult SpectralDensity::compute(const Packing& packing, const Voxelization& voxels,
                                               const VoxelFourierTransform& transform,
                                               const Progress& progress) const {
    const Stopwatch clock;
    if (transform.voxels() != voxels.voxels())
        throw std::invalid_argument("spectral density: the transform is of a different grid");
    if (voxels.boxLength() != packing.boxLength)
        throw std::invalid_argument("spectral density: the voxelization is of a box of edge " +
                                    std::to_string(voxels.boxLength()) + ", the packing's is " +
                                    std::to_string(packing.boxLength));
    SpectralDensityResult result = start(packing, voxels.voxels(), voxels.phiVoxel());
    result.planSeconds = transform.planSeconds();
    result.fillSeconds = transform.fillSeconds();
    result.transformSeconds = transform.transformSeconds();
    const Stopwatch shellClock;
    const int m = voxels.voxels();
    const SpectrumSlab whole{transform.data(), m, 0, m, m, m / 2 + 1};
    ShellAverage shells =
        spectralShellSums(whole, voxels.voxelSize(), packing.boxLength, result.maxShell, progress)
            .average();
    result.shellSeconds = shellClock.seconds();
    result.runtimeSeconds =
        clock.seconds() + result.planSeconds + result.fillSeconds + result.transformSeconds;
    finish(packing, std::move(shells), progress, result);
    return result;
}

ShellAverage sphereSpectralDensity(const Packing& packing, int maxShell, const Progress& progress) {
    if (maxShell < 1) throw std::invalid_argument("exact spectral density: no shell");
    return shellAverage(sphereWaveVectors(packing, maxSquaredIndex(maxShell), progress), maxShell);
}

} // namespace sbpack

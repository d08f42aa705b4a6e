#include "voronoi/set_voronoi.hpp"

#include "numerics/sample_statistics.hpp"
#include "parallel/parallel.hpp"
#include "pores/distance_transform.hpp"
#include "voxels/voxelization.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// Voxels per chunk of the counting loop (and per interrupt check).
constexpr std::int64_t kChunkVoxels = std::int64_t{1} << 22;

/// Per particle: the voxels of its cell and its solid voxels.
struct VoxelCounts {
    std::vector<std::uint32_t> cell, solid;
};

/// Each voxel counted for the particle of its nearest solid voxel (cell) and, if solid, for the
/// particle that holds it (solid). Integer counts: the result does not depend on the threads.
VoxelCounts countVoxels(std::span<const std::uint32_t> labels,
                        std::span<const std::uint32_t> features, std::size_t particles,
                        const Progress& progress) {
    const std::int64_t total = static_cast<std::int64_t>(labels.size());
    const std::int64_t chunks = (total + kChunkVoxels - 1) / kChunkVoxels;
    auto count = [&](std::int64_t c) {
        progress.checkInterrupt();
        VoxelCounts part{std::vector<std::uint32_t>(particles, 0),
                         std::vector<std::uint32_t>(particles, 0)};
        for (std::int64_t v = c * kChunkVoxels; v < std::min(total, (c + 1) * kChunkVoxels); ++v) {
            ++part.cell[labels[features[v]] - 1];
            if (labels[v] != 0) ++part.solid[labels[v] - 1];
        }
        return part;
    };
    auto add = [](VoxelCounts& sum, VoxelCounts&& part) {
        if (sum.cell.empty()) {
            sum = std::move(part);
            return;
        }
        for (std::size_t i = 0; i < sum.cell.size(); ++i) {
            sum.cell[i] += part.cell[i];
            sum.solid[i] += part.solid[i];
        }
    };
    return orderedReduce(chunks, VoxelCounts{}, count, add, progress);
}

/// The moments of phi over the particles i with rattler[i] == selected (all where rattler is
/// empty); nullopt where there are none.
std::optional<LocalPhiMoments> moments(const std::vector<double>& phi,
                                       const std::vector<bool>& rattler, bool selected) {
    std::vector<double> chosen;
    for (std::size_t i = 0; i < phi.size(); ++i)
        if (rattler.empty() || rattler[i] == selected) chosen.push_back(phi[i]);
    if (chosen.empty()) return std::nullopt;
    const SampleStatistics s = sampleStatistics(chosen);
    double inverse = 0.0;
    for (double v : chosen)
        inverse += 1.0 / v;
    const auto [low, high] = std::minmax_element(chosen.begin(), chosen.end());
    return LocalPhiMoments{static_cast<std::int64_t>(chosen.size()),     s.mean, s.std,
                           static_cast<double>(chosen.size()) / inverse, *low,   *high};
}

/// The density of phi over [0, 1] in kHistogramBins bins (values of 1 and above in the last).
void fillHistogram(SetVoronoiResult& r) {
    const int bins = SetVoronoi::kHistogramBins;
    const double width = 1.0 / bins;
    r.histogramPhi.resize(bins);
    r.histogramDensity.assign(bins, 0.0);
    for (int b = 0; b < bins; ++b)
        r.histogramPhi[b] = (b + 0.5) * width;
    for (double phi : r.localPhi)
        r.histogramDensity[std::min(bins - 1, static_cast<int>(phi / width))] += 1.0;
    for (double& d : r.histogramDensity)
        d /= static_cast<double>(r.localPhi.size()) * width;
}

} // namespace

SetVoronoi::SetVoronoi(int voxels) : voxels_(voxels) {
    if (voxels < 1 || voxels > maxFeatureTransformVoxels)
        throw VoxelResolutionError("set-Voronoi cells: M = " + std::to_string(voxels) +
                                   " is not in [1, " + std::to_string(maxFeatureTransformVoxels) +
                                   "] (the feature transform's voxel indices fit 32 bits)");
}

double SetVoronoi::memoryBytes(int voxels) {
    return 13.0 * std::pow(double(voxels), 3);
}

SetVoronoiResult SetVoronoi::compute(const Packing& packing, const std::vector<bool>& rattler,
                                     const Progress& progress) const {
    const Stopwatch clock;
    const std::size_t n = packing.size();
    if (!rattler.empty() && rattler.size() != n)
        throw std::invalid_argument("set-Voronoi cells: " + std::to_string(rattler.size()) +
                                    " rattler flags for " + std::to_string(n) + " particles");
    const int m = voxels_;
    const std::vector<std::uint32_t> labels = Voxelizer({m}).particleLabels(packing, progress);
    std::vector<std::uint8_t> mask(labels.size());
    std::transform(labels.begin(), labels.end(), mask.begin(),
                   [](std::uint32_t l) { return static_cast<std::uint8_t>(l != 0); });
    SetVoronoiResult r;
    r.voxels = m;
    r.voxelSize = packing.boxLength / m;
    r.particleVolume = packing.shape().volume();
    const PoreSizeMap map = periodicFeatureTransform(mask, m, r.voxelSize, progress);
    mask = {};
    const VoxelCounts counts = countVoxels(labels, map.features(), n, progress);
    const double voxelVolume = r.voxelSize * r.voxelSize * r.voxelSize;
    double cells = 0.0, squares = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (counts.cell[i] == 0)
            throw std::domain_error("set-Voronoi cells: particle " + std::to_string(i) +
                                    " holds no voxel of its own on the " + std::to_string(m) +
                                    "^3 grid (it overlaps others)");
        const double size = packing.relativeSize(i);
        const double volume = r.particleVolume * size * size * size; // v_i
        r.cellVolumes.push_back(counts.cell[i] * voxelVolume);
        r.localPhi.push_back(volume / r.cellVolumes.back());
        r.particleVoxelError.push_back(counts.solid[i] * voxelVolume / volume - 1.0);
        cells += counts.cell[i];
        squares += r.particleVoxelError.back() * r.particleVoxelError.back();
    }
    r.tilingError = cells / (double(m) * m * m) - 1.0;
    r.voxelErrorRms = std::sqrt(squares / static_cast<double>(n));
    r.all = *moments(r.localPhi, {}, false);
    if (!rattler.empty()) {
        r.nonRattlers = moments(r.localPhi, rattler, false);
        r.rattlers = moments(r.localPhi, rattler, true);
    }
    fillHistogram(r);
    r.runtimeSeconds = clock.seconds();
    return r;
}

} // namespace sbpack

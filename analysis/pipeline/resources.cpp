#include "pipeline/resources.hpp"
#include "pores/distance_transform.hpp"

#include "shells/shell_average.hpp"
#include "spectral/spectral_density.hpp"
#include "structure/structure_factor.hpp"
#include "voxels/voxelization.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace sbpack {

namespace {

/// Float leaves of the .vdb export: 8^3 floats and their masks per block, at most every block.
double vdbExportBytes(int voxels) {
    return std::pow(std::ceil(voxels / 8.0), 3) * (512.0 * 4.0 + 200.0);
}

/// Phase tables and modes of the collective-density kernel up to shell s.
double collectiveDensityBytes(const Packing& packing, int maxShell) {
    const double modes = 2.0 / 3.0 * std::numbers::pi * std::pow(maxShell + 0.5, 3);
    return 6.0 * 8.0 * static_cast<double>(packing.size()) * (maxShell + 1) + modes * 2.0 * 20.0;
}

} // namespace

std::string formatBytes(double bytes) {
    const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
    int u = 0;
    while (bytes >= 1000.0 && u < 5) {
        bytes /= 1000.0;
        ++u;
    }
    std::ostringstream out;
    out << std::setprecision(bytes < 10.0 ? 2 : 3) << bytes << ' ' << units[u];
    return out.str();
}

MemoryEstimate estimateMemory(const Packing& packing, const RunSettings& settings) {
    MemoryEstimate estimate;
    auto add = [&](const std::string& what, double bytes) {
        estimate.bytes += bytes;
        estimate.breakdown +=
            (estimate.breakdown.empty() ? "" : ", ") + what + " " + formatBytes(bytes);
    };
    const double meanWidth = packing.shape().meanWidth();
    const int sqShell = StructureFactor::maxShellFor(settings.maxQw, packing.boxLength, meanWidth);
    // Voxelizations are kept while the file is analysed, one per grid.
    for (VoxelGrid grid : settings.grids()) {
        const int m = settings.voxelsOf(grid);
        add("voxel tree " + std::to_string(m) + "^3", Voxelizer::memoryEstimateBytes(packing, m));
    }
    // The stages after the voxelization run one at a time: the largest counts.
    double stage = 0.0;
    std::string stageName;
    auto consider = [&](const std::string& what, double bytes) {
        if (bytes > stage) {
            stage = bytes;
            stageName = what;
        }
    };
    if (settings.runs(Analysis::StructureFactor))
        consider("S(Q) tables", collectiveDensityBytes(packing, std::max(sqShell, 1)));
    if (settings.runs(Analysis::SpectralDensity)) {
        const int m = settings.voxels;
        const int shell =
            SpectralDensity::maxShellFor(settings.maxQw, packing.boxLength, meanWidth, m);
        double bytes = SpectralDensity::memoryEstimateBytes(m);
        if (packing.shape().isSphere())
            bytes += collectiveDensityBytes(packing, std::max(shell, 1));
        consider("FFT grid " + std::to_string(m) + "^3", bytes);
    }
    if (settings.runs(Analysis::PoreSizes))
        consider("pore-size map " + std::to_string(settings.poreVoxels) + "^3",
                 static_cast<double>(poreSizeMemoryBytes(settings.poreVoxels)));
    if (!settings.vdbDirectory.empty()) consider(".vdb export", vdbExportBytes(settings.voxels));
    if (stage > 0.0) add(stageName, stage);
    return estimate;
}

std::optional<double> availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double value = 0.0;
    std::string unit;
    while (meminfo >> key >> value >> unit)
        if (key == "MemAvailable:") return value * (unit == "kB" ? 1024.0 : 1.0);
    return std::nullopt;
}

void checkMemory(const Packing& packing, const RunSettings& settings, const std::string& source) {
    const std::optional<double> available = availableMemoryBytes();
    if (!available) return;
    const MemoryEstimate estimate = estimateMemory(packing, settings);
    if (estimate.bytes > *available)
        throw std::invalid_argument(
            source + ": the analyses need about " + formatBytes(estimate.bytes) + " of memory (" +
            estimate.breakdown + "), more than the " + formatBytes(*available) +
            " available; use a smaller --voxels or --qmax");
}

} // namespace sbpack

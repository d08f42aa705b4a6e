#include "pipeline/resources.hpp"

#include "parallel/available_memory.hpp"

#include "voxels/voxelization.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace sbpack {

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
    auto add = [&](const std::string& what, double bytes, const std::string& option) {
        estimate.bytes += bytes;
        estimate.breakdown +=
            (estimate.breakdown.empty() ? "" : ", ") + what + " " + formatBytes(bytes);
        if (estimate.options.find(option) == std::string::npos)
            estimate.options += (estimate.options.empty() ? "" : " or ") + option;
    };
    // Voxelizations are kept while the file is analysed, one per grid.
    for (VoxelGrid grid : settings.grids()) {
        const int m = settings.voxelsOf(grid);
        add("voxel tree " + std::to_string(m) + "^3", Voxelizer::memoryEstimateBytes(packing, m),
            grid == VoxelGrid::Pore ? "--pore-voxels" : "--voxels");
    }
    // The stages after the voxelization run one at a time: the largest counts.
    StageMemory largest;
    for (Analysis analysis : settings.analyses)
        if (const StageMemoryEstimate memory = analysisInfo(analysis).memory) {
            StageMemory stage = memory(packing, settings);
            if (stage.bytes > largest.bytes) largest = std::move(stage);
        }
    if (largest.bytes > 0.0) add(largest.what, largest.bytes, largest.option);
    return estimate;
}

void checkMemory(const Packing& packing, const RunSettings& settings, const std::string& source) {
    const std::optional<double> available = availableMemoryBytes();
    if (!available) return;
    const MemoryEstimate estimate = estimateMemory(packing, settings);
    if (estimate.bytes > *available)
        throw std::invalid_argument(
            source + ": the analyses need about " + formatBytes(estimate.bytes) + " of memory (" +
            estimate.breakdown + "), more than the " + formatBytes(*available) +
            " available; use a smaller " + estimate.options);
}

} // namespace sbpack

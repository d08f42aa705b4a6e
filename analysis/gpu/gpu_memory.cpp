#include "gpu/gpu_memory.hpp"

#include "grid/voxel_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

} // namespace

double gpuVoxelBytes(int voxels) {
    const double m = voxels;
    return m * m * grid::wordsPerRow(voxels) * 4.0;
}

double gpuFftGridBytes(int voxels, bool single) {
    const double m = voxels;
    return m * m * (std::floor(m / 2) + 1) * 2.0 * (single ? 4.0 : 8.0);
}

GpuMemoryPlan planGpuMemory(int spectralVoxels, int poreVoxels, bool single,
                            std::size_t fftWorkBytes) {
    GpuMemoryPlan plan;
    const double kept = spectralVoxels > 0 ? gpuVoxelBytes(spectralVoxels) : 0.0;
    if (spectralVoxels > 0)
        plan.spectralBytes =
            kept + gpuFftGridBytes(spectralVoxels, single) + static_cast<double>(fftWorkBytes);
    if (poreVoxels > 0) {
        const double m = poreVoxels;
        plan.poreBytes = gpuVoxelBytes(poreVoxels) + 2 * m * m * m * 4.0;
    }
    plan.peakBytes = std::max(plan.spectralBytes, kept + plan.poreBytes);
    return plan;
}

void checkGpuMemory(const GpuMemoryPlan& plan, std::size_t freeBytes, const std::string& device) {
    if (plan.peakBytes <= static_cast<double>(freeBytes)) return;
    throw std::runtime_error(fmt::format(
        "--device cuda: the grids need {:.2f} GiB on the GPU (chi {:.2f} GiB, pores {:.2f} GiB), "
        "but {} has {:.2f} GiB free; choose a smaller --voxels or --pore-voxels, or --device cpu",
        plan.peakBytes / kGiB, plan.spectralBytes / kGiB, plan.poreBytes / kGiB, device,
        static_cast<double>(freeBytes) / kGiB));
}

} // namespace sbpack

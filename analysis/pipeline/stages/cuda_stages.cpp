// --device cuda (docs/gpu.md): the voxels, chi and pore-grid stages on the GPU (gpu/cuda_grid.hpp),
// with the progress lines and results of the CPU stages beside it; built with SBPACK_WITH_CUDA
// only.
#include "gpu/cuda_grid.hpp"
#include "gpu/gpu_memory.hpp"
#include "pipeline/resources.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "voxels/voxelization.hpp"
#include "voxels/voxelization_fields.hpp"

#include <fmt/format.h>

namespace sbpack::stages {

namespace {

/// The device's free memory now.
std::size_t freeDeviceBytes() {
    std::string reason;
    const std::optional<CudaDevice> device = probeCudaDevice(reason);
    if (!device) throw std::runtime_error("--device cuda: " + reason);
    return device->freeBytes;
}

GpuMemoryPlan planFor(const RunSettings& settings) {
    const bool spectral =
        settings.runs(Analysis::Voxels) || settings.runs(Analysis::SpectralDensity);
    const bool pores =
        settings.runs(Analysis::PoreSizes) && settings.poreMethod() == PoreMethod::Voxel;
    const int m = spectral ? settings.voxelization.voxels : 0;
    return planGpuMemory(m, pores ? settings.poreVoxels() : 0, settings.fftSingle,
                         m > 0 ? gpu::cuda::fftWorkBytes(m, settings.fftSingle) : 0);
}

} // namespace

void checkCudaRun(const RunSettings& settings) {
    const std::size_t freeBytes = freeDeviceBytes();
    checkGpuMemory(planFor(settings), freeBytes, settings.device.description());
}

bool runCudaVoxels(FileContext& context, schema::Record& record) {
    const int m = context.settings().voxelization.voxels;
    CudaGrid grid(context.packing(), m);
    const double phiExact = context.packing().packingFraction();
    context.progress().stageDone("voxelization (cuda)", grid.runtimeSeconds(),
                                 fmt::format("{}^3, phi_voxel = {} (phi = {}), GPU bits {}", m,
                                             describe(grid.phiVoxel()), describe(phiExact),
                                             formatBytes(static_cast<double>(grid.deviceBytes()))));
    VoxelFigures figures{.voxels = m,
                         .phiVoxel = grid.phiVoxel(),
                         .phiExact = phiExact,
                         .voxelSize = grid.voxelSize(),
                         .solidVoxels = grid.solidCount(),
                         .memoryBytes = static_cast<std::int64_t>(grid.deviceBytes()),
                         .runtimeSeconds = grid.runtimeSeconds(),
                         .vdbFile = std::nullopt, // set below with --vdb
                         .distribution = std::nullopt};
    if (context.vdbExport(Analysis::Voxels) != nullptr) // OpenVDB on the host, from the GPU's bits
        figures.vdbFile =
            exportVoxels(context, Voxelizer::fromRowBits(grid.rowBits(), context.packing(), m,
                                                         grid.runtimeSeconds()));
    voxelization_fields::kTable.fill(record, figures, context.scales());
    context.keep(Analysis::Voxels, std::move(grid));
    return true;
}

SpectralDensityResult cudaSpectralDensity(FileContext& context,
                                          const SpectralDensityParameters& parameters) {
    const CudaGrid& grid = context.kept<CudaGrid>(Analysis::Voxels);
    const bool hyper = context.settings().keepsVoxelSpectrum();
    const VoxelSpectrumOptions spectrum; // as the CPU stage's voxelSpectrum
    CudaGrid::Spectra s =
        grid.spectralDensity(context.packing(), parameters, context.settings().fftSingle,
                             hyper ? &spectrum : nullptr, context.progress());
    if (hyper) {
        const SpectralPeak peak = principalPeak(*s.voxelSpectrum);
        context.keep(Analysis::SpectralDensity, KeptSpectrum{std::move(*s.voxelSpectrum), peak});
    }
    return std::move(s.chi);
}

namespace {

CudaGrid voxelizedPoreGrid(const FileContext& context, int voxels) {
    CudaGrid grid(context.packing(), voxels);
    context.progress().stageDone(
        "pore voxelization (cuda)", grid.runtimeSeconds(),
        fmt::format("{}^3, phi_voxel = {}", voxels, describe(grid.phiVoxel())));
    return grid;
}

} // namespace

PoreSizeMap cudaPoreSizeMap(const FileContext& context, int voxels) {
    const CudaGrid grid = voxelizedPoreGrid(context, voxels);
    const Stopwatch clock;
    CudaGrid::TimedPoreSizeMap timed = grid.poreSizeMap();
    context.progress().stageDone(
        "distance transform (cuda)", clock.seconds(),
        fmt::format("{} void voxels; device {:.3g} s, copy to the host {:.3g} s",
                    timed.map.voidCount(), timed.deviceSeconds, timed.copySeconds));
    return std::move(timed.map);
}

PoreSizeDistributionResult cudaPoreSizes(const FileContext& context, int voxels,
                                         const PoreSizeParameters& parameters) {
    const CudaGrid grid = voxelizedPoreGrid(context, voxels);
    const Stopwatch clock;
    const std::vector<std::int64_t> histogram = grid.poreHistogram();
    context.progress().stageDone(
        "distance transform and histogram (cuda)", clock.seconds(),
        fmt::format("{} void voxels", voxels * std::int64_t{voxels} * voxels - grid.solidCount()));
    const Stopwatch countClock;
    PoreSizeDistributionResult pores =
        PoreSizeDistribution(parameters)
            .fromHistogram(histogram, voxels, grid.voxelSize(), context.meanWidth());
    pores.runtimeSeconds = countClock.seconds();
    return pores;
}

} // namespace sbpack::stages

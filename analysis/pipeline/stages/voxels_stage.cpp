// voxels: the voxelization on the spectral grid (--voxels), kept for chi, optionally exported.
#include "pipeline/resources.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "voxels/voxelization.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sbpack::stages {

StageMemory voxelsMemory(const Packing&, const RunSettings& settings) {
    if (settings.vdbDirectory.empty()) return {};
    // Float leaves of the .vdb export: 8^3 floats and their masks per block, at most every block.
    return {std::pow(std::ceil(settings.voxels / 8.0), 3) * (512.0 * 4.0 + 200.0), ".vdb export",
            "--voxels"};
}

namespace {

/// --distribute grids: this rank's slab, kept for chi; the whole grid's figures.
bool runSlabVoxels(FileContext& context, schema::Record& record) {
    const int m = context.settings().voxels;
    SlabVoxels voxels = context.grids()->voxelize(context.packing(), m, context.progress());
    context.progress().stageDone(
        "voxelization", voxels.slab.runtimeSeconds(),
        fmt::format("{}^3 over {} ranks, slab [{}, {}), phi_voxel = {} (phi = {})", m,
                    voxels.figures.ranks, voxels.slab.slabBegin(), voxels.slab.slabEnd(),
                    describe(voxels.phiVoxel()), describe(voxels.slab.phiExact())));
    setVoxelFigures(record, {m, voxels.phiVoxel(), voxels.slab.phiExact(), voxels.slab.voxelSize(),
                             voxels.solidCount, static_cast<double>(voxels.slab.memoryBytes()),
                             voxels.slab.runtimeSeconds()});
    setDistribution(record, voxels.figures);
    context.keep(Analysis::Voxels, std::move(voxels));
    return true;
}

} // namespace

void exportVoxels(const FileContext& context, schema::Record& record, const Voxelization& voxels) {
    const VdbExport* vdb = context.vdbExport(Analysis::Voxels);
    if (vdb == nullptr) return;
    const Stopwatch clock;
    vdb->output->write(voxels.vdbImage());
    record.set("vdb_file", vdb->destination.string());
    context.progress().stageDone("vdb export", clock.seconds(), vdb->destination.string());
}

void setVoxelFigures(schema::Record& record, const VoxelFigures& figures) {
    record.set("voxels", figures.voxels)
        .set("phi_voxel", figures.phiVoxel)
        .set("phi_exact", figures.phiExact)
        .set("voxel_size", figures.voxelSize)
        .set("solid_voxels", figures.solidVoxels)
        .set("memory_bytes", static_cast<std::int64_t>(figures.memoryBytes))
        .set("runtime_s", figures.runtimeSeconds);
}

bool runVoxels(FileContext& context, schema::Record& record) {
    if (context.grids() != nullptr) return runSlabVoxels(context, record);
#ifdef SBPACK_WITH_CUDA
    if (context.settings().device.device == ComputeDevice::Cuda)
        return runCudaVoxels(context, record);
#endif
    const int m = context.settings().voxels;
    Voxelization voxels = Voxelizer({m}).compute(context.packing(), context.progress());
    context.progress().stageDone(
        "voxelization", voxels.runtimeSeconds(),
        fmt::format("{}^3, phi_voxel = {} (phi = {}), OpenVDB tree {}", m,
                    describe(voxels.phiVoxel()), describe(voxels.phiExact()),
                    formatBytes(static_cast<double>(voxels.memoryBytes()))));
    setVoxelFigures(record, {m, voxels.phiVoxel(), voxels.phiExact(), voxels.voxelSize(),
                             voxels.solidCount(), static_cast<double>(voxels.memoryBytes()),
                             voxels.runtimeSeconds()});
    exportVoxels(context, record, voxels);
    context.keep(Analysis::Voxels, std::move(voxels));
    return true;
}

} // namespace sbpack::stages

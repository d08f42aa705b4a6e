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
    return {std::pow(std::ceil(settings.voxels / 8.0), 3) * (512.0 * 4.0 + 200.0), ".vdb export"};
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
    record.set("voxels", m)
        .set("phi_voxel", voxels.phiVoxel())
        .set("phi_exact", voxels.slab.phiExact())
        .set("voxel_size", voxels.slab.voxelSize())
        .set("solid_voxels", voxels.solidCount)
        .set("memory_bytes", static_cast<std::int64_t>(voxels.slab.memoryBytes()))
        .set("runtime_s", voxels.slab.runtimeSeconds());
    setDistribution(record, voxels.figures);
    context.keep(Analysis::Voxels, std::move(voxels));
    return true;
}

} // namespace

bool runVoxels(FileContext& context, schema::Record& record) {
    if (context.grids() != nullptr) return runSlabVoxels(context, record);
    const int m = context.settings().voxels;
    Voxelization voxels = Voxelizer({m}).compute(context.packing(), context.progress());
    context.progress().stageDone(
        "voxelization", voxels.runtimeSeconds(),
        fmt::format("{}^3, phi_voxel = {} (phi = {}), OpenVDB tree {}", m,
                    describe(voxels.phiVoxel()), describe(voxels.phiExact()),
                    formatBytes(static_cast<double>(voxels.memoryBytes()))));
    record.set("voxels", voxels.parameters().voxels)
        .set("phi_voxel", voxels.phiVoxel())
        .set("phi_exact", voxels.phiExact())
        .set("voxel_size", voxels.voxelSize())
        .set("solid_voxels", voxels.solidCount())
        .set("memory_bytes", static_cast<std::int64_t>(voxels.memoryBytes()))
        .set("runtime_s", voxels.runtimeSeconds());
    if (const VdbExport* vdb = context.vdbExport(Analysis::Voxels)) {
        const Stopwatch clock;
        vdb->output->write(voxels.vdbImage());
        record.set("vdb_file", vdb->destination.string());
        context.progress().stageDone("vdb export", clock.seconds(), vdb->destination.string());
    }
    context.keep(Analysis::Voxels, std::move(voxels));
    return true;
}

} // namespace sbpack::stages

// voxels: the voxelization on the spectral grid (--voxels), kept for chi, optionally exported.
#include "pipeline/resources.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "voxels/voxelization.hpp"
#include "voxels/voxelization_fields.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sbpack::stages {

StageMemory voxelsMemory(const Packing&, const RunSettings& settings) {
    if (settings.vdbDirectory.empty()) return {};
    // Float leaves of the .vdb export: 8^3 floats and their masks per block, at most every block.
    return {std::pow(std::ceil(settings.voxelization.voxels / 8.0), 3) * (512.0 * 4.0 + 200.0),
            ".vdb export", "--voxels"};
}

namespace {

/// --distribute grids: this rank's slab, kept for chi; the whole grid's figures.
bool runSlabVoxels(FileContext& context, schema::Record& record) {
    const int m = context.settings().voxelization.voxels;
    SlabVoxels voxels = context.grids()->voxelize(context.packing(), m, context.progress());
    context.progress().stageDone(
        "voxelization", voxels.slab.runtimeSeconds(),
        fmt::format("{}^3 over {} ranks, slab [{}, {}), phi_voxel = {} (phi = {})", m,
                    voxels.figures.ranks, voxels.slab.slabBegin(), voxels.slab.slabEnd(),
                    describe(voxels.phiVoxel()), describe(voxels.slab.phiExact())));
    const VoxelFigures figures{.voxels = m,
                               .phiVoxel = voxels.phiVoxel(),
                               .phiExact = voxels.slab.phiExact(),
                               .voxelSize = voxels.slab.voxelSize(),
                               .solidVoxels = voxels.solidCount,
                               .memoryBytes = static_cast<std::int64_t>(voxels.slab.memoryBytes()),
                               .runtimeSeconds = voxels.slab.runtimeSeconds(),
                               .vdbFile = std::nullopt, // no export of a slab
                               .distribution = voxels.figures};
    voxelization_fields::kTable.fill(record, figures, context.scales());
    context.keep(Analysis::Voxels, std::move(voxels));
    return true;
}

} // namespace

std::optional<std::string> exportVoxels(const FileContext& context, const Voxelization& voxels) {
    const VdbExport* vdb = context.vdbExport(Analysis::Voxels);
    if (vdb == nullptr) return std::nullopt;
    const Stopwatch clock;
    vdb->output->write(voxels.vdbImage(context.lengthUnit()));
    context.progress().stageDone("vdb export", clock.seconds(), vdb->destination.string());
    return vdb->destination.string();
}

bool runVoxels(FileContext& context, schema::Record& record) {
    if (context.grids() != nullptr) return runSlabVoxels(context, record);
#ifdef SBPACK_WITH_CUDA
    if (context.gridsOnGpu()) return runCudaVoxels(context, record);
#endif
    const int m = context.settings().voxelization.voxels;
    Voxelization voxels =
        Voxelizer(context.settings().voxelization).compute(context.packing(), context.progress());
    context.progress().stageDone(
        "voxelization", voxels.runtimeSeconds(),
        fmt::format("{}^3, phi_voxel = {} (phi = {}), OpenVDB tree {}", m,
                    describe(voxels.phiVoxel()), describe(voxels.phiExact()),
                    formatBytes(static_cast<double>(voxels.memoryBytes()))));
    const VoxelFigures figures{.voxels = m,
                               .phiVoxel = voxels.phiVoxel(),
                               .phiExact = voxels.phiExact(),
                               .voxelSize = voxels.voxelSize(),
                               .solidVoxels = voxels.solidCount(),
                               .memoryBytes = static_cast<std::int64_t>(voxels.memoryBytes()),
                               .runtimeSeconds = voxels.runtimeSeconds(),
                               .vdbFile = exportVoxels(context, voxels),
                               .distribution = std::nullopt};
    voxelization_fields::kTable.fill(record, figures, context.scales());
    context.keep(Analysis::Voxels, std::move(voxels));
    return true;
}

} // namespace sbpack::stages

// pores: F(delta) on the pore grid (--pore-voxels) by the exact periodic distance transform;
// the result is kept for transport, the pore-size map optionally exported.
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "pores/distance_transform.hpp"
#include "pores/pore_size_distribution.hpp"
#include "voxels/voxelization.hpp"

#include <fmt/format.h>

#include <vector>

namespace sbpack::stages {

StageMemory poreSizesMemory(const Packing&, const RunSettings& settings) {
    return {static_cast<double>(poreSizeMemoryBytes(settings.poreVoxels)),
            fmt::format("pore-size map {}^3", settings.poreVoxels)};
}

namespace {

/// The pore-size map of the packing on an M^3 grid (the solid mask is released on return).
PoreSizeMap poreSizeMap(const FileContext& context, int m) {
    checkPoreSizeMemory(m);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    double voxelSize = 0.0;
    {
        const Voxelization voxels = Voxelizer({m}).compute(context.packing(), context.progress());
        voxels.copySolidMask(mask);
        voxelSize = voxels.voxelSize();
        context.progress().stageDone(
            "pore voxelization", voxels.runtimeSeconds(),
            fmt::format("{}^3, phi_voxel = {}", m, describe(voxels.phiVoxel())));
    }
    const Stopwatch clock;
    PoreSizeMap map = periodicDistanceTransform(mask, m, voxelSize);
    context.progress().stageDone("distance transform", clock.seconds(),
                                 fmt::format("{} void voxels", map.voidCount()));
    return map;
}

void setPoreSizes(schema::Record& record, const PoreSizeDistributionResult& s) {
    record.set("mean", s.mean)
        .set("second_moment", s.secondMoment)
        .set("max", s.max)
        .set("mean_w", s.meanOverWidth())
        .set("second_moment_w2", s.secondMomentOverWidth2())
        .set("max_w", s.maxOverWidth())
        .set("saturated", s.saturated)
        .set("voxels", s.voxels)
        .set("voxel_size", s.voxelSize)
        .set("samples", s.samples)
        .set("method", s.method)
        .set("runtime_s", s.runtimeSeconds)
        .set("delta", s.delta)
        .set("F", s.F)
        .set("delta_w", s.deltaOverWidth())
        .set("P_delta", s.densityDelta)
        .set("P", s.density)
        .set("P_delta_w", s.densityDeltaOverWidth())
        .set("P_w", s.densityTimesWidth());
}

/// --distribute grids: F(delta) of the slabs' distance transform (pipeline/distributed_grids.hpp).
bool runDistributedPoreSizes(FileContext& context, schema::Record& record) {
    DistributionFigures figures;
    PoreSizeDistributionResult pores = context.grids()->poreSizes(
        context.packing(), context.settings().poreVoxels, PoreSizeParameters{}, context.meanWidth(),
        context.progress(), figures);
    context.progress().stageDone("pore sizes", pores.runtimeSeconds,
                                 fmt::format("{} ranks, <delta>/w = {}, max/w = {}", figures.ranks,
                                             describe(pores.meanOverWidth()),
                                             describe(pores.maxOverWidth())));
    setPoreSizes(record, pores);
    setDistribution(record, figures);
    context.keep(Analysis::PoreSizes, std::move(pores));
    return true;
}

} // namespace

bool runPoreSizes(FileContext& context, schema::Record& record) {
    if (context.grids() != nullptr) return runDistributedPoreSizes(context, record);
    const PoreSizeMap map = poreSizeMap(context, context.settings().poreVoxels);
    PoreSizeParameters parameters;
    parameters.randomPoints = context.settings().porePoints;
    PoreSizeDistributionResult pores =
        PoreSizeDistribution(parameters).compute(map, context.meanWidth());
    context.progress().stageDone(
        "pore sizes", pores.runtimeSeconds,
        fmt::format("<delta>/w = {}, max/w = {}{}", describe(pores.meanOverWidth()),
                    describe(pores.maxOverWidth()),
                    pores.saturated ? " (saturated)" : " (NOT below w/2)"));
    if (const VdbExport* vdb = context.vdbExport(Analysis::PoreSizes)) {
        const Stopwatch clock;
        vdb->output->write(map.vdbImage());
        context.progress().stageDone("pore vdb export", clock.seconds(), vdb->destination.string());
    }
    setPoreSizes(record, pores);
    context.keep(Analysis::PoreSizes, std::move(pores));
    return true;
}

} // namespace sbpack::stages

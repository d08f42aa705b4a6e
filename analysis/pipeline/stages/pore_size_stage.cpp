// pores: F(delta) by the method of --pores: on the pore grid (--pore-voxels) by the exact periodic
// distance transform (voxel), refined to each void voxel centre's distance to the nearest surface
// (refined), or from random points without voxels (exact); the result is kept for transport, the
// pore-size map optionally exported.
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "pores/distance_transform.hpp"
#include "pores/exact_pore_size.hpp"
#include "pores/pore_size_fields.hpp"
#include "pores/refined_pore_size.hpp"
#include "voxels/voxelization.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <vector>

namespace sbpack::stages {

StageMemory poreSizesMemory(const Packing& packing, const RunSettings& settings) {
    const int m = settings.poreVoxels();
    switch (settings.poreMethod()) {
    case PoreMethod::Exact: {
        const std::int64_t k = settings.pores.exactParameters().randomPoints;
        return {static_cast<double>(k) * 2.0 * sizeof(double) +
                    static_cast<double>(packing.size()) * 100.0,
                fmt::format("exact pore sizes of {} points", k), "--pore-points"};
    }
    case PoreMethod::Refined:
        return {static_cast<double>(poreSizeMemoryBytes(m)) + 4.0 * m * m * static_cast<double>(m),
                fmt::format("pore-size map and feature transform {}^3", m), "--pore-voxels"};
    case PoreMethod::Voxel:
        break;
    }
    return {static_cast<double>(poreSizeMemoryBytes(m)), fmt::format("pore-size map {}^3", m),
            "--pore-voxels"};
}

namespace {

/// The pore-size map of the packing on an M^3 grid, with the feature transform when asked (the
/// solid mask is released on return).
PoreSizeMap poreSizeMap(const FileContext& context, int m, bool features) {
    checkPoreSizeMemory(m);
#ifdef SBPACK_WITH_CUDA
    if (context.gridsOnGpu() && !features)
        return cudaPoreSizeMap(context, m); // refined pore sizes run on the CPU (docs/gpu.md)
#endif
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    double voxelSize = 0.0;
    {
        const Voxelization voxels = Voxelizer({m}).compute(context.packing(), context.progress());
        voxels.copySolidMask(mask, context.progress());
        voxelSize = voxels.voxelSize();
        context.progress().stageDone(
            "pore voxelization", voxels.runtimeSeconds(),
            fmt::format("{}^3, phi_voxel = {}", m, describe(voxels.phiVoxel())));
    }
    const Stopwatch clock;
    PoreSizeMap map = features ? periodicFeatureTransform(mask, m, voxelSize, context.progress())
                               : periodicDistanceTransform(mask, m, voxelSize, context.progress());
    context.progress().stageDone(features ? "distance and feature transform" : "distance transform",
                                 clock.seconds(), fmt::format("{} void voxels", map.voidCount()));
    return map;
}

/// The pore sizes by the run's method; `map` is filled unless the method is exact or the GPU
/// made the histogram alone, and mapSeconds is the time the distances took.
PoreSizeDistributionResult measurePores(const FileContext& context, std::optional<PoreSizeMap>& map,
                                        double& mapSeconds) {
    const RunSettings& s = context.settings();
    if (s.poreMethod() == PoreMethod::Exact)
        return ExactPoreSizeDistribution(s.pores.exactParameters())
            .compute(context.packing(), context.progress());
    const bool refined = s.poreMethod() == PoreMethod::Refined;
    const PoreSizeParameters parameters = s.pores.gridParameters();
    const Stopwatch clock;
#ifdef SBPACK_WITH_CUDA
    // All voxels counted and no export: the histogram alone comes back from the GPU.
    if (context.gridsOnGpu() && !refined && s.pores.points == 0 &&
        context.vdbExport(Analysis::PoreSizes) == nullptr) {
        PoreSizeDistributionResult pores = cudaPoreSizes(context, s.poreVoxels(), parameters);
        mapSeconds = clock.seconds() - pores.runtimeSeconds;
        return pores;
    }
#endif
    map.emplace(poreSizeMap(context, s.poreVoxels(), refined));
    mapSeconds = clock.seconds();
    if (refined)
        return RefinedPoreSizeDistribution(parameters)
            .compute(*map, context.packing(), context.progress());
    return PoreSizeDistribution(parameters).compute(*map, context.meanWidth(), context.progress());
}

/// The progress line's detail: the moment, the largest pore, and what bounds the error.
std::string poreDetail(const PoreSizeDistributionResult& pores) {
    std::string detail = fmt::format("<delta>/w = {}", describe(pores.meanOverWidth()));
    if (std::isfinite(pores.meanStandardError))
        detail += fmt::format(" +- {}", describe(pores.meanStandardError / pores.meanWidth));
    detail += fmt::format(", max/w = {}{}", describe(pores.maxOverWidth()),
                          pores.saturated ? " (saturated)" : " (NOT below w/2)");
    if (std::isfinite(pores.errorBound))
        detail += fmt::format(", certified to {:.1e} w", pores.errorBound / pores.meanWidth);
    return detail;
}

/// --distribute grids: F(delta) of the slabs' distance transform (pipeline/distributed_grids.hpp).
bool runDistributedPoreSizes(FileContext& context, schema::Record& record) {
    DistributionFigures figures;
    PoreSizeDistributionResult pores = context.grids()->poreSizes(
        context.packing(), context.settings().poreVoxels(), PoreSizeParameters{},
        context.meanWidth(), context.progress(), figures);
    context.progress().stageDone("pore sizes", pores.runtimeSeconds,
                                 fmt::format("{} ranks, <delta>/w = {}, max/w = {}", figures.ranks,
                                             describe(pores.meanOverWidth()),
                                             describe(pores.maxOverWidth())));
    PoreSizeFigures recorded{std::move(pores), std::nullopt, figures};
    pore_size_fields::kTable.fill(record, recorded, context.scales());
    context.keep(Analysis::PoreSizes, std::move(recorded.pores));
    return true;
}

} // namespace

bool runPoreSizes(FileContext& context, schema::Record& record) {
    if (context.grids() != nullptr) return runDistributedPoreSizes(context, record);
    std::optional<PoreSizeMap> map;
    double mapSeconds = 0.0;
    PoreSizeDistributionResult pores = measurePores(context, map, mapSeconds);
    context.progress().stageDone(
        fmt::format("pore sizes ({})", poreMethodName(context.settings().poreMethod())),
        pores.runtimeSeconds, poreDetail(pores));
    if (const VdbExport* vdb = context.vdbExport(Analysis::PoreSizes); vdb != nullptr && map) {
        const Stopwatch clock;
        vdb->output->write(map->vdbImage(context.lengthUnit()));
        context.progress().stageDone("pore vdb export", clock.seconds(), vdb->destination.string());
    }
    const bool gridded = context.settings().poreMethod() != PoreMethod::Exact;
    PoreSizeFigures recorded{std::move(pores), gridded ? std::optional(mapSeconds) : std::nullopt,
                             std::nullopt};
    pore_size_fields::kTable.fill(record, recorded, context.scales());
    context.keep(Analysis::PoreSizes, std::move(recorded.pores));
    return true;
}

} // namespace sbpack::stages

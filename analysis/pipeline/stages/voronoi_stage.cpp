// voronoi: the set-Voronoi cells of voronoi/set_voronoi.hpp on the spectral grid (--voxels),
// their local packing fractions split by the rattlers that contacts found.
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "voronoi/voronoi_fields.hpp"

#include <fmt/format.h>

namespace sbpack::stages {

StageMemory voronoiMemory(const Packing&, const RunSettings& settings) {
    const int m = settings.voxelization.voxels;
    return {SetVoronoi::memoryBytes(m), fmt::format("set-Voronoi labels and features {}^3", m),
            "--voxels"};
}

bool runVoronoi(FileContext& context, schema::Record& record) {
    const SetVoronoiResult cells =
        SetVoronoi(context.settings().voxelization.voxels)
            .compute(context.packing(), context.kept<KeptContacts>(Analysis::Contacts).rattler,
                     context.progress());
    context.progress().stageDone("set-Voronoi cells", cells.runtimeSeconds,
                                 fmt::format("{}^3, local phi {} +- {} (voxel rounding {})",
                                             cells.voxels, describe(cells.all.mean, 4),
                                             describe(cells.all.sd, 3),
                                             describe(cells.voxelErrorRms, 2)));
    voronoi_fields::kTable.fill(record, cells, context.scales());
    return true;
}

} // namespace sbpack::stages

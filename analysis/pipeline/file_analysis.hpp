#pragma once
// The analyses of one packing file: its results groups, filled by the registry's stages.

#include "packing/packing.hpp"
#include "pipeline/run_settings.hpp"
#include "pipeline/stage.hpp"
#include "progress/progress.hpp"
#include "schema/record.hpp"
#include "schema/shape_record.hpp"

#include <filesystem>
#include <map>
#include <string_view>
#include <vector>

namespace sbpack {

/// What a results file holds of one input (files/<i>): its attributes and one group per
/// analysis that ran and applied.
struct FileResults {
    std::filesystem::path input;
    schema::Record root{schema::fileGroup()};
    std::vector<schema::Record> groups;
    /// A mixture's largest semi-axis over its smallest (docs/mixtures.md), 1 for identical
    /// particles: inputs of other sizes form other ensembles (not written to the file).
    double sizeRatio = 1.0;

    /// The group called `name` (e.g. "contacts"); nullptr if it was not written.
    const schema::Record* group(std::string_view name) const;
    ShapeSpec shape() const { return schema::shapeOf(root); }
    std::int64_t particles() const { return root.integer("n_particles"); }
};

/// Runs the analyses of `settings` on one packing (already validated), in runOrder, reporting one
/// line per stage. `exports`: where analyses with a vdbSuffix export their grids; `grids`: the
/// distributed grid computations under --distribute grids (every rank calls it), else nullptr.
FileResults analyzeFile(const Packing& packing, const std::filesystem::path& input,
                        const RunSettings& settings, const Progress& progress,
                        const std::map<Analysis, VdbExport>& exports = {},
                        const DistributedGrids* grids = nullptr);

} // namespace sbpack

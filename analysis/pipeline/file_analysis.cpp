#include "pipeline/file_analysis.hpp"

#include "contacts/contact_network.hpp"
#include "contacts/contact_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sbpack {

namespace {

/// The file's attributes: its lengths as read, phi of the packing the stages see (in its
/// analysis length unit, where N v1 / L^3 neither overflows nor underflows).
schema::Record fileRecord(const Packing& packing, const std::filesystem::path& input,
                          const FileContext& context) {
    schema::Record r(schema::fileGroup());
    r.set("input", input.string());
    schema::setShape(r, packing.shapeSpec);
    r.set("n_particles", packing.size())
        .set("box_length", packing.boxLength)
        .set("semi_axis", packing.semiAxis)
        .set("phi", context.packing().packingFraction())
        .set("mean_width", packing.shape().meanWidth());
    return r;
}

/// A packing with overlapping pairs is analysed as given, with a warning (count and worst).
void warnAboutOverlaps(const Packing& packing, const Progress& progress) {
    const ContactResult c = ContactNetwork({}).compute(packing);
    if (c.overlappingPairs == 0) return;
    const bool rounded =
        overlapsWithinRounding(c, 2.0 * packing.semiAxis, singlePrecisionRounding(packing));
    progress.warn(describeOverlaps(c, 2.0 * packing.semiAxis) +
                  (rounded ? ": within the rounding of its single-precision coordinates "
                             "(docs/design.md §3, \"Honest contacts\"); analysed as given"
                           : ": not a packing of hard particles; analysed as given"));
}

/// Whether a stage after position `done` of `order` needs `analysis`.
bool neededLater(Analysis analysis, const std::vector<Analysis>& order, std::size_t done) {
    for (std::size_t later = done + 1; later < order.size(); ++later) {
        const auto needs = analysisInfo(order[later]).needs;
        if (std::find(needs.begin(), needs.end(), analysis) != needs.end()) return true;
    }
    return false;
}

} // namespace

const schema::Record* FileResults::group(std::string_view name) const {
    for (const schema::Record& g : groups)
        if (g.group().name == name) return &g;
    return nullptr;
}

FileResults analyzeFile(const Packing& packing, const std::filesystem::path& input,
                        const RunSettings& settings, const Progress& progress,
                        const std::map<Analysis, VdbExport>& exports,
                        const DistributedGrids* grids) {
    FileContext context(packing, settings, progress, exports);
    warnAboutOverlaps(context.packing(), progress);
    if (settings.distribute == Distribution::Grids) context.distributeGrids(grids);
    FileResults results{input, fileRecord(packing, input, context), {}};
    if (packing.isMixture()) results.sizeRatio = packing.semiAxis / packing.smallestSemiAxis();
    if (settings.device.device == ComputeDevice::Cuda && !context.gridsOnGpu())
        progress.warn(packing.isMixture()
                          ? "--device cuda: a mixture's grids are computed on the CPU (the GPU "
                            "voxeliser reads one size; docs/mixtures.md)"
                          : "--device cuda: the grids of " +
                                std::string(packing.shape().familyName()) +
                                "s are computed on the CPU (the GPU voxeliser's inside test is "
                                "the superball's; docs/gpu.md)");
    const std::vector<Analysis> order = runOrder(settings.analyses);
    for (std::size_t i = 0; i < order.size(); ++i) {
        const AnalysisInfo& info = analysisInfo(order[i]);
        schema::Record record(info.group());
        if (info.run(context, record)) results.groups.push_back(std::move(record));
        for (schema::Record& extra : context.takeGroups())
            results.groups.push_back(std::move(extra));
        // Big intermediates (the spectral voxelization) go as soon as nothing needs them.
        for (std::size_t j = 0; j <= i; ++j)
            if (!neededLater(order[j], order, i)) context.release(order[j]);
    }
    return results;
}

} // namespace sbpack

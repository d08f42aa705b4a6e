// variance: the local volume-fraction variance by sampled windows on the kept voxel grid
// (--voxels) and by the spectral route over chi's kept spectrum with chi_V exact at small Q as
// hyper's (docs/local-structure.md §2).
#include "pipeline/ensemble.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "variance/variance_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sbpack::stages {

StageMemory varianceMemory(const Packing&, const RunSettings& settings) {
    const int m = settings.voxelization.voxels;
    return {VolumeFractionVariance::memoryBytes(m), fmt::format("variance row sums {}^3", m),
            "--voxels"};
}

bool runVariance(FileContext& context, schema::Record& record) {
    const DiscreteSpectrum spectrum =
        spectrumOf(context, context.kept<KeptSpectrum>(Analysis::SpectralDensity).spectrum);
    const VarianceResult r =
        VolumeFractionVariance(context.settings().variance)
            .compute(spectrum, &context.kept<Voxelization>(Analysis::Voxels), context.progress());
    std::string detail =
        r.exponent
            ? fmt::format("alpha = {} +- {}{} (R / w {} .. {})", describe(r.exponent->alpha, 3),
                          describe(r.exponent->standardError, 2),
                          r.exponent->saturated ? " (>= 1)" : "",
                          describe(r.exponent->minRadius / context.meanWidth(), 3),
                          describe(r.exponent->maxRadius / context.meanWidth(), 3))
            : std::string("no tail fit (the box is too small)");
    context.progress().stageDone(
        "variance", r.runtimeSeconds,
        fmt::format("{} radii, {} windows each; {}", r.radius.size(), r.windows, detail));
    variance_fields::kTable.fill(record, r, context.scales());
    return true;
}

void poolVariance(EnsembleResults& e, std::span<const FileResults> files) {
    std::vector<const schema::Record*> groups;
    double maxRadiusW = INFINITY;
    for (std::size_t m : e.members)
        if (const schema::Record* v = files[m].group(kVarianceGroup.name)) {
            groups.push_back(v);
            maxRadiusW = std::min(maxRadiusW, 0.25 * files[m].root.number("box_length") /
                                                  files[m].root.number("mean_width"));
        }
    if (groups.empty()) return;
    std::size_t n = SIZE_MAX;
    for (const schema::Record* v : groups)
        n = std::min(n, v->floats("radius_w").size()); // the radii are one sequence's prefixes
    std::vector<double> mean(n, 0.0);
    for (const schema::Record* v : groups) {
        const std::vector<double>& sigma2 = v->floats("sigma2_spectral");
        for (std::size_t i = 0; i < n; ++i)
            mean[i] += sigma2[i] / static_cast<double>(groups.size());
    }
    const std::span<const double> radius(groups.front()->floats("radius_w").data(), n);
    const std::optional<VarianceExponent> tail =
        fitVarianceTail(radius, mean, VarianceParameters{}.fitMinRadiusW, maxRadiusW);
    if (!tail) return;
    e.group(kVarianceGroup.name)
        ->set("alpha_pooled", tail->alpha)
        .set("alpha_pooled_error", tail->standardError)
        .set("alpha_pooled_saturated", static_cast<std::int64_t>(tail->saturated));
}

} // namespace sbpack::stages

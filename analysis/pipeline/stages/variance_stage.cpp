// variance: the local volume-fraction variance by sampled windows on the kept voxel grid
// (--voxels) and by the spectral route over chi's kept spectrum with chi_V exact at small Q as
// hyper's (docs/local-structure.md §2).
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "variance/variance_fields.hpp"

#include <fmt/format.h>

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

} // namespace sbpack::stages

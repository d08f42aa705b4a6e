// What several stages share.
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "schema/record.hpp"
#include "spectral/exact_spectral_density.hpp"
#include "spectral/form_factors.hpp"

#include "packing/packing.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace sbpack::stages {

DiscreteSpectrum spectrumOf(FileContext& context, const DiscreteSpectrum& voxel) {
    const double qmax = context.settings().hyperuniformity.chiExactQw;
    if (qmax == 0.0) return voxel;
    const Packing& packing = context.packing();
    if (sumsFormFactors(packing) && !hasFormFactor(packing.shape())) {
        context.progress().warn(fmt::format(
            "exact chi: no form factor of {}s (spectral/form_factors.hpp); the voxel spectrum "
            "alone at small Q",
            packing.shape().familyName()));
        return voxel;
    }
    ExactSpectralDensityParameters parameters;
    parameters.maxQw = qmax;
    const ExactSpectralDensityResult exact =
        ExactSpectralDensity(parameters).compute(packing, context.progress());
    context.progress().stageDone(
        "exact chi", exact.runtimeSeconds,
        fmt::format("{} wave vectors up to Q w = {}", 2 * exact.modes.size(), describe(qmax, 3)));
    return withExactSmallQ(voxel, exact);
}

std::string describe(double value, int digits) {
    return fmt::format("{:.{}g}", value, digits);
}

double collectiveDensityBytes(const Packing& packing, int maxShell) {
    const double modes = 2.0 / 3.0 * std::numbers::pi * std::pow(maxShell + 0.5, 3);
    return 6.0 * 8.0 * static_cast<double>(packing.size()) * (maxShell + 1) + modes * 2.0 * 20.0;
}

} // namespace sbpack::stages

#include "structure/structure_factor.hpp"

#include "structure/collective_density.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

StructureFactor::StructureFactor(StructureFactorParameters parameters) : parameters_(parameters) {
    if (!(parameters.maxQw > 0.0) || !std::isfinite(parameters.maxQw))
        throw std::invalid_argument("structure factor: qmax must be positive and finite, not " +
                                    fmt::format("{:g}", parameters.maxQw));
}

int StructureFactor::maxShellFor(double maxQw, double boxLength, double meanWidth) {
    // Saturated below INT_MAX: a huge qmax is a huge shell count (refused by the memory
    // estimate), never an overflow read as "below the box's smallest wave number".
    const double shells = std::floor(maxQw * boxLength / (2.0 * std::numbers::pi * meanWidth));
    return static_cast<int>(std::min(shells, 1e9));
}

StructureFactorResult StructureFactor::compute(const Packing& packing,
                                               const Progress& progress) const {
    const Stopwatch clock;
    StructureFactorResult result;
    result.parameters = parameters_;
    result.boxLength = packing.boxLength;
    result.meanWidth = packing.shape().meanWidth();
    result.maxShell = maxShellFor(parameters_.maxQw, packing.boxLength, result.meanWidth);
    if (result.maxShell < 1)
        throw std::invalid_argument(
            "structure factor: qmax = " + fmt::format("{:g}", parameters_.maxQw) +
            " is below the smallest wave number of the box, 2 pi w / L = " +
            std::to_string(2.0 * std::numbers::pi * result.meanWidth / packing.boxLength));
    const DensityModes modes = collectiveDensity(packing.positions, packing.boxLength,
                                                 maxSquaredIndex(result.maxShell), progress);
    const auto n = static_cast<double>(packing.size());
    ShellAccumulator shells(packing.boxLength, result.maxShell);
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const auto& k = modes.n[m];
        const std::int64_t n2 = static_cast<std::int64_t>(k[0]) * k[0] +
                                static_cast<std::int64_t>(k[1]) * k[1] +
                                static_cast<std::int64_t>(k[2]) * k[2];
        shells.add(n2, modes.intensity[m] / n, 2); // S(Q) = S(-Q): n stands for +-n
    }
    result.shells = shells.average();
    result.runtimeSeconds = clock.seconds();
    return result;
}

} // namespace sbpack

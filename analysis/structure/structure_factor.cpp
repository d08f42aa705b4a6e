#include "structure/structure_factor.hpp"

#include "structure/collective_density.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <set>
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

namespace {

/// The species of a binary mixture: true for the large particles (semi-axis the largest);
/// empty unless the packing has exactly two sizes.
std::vector<bool> binarySpecies(const Packing& packing) {
    if (std::set<double>(packing.semiAxes.begin(), packing.semiAxes.end()).size() != 2) return {};
    std::vector<bool> large;
    for (const double r : packing.semiAxes)
        large.push_back(r == packing.semiAxis);
    return large;
}

/// The partials of `species` (binarySpecies) on the shells of S, from each species' own rho(Q)
/// (two sums independent of the total's).
PartialStructureFactors partialStructureFactors(const Packing& packing,
                                                const std::vector<bool>& species, int maxShell,
                                                std::int64_t maxN2, const Progress& progress) {
    std::vector<Vector3d> a, b;
    for (std::size_t i = 0; i < packing.size(); ++i)
        (species[i] ? a : b).push_back(packing.positions[i]);
    const DensityModes ma = collectiveDensity(a, packing.boxLength, maxN2, progress, true);
    const DensityModes mb = collectiveDensity(b, packing.boxLength, maxN2, progress, true);
    const auto na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
    ShellAccumulator aa(packing.boxLength, maxShell), bb(packing.boxLength, maxShell),
        ab(packing.boxLength, maxShell);
    for (std::size_t m = 0; m < ma.size(); ++m) {
        const std::int64_t n2 = squaredIndex(ma.n[m]);
        aa.add(n2, ma.intensity[m] / na, 2);
        bb.add(n2, mb.intensity[m] / nb, 2);
        ab.add(n2, (ma.amplitude[m] * std::conj(mb.amplitude[m])).real() / std::sqrt(na * nb), 2);
    }
    return {na / (na + nb), aa.average().value, bb.average().value, ab.average().value};
}

} // namespace

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
    const std::int64_t maxN2 = maxSquaredIndex(result.maxShell);
    const DensityModes modes =
        collectiveDensity(packing.positions, packing.boxLength, maxN2, progress);
    const auto n = static_cast<double>(packing.size());
    ShellAccumulator shells(packing.boxLength, result.maxShell);
    for (std::size_t m = 0; m < modes.size(); ++m) {
        shells.add(squaredIndex(modes.n[m]), modes.intensity[m] / n,
                   2); // S(Q) = S(-Q): n stands for +-n
    }
    result.shells = shells.average();
    if (const std::vector<bool> species = binarySpecies(packing); !species.empty())
        result.partials =
            partialStructureFactors(packing, species, result.maxShell, maxN2, progress);
    result.runtimeSeconds = clock.seconds();
    return result;
}

} // namespace sbpack

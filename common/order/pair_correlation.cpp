#include "order/pair_correlation.hpp"

#include "contacts/cell_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sbpack {
namespace {

/// n = floor(r_max / dr), forgiving the round-off of a ratio meant to be whole (3 / 0.02).
int binCount(const PairCorrelationParameters& parameters) {
    return static_cast<int>(
        std::floor(parameters.maxDistance / parameters.binWidth * (1.0 + 1e-12)));
}

/// Moving average over [b - h, b + h], cut at the ends.
std::vector<double> movingAverage(const std::vector<double>& values, int halfWidth) {
    const auto n = static_cast<int>(values.size());
    std::vector<double> smooth(values.size());
    for (int b = 0; b < n; ++b) {
        const int first = std::max(0, b - halfWidth);
        const int last = std::min(n - 1, b + halfWidth);
        double sum = 0.0;
        for (int k = first; k <= last; ++k)
            sum += values[k];
        smooth[b] = sum / (last - first + 1);
    }
    return smooth;
}

/// The mean of sigma_ij^3 over all ordered pairs (i, j), self pairs included, sigma_ij =
/// Packing::pairSize: an ideal gas's pair count at reduced distance r is that of identical
/// particles times it (docs/order-metrics.md §1, mixtures). 1 for identical particles. From the
/// moments M_k = sum_i s_i^k: sum_ij ((s_i + s_j) / 2)^3 = (2 N M_3 + 6 M_1 M_2) / 8.
double meanCubedPairSize(const Packing& packing) {
    if (!packing.isMixture()) return 1.0;
    double m1 = 0.0, m2 = 0.0, m3 = 0.0;
    for (const double s : packing.relativeSizes()) {
        m1 += s;
        m2 += s * s;
        m3 += s * s * s;
    }
    const auto n = static_cast<double>(packing.size());
    return (2.0 * n * m3 + 6.0 * m1 * m2) / (8.0 * n * n);
}

} // namespace

PairCorrelation::PairCorrelation(PairCorrelationParameters parameters) : parameters_(parameters) {
    if (!(parameters.binWidth > 0.0) || !(parameters.binWidth <= parameters.maxDistance) ||
        !std::isfinite(parameters.maxDistance))
        throw std::invalid_argument(fmt::format(
            "pair correlation: need 0 < dr <= r_max < inf, not dr = {:g}, r_max = {:g} (units of "
            "w)",
            parameters.binWidth, parameters.maxDistance));
}

PairCorrelationResult PairCorrelation::compute(const Packing& packing) const {
    const std::size_t n = packing.size();
    const double w = packing.shape().meanWidth();
    const double dr = parameters_.binWidth * w; // length units
    const int bins = binCount(parameters_);
    if (n < 2) throw std::invalid_argument("pair correlation: needs at least 2 particles");
    if (bins * dr > 0.5 * packing.boxLength)
        throw std::invalid_argument(
            fmt::format("pair correlation: r_max = {:g} w exceeds L / 2 = {:g} w",
                        bins * parameters_.binWidth, 0.5 * packing.boxLength / w));
    PairCorrelationResult result;
    result.parameters = parameters_;
    result.meanWidth = w;
    const double rho = static_cast<double>(n) / std::pow(packing.boxLength, 3);
    result.numberDensity = rho * w * w * w;
    result.pairCount.assign(bins, 0);
    // A mixture's pair counts at r_ij / sigma_ij; a pair of sigma_ij < 1 ends at r_max sigma_ij.
    forEachNeighbourPair(packing.positions, packing.boxLength, bins * dr,
                         [&](int i, int j, const Vector3d& d) {
                             const double sigma = packing.pairSize(i, j);
                             const double r = d.norm() / sigma;
                             if (sigma < 1.0 && r >= bins * dr) return;
                             const auto b = static_cast<int>(r / dr);
                             ++result.pairCount[std::min(b, bins - 1)]; // round-off at r_max
                         });
    const double pairVolume = meanCubedPairSize(packing);
    for (int b = 0; b < bins; ++b) {
        const double shell =
            4.0 * std::numbers::pi / 3.0 * (std::pow((b + 1) * dr, 3) - std::pow(b * dr, 3));
        const double idealPairs =
            0.5 * static_cast<double>(n) * rho * shell * pairVolume; // Eq. 1.2
        result.r.push_back((b + 0.5) * parameters_.binWidth);
        result.g2.push_back(static_cast<double>(result.pairCount[b]) / idealPairs); // Eq. 1.1
        result.idealGasError.push_back(1.0 / std::sqrt(idealPairs));
    }
    return result;
}

double firstMinimum(const PairCorrelationResult& result, int smoothingBins) {
    if (smoothingBins < 0)
        throw std::invalid_argument(
            fmt::format("first minimum of g2: the smoothing half-width must be >= 0 bins, not {}",
                        smoothingBins));
    const std::vector<double> g = movingAverage(result.g2, smoothingBins);
    const auto n = static_cast<int>(g.size());
    const int peak = static_cast<int>(std::max_element(g.begin(), g.end()) - g.begin());
    for (int b = peak + 1; b < n; ++b) {
        if (!(g[b] < 1.0) || g[b] > g[b - 1]) continue;
        int end = b; // the run of values equal to g[b]
        while (end + 1 < n && g[end + 1] == g[b])
            ++end;
        if (end + 1 < n && g[end + 1] > g[b]) return 0.5 * (result.r[b] + result.r[end]);
        b = end;
    }
    throw std::runtime_error(fmt::format(
        "first minimum of g2: no local minimum below 1 after the main peak at r = {:g} w, up to "
        "r_max = {:g} w",
        result.r.empty() ? 0.0 : result.r[peak], result.r.empty() ? 0.0 : result.r.back()));
}

} // namespace sbpack

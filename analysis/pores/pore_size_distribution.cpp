#include "pores/pore_size_distribution.hpp"

#include "parallel/parallel.hpp"
#include "pores/random_points.hpp"
#include "random/random.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace sbpack {

namespace {

std::vector<double> scaled(const std::vector<double>& values, double factor) {
    std::vector<double> out(values.size());
    std::transform(values.begin(), values.end(), out.begin(),
                   [factor](double v) { return v * factor; });
    return out;
}

void checkMeanWidth(double meanWidth) {
    if (!(std::isfinite(meanWidth) && meanWidth > 0.0))
        throw std::invalid_argument("pore sizes: mean width " + std::to_string(meanWidth) +
                                    " is not finite and positive");
}

/// Right-continuous value of a result's step function F at x >= 0.
double stepValue(const PoreSizeDistributionResult& r, double x) {
    const auto above = std::upper_bound(r.delta.begin(), r.delta.end(), x);
    return r.F[static_cast<std::size_t>(above - r.delta.begin()) - 1];
}

void checkDensityBins(int densityBins) {
    if (densityBins < 1)
        throw std::invalid_argument("pore sizes: densityBins = " + std::to_string(densityBins) +
                                    " (need >= 1)");
}

} // namespace

PoreMethod poreMethodFromName(std::string_view name) {
    if (name == "voxel") return PoreMethod::Voxel;
    if (name == "refined") return PoreMethod::Refined;
    if (name == "exact") return PoreMethod::Exact;
    throw std::invalid_argument("option --pores: '" + std::string(name) +
                                "' is not one of voxel, refined, exact");
}

std::string_view poreMethodName(PoreMethod method) {
    switch (method) {
    case PoreMethod::Voxel:
        return "voxel";
    case PoreMethod::Refined:
        return "refined";
    case PoreMethod::Exact:
        return "exact";
    }
    return "?";
}

void PoreSizeSums::add(double delta, std::int64_t times) {
    const double n = static_cast<double>(times), square = delta * delta;
    count += times;
    sum += n * delta;
    sumSquares += n * square;
    sumCubes += n * square * delta;
    sumFourth += n * square * square;
}

void PoreSizeSums::add(const PoreSizeSums& other) {
    count += other.count;
    sum += other.sum;
    sumSquares += other.sumSquares;
    sumCubes += other.sumCubes;
    sumFourth += other.sumFourth;
}

void setStandardErrors(PoreSizeDistributionResult& r, const PoreSizeSums& sums) {
    if (sums.count < 2) {
        r.meanStandardError = r.secondMomentStandardError = PoreSizeDistributionResult::kUnset;
        return;
    }
    const double n = static_cast<double>(sums.count);
    // Sample variances (n - 1) of delta and of delta^2; the standard error is sqrt(var / n).
    const double varianceDelta =
        std::max(0.0, (sums.sumSquares - sums.sum * sums.sum / n) / (n - 1));
    const double varianceSquare =
        std::max(0.0, (sums.sumFourth - sums.sumSquares * sums.sumSquares / n) / (n - 1));
    r.meanStandardError = std::sqrt(varianceDelta / n);
    r.secondMomentStandardError = std::sqrt(varianceSquare / n);
}

PoreSizeDistributionResult binnedPoreSizeStatistics(std::span<const std::int64_t> counts, double h,
                                                    const PoreSizeSums& sums, double largest,
                                                    double meanWidth, int densityBins) {
    checkMeanWidth(meanWidth);
    checkDensityBins(densityBins);
    if (sums.count < 1 || !(h > 0.0) || !(largest > 0.0) || !std::isfinite(largest))
        throw std::invalid_argument("pore sizes: a binned sample needs points, a positive bin "
                                    "width and a positive, finite largest size");
    std::size_t last = counts.size();
    while (last > 0 && counts[last - 1] == 0)
        --last;
    if (last == 0 || static_cast<double>(last - 1) * h > largest ||
        largest > last * h * (1 + 1e-12))
        throw std::invalid_argument("pore sizes: the largest size is not in the last bin");
    PoreSizeDistributionResult r;
    r.meanWidth = meanWidth;
    r.samples = sums.count;
    r.parameters.densityBins = densityBins;
    r.binWidth = h;
    const auto total = static_cast<double>(sums.count);
    std::int64_t remaining = sums.count;
    r.delta = {0.0};
    r.F = {1.0}; // every pore size is positive
    for (std::size_t j = 0; j < last; ++j) {
        if (j > 0) {
            r.delta.push_back(static_cast<double>(j) * h);
            r.F.push_back(static_cast<double>(remaining) / total); // Eq. 13 at the bin edge
        }
        remaining -= counts[j];
    }
    if (largest > r.delta.back()) {
        r.delta.push_back(largest);
        r.F.push_back(0.0);
    } else {
        r.F.back() = 0.0;
    }
    r.mean = sums.sum / total;                // Eq. 14
    r.secondMoment = sums.sumSquares / total; // Eq. 15
    r.max = largest;
    r.saturated = r.max < 0.5 * meanWidth; // paper Sec. V A
    const double width = r.max / densityBins;
    std::vector<std::int64_t> histogram(densityBins, 0);
    for (std::size_t j = 0; j < last; ++j)
        histogram[std::min(densityBins - 1, static_cast<int>((static_cast<double>(j) + 0.5) * h /
                                                             width))] += counts[j];
    r.densityDelta.resize(densityBins);
    r.density.resize(densityBins);
    for (int b = 0; b < densityBins; ++b) {
        r.densityDelta[b] = (b + 0.5) * width;
        r.density[b] = static_cast<double>(histogram[b]) / (total * width);
    }
    return r;
}

std::vector<double> PoreSizeDistributionResult::deltaOverWidth() const {
    return scaled(delta, 1.0 / meanWidth);
}

std::vector<double> PoreSizeDistributionResult::densityDeltaOverWidth() const {
    return scaled(densityDelta, 1.0 / meanWidth);
}

std::vector<double> PoreSizeDistributionResult::densityTimesWidth() const {
    return scaled(density, meanWidth);
}

PoreSizeDistributionResult poreSizeStatistics(std::span<const double> sizes,
                                              std::span<const std::int64_t> counts,
                                              double meanWidth, int densityBins) {
    checkMeanWidth(meanWidth);
    if (sizes.empty() || sizes.size() != counts.size())
        throw std::invalid_argument("pore sizes: " + std::to_string(sizes.size()) + " sizes and " +
                                    std::to_string(counts.size()) +
                                    " counts (need the same, at least one)");
    checkDensityBins(densityBins);
    std::int64_t total = 0;
    for (std::size_t j = 0; j < sizes.size(); ++j) {
        if (!(std::isfinite(sizes[j]) && sizes[j] > 0.0) || (j > 0 && !(sizes[j] > sizes[j - 1])))
            throw std::invalid_argument("pore sizes: sizes must be finite, positive and strictly "
                                        "ascending (entry " +
                                        std::to_string(j) + ")");
        if (counts[j] < 1)
            throw std::invalid_argument("pore sizes: count " + std::to_string(counts[j]) +
                                        " of entry " + std::to_string(j) + " is not positive");
        total += counts[j];
    }
    PoreSizeDistributionResult r;
    r.meanWidth = meanWidth;
    r.samples = total;
    r.parameters.densityBins = densityBins;
    r.delta.reserve(sizes.size() + 1);
    r.F.reserve(sizes.size() + 1);
    r.delta.push_back(0.0);
    r.F.push_back(1.0); // F(0) = 1: every pore size is positive
    std::int64_t remaining = total;
    double sum = 0.0, sumSquares = 0.0;
    for (std::size_t j = 0; j < sizes.size(); ++j) {
        remaining -= counts[j];
        r.delta.push_back(sizes[j]);
        r.F.push_back(static_cast<double>(remaining) / static_cast<double>(total)); // Eq. 13
        sum += static_cast<double>(counts[j]) * sizes[j];
        sumSquares += static_cast<double>(counts[j]) * sizes[j] * sizes[j];
    }
    r.mean = sum / static_cast<double>(total);                // Eq. 14
    r.secondMoment = sumSquares / static_cast<double>(total); // Eq. 15
    r.max = sizes.back();
    r.saturated = r.max < 0.5 * meanWidth; // paper Sec. V A: max delta < w / 2
    const double width = r.max / densityBins;
    std::vector<std::int64_t> histogram(densityBins, 0);
    for (std::size_t j = 0; j < sizes.size(); ++j)
        histogram[std::min(densityBins - 1, static_cast<int>(sizes[j] / width))] += counts[j];
    r.densityDelta.resize(densityBins);
    r.density.resize(densityBins);
    for (int b = 0; b < densityBins; ++b) {
        r.densityDelta[b] = (b + 0.5) * width;
        r.density[b] = static_cast<double>(histogram[b]) / (static_cast<double>(total) * width);
    }
    return r;
}

double largestGap(const PoreSizeDistributionResult& a, const PoreSizeDistributionResult& b) {
    if (a.delta.empty() || b.delta.empty())
        throw std::invalid_argument("largestGap: a result without F(delta)");
    double gap = 0.0;
    for (const PoreSizeDistributionResult* r : {&a, &b})
        for (const double x : r->delta)
            gap = std::max(gap, std::abs(stepValue(a, x) - stepValue(b, x)));
    return gap;
}

PoreSizeDistribution::PoreSizeDistribution(PoreSizeParameters parameters)
    : parameters_(parameters) {
    if (parameters_.randomPoints < 0)
        throw std::invalid_argument("pore sizes: the number of random points K = " +
                                    std::to_string(parameters_.randomPoints) +
                                    " is negative (0 = every void voxel)");
    if (parameters_.densityBins < 1)
        throw std::invalid_argument("pore sizes: densityBins = " +
                                    std::to_string(parameters_.densityBins) + " (need >= 1)");
}

PoreSizeDistributionResult PoreSizeDistribution::compute(const PoreSizeMap& map, double meanWidth,
                                                         const Progress& progress) const {
    const auto started = std::chrono::steady_clock::now();
    checkMeanWidth(meanWidth);
    const int m = map.voxels();
    const std::int64_t plane = static_cast<std::int64_t>(m) * m;
    const std::int64_t total = plane * m;
    const std::uint32_t* squared = map.squaredDistances().data();
    const std::size_t levels = static_cast<std::size_t>(map.maxSquaredDistance()) + 1;

    // Histogram of the squared distances n (voxel units): the pore size is a sqrt(n). Each chunk
    // counts into its own histogram (split by output block), summed in order afterwards.
    const bool sampled = parameters_.randomPoints > 0;
    if (sampled) checkRandomVoidFraction(map.voidFraction(), m);
    const std::int64_t planesPerChunk = std::max<std::int64_t>(1, m / 64);
    const std::int64_t chunks =
        sampled ? (parameters_.randomPoints + kRandomPointChunk - 1) / kRandomPointChunk
                : (m + planesPerChunk - 1) / planesPerChunk;
    const auto countChunk = [&](std::int64_t c) {
        std::vector<std::int64_t> histogram(levels, 0);
        if (sampled) {
            // Uniform random void voxels: each equally likely (the paper's sampling, Sec. III B).
            Random generator = Random::stream(parameters_.seed, c);
            const std::int64_t points =
                std::min(kRandomPointChunk, parameters_.randomPoints - c * kRandomPointChunk);
            for (const std::int64_t v :
                 randomVoidVoxels(squared, total, map.voidFraction(), points, generator))
                ++histogram[squared[v]];
        } else {
            const std::int64_t first = c * planesPerChunk * plane;
            const std::int64_t last = std::min<std::int64_t>(m, (c + 1) * planesPerChunk) * plane;
            for (std::int64_t v = first; v < last; ++v)
                ++histogram[squared[v]];
        }
        return histogram;
    };
    const std::vector<std::int64_t> histogram = orderedReduce(
        chunks, std::vector<std::int64_t>(levels, 0), countChunk,
        [](std::vector<std::int64_t>& sum, const std::vector<std::int64_t>& h) {
            for (std::size_t n = 0; n < sum.size(); ++n)
                sum[n] += h[n];
        },
        progress);
    PoreSizeDistributionResult r = fromHistogram(histogram, m, map.voxelSize(), meanWidth);
    r.runtimeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
}

PoreSizeDistributionResult
PoreSizeDistribution::fromHistogram(std::span<const std::int64_t> histogram, int voxels,
                                    double voxelSize, double meanWidth) const {
    checkMeanWidth(meanWidth);
    std::vector<double> sizes;
    std::vector<std::int64_t> counts;
    PoreSizeSums sums;
    for (std::size_t n = 1; n < histogram.size(); ++n) // n = 0: solid voxels
        if (histogram[n] > 0) {
            sizes.push_back(voxelSize * std::sqrt(static_cast<double>(n)));
            counts.push_back(histogram[n]);
            sums.add(sizes.back(), histogram[n]);
        }
    // The voxel method's sizes are the discrete sqrt(n) a, from a on: density bins no wider than
    // a voxel would fall empty between them (a comb), so each is wider (fewer than max / a
    // bins; docs/design.md §5).
    const double voxelsAcross = sizes.empty() ? 1.0 : std::ceil(sizes.back() / voxelSize) - 1.0;
    const int bins = static_cast<int>(
        std::clamp(voxelsAcross, 1.0, static_cast<double>(parameters_.densityBins)));
    PoreSizeDistributionResult r = poreSizeStatistics(sizes, counts, meanWidth, bins);
    const bool sampled = parameters_.randomPoints > 0;
    if (sampled) setStandardErrors(r, sums);
    r.method = sampled ? "random voxels" : "voxels";
    r.parameters = parameters_;
    r.voxels = voxels;
    r.voxelSize = voxelSize;
    return r;
}

} // namespace sbpack

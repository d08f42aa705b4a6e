#include "pores/exact_pore_size.hpp"

#include "parallel/parallel.hpp"
#include "pores/largest_pore.hpp"
#include "pores/random_points.hpp"
#include "random/random.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sbpack {

namespace {

/// The packing's positions after the checks of ExactPoreSizes' constructor.
const std::vector<Vector3d>& checkedPositions(const Packing& packing) {
    if (packing.positions.empty())
        throw std::invalid_argument("exact pore sizes: the packing has no particles");
    if (packing.orientations.size() != packing.positions.size())
        throw std::invalid_argument(
            "exact pore sizes: " + std::to_string(packing.positions.size()) + " positions but " +
            std::to_string(packing.orientations.size()) + " orientations");
    if (!(std::isfinite(packing.boxLength) && packing.boxLength > 0.0))
        throw std::invalid_argument("exact pore sizes: box length is not finite and positive");
    return packing.positions;
}

} // namespace

ExactPoreSizes::ExactPoreSizes(const Packing& packing)
    : shape_(packing.shape()), boxLength_(packing.boxLength), circumradius_(shape_.circumradius()),
      inradius_(shape_.inradius()),
      cells_(checkedPositions(packing), packing.boxLength, shape_.circumradius()) {
    positions_.reserve(packing.size());
    rotations_.reserve(packing.size());
    for (std::size_t j = 0; j < packing.size(); ++j) {
        positions_.push_back(wrapIntoBox(packing.positions[j], boxLength_));
        rotations_.push_back(packing.orientations[j].normalized().toRotationMatrix());
    }
    sizes_ = packing.relativeSizes();
}

SurfaceDistance ExactPoreSizes::particleDistance(int particle, const Vector3d& d) const {
    const double s = relativeSize(particle);
    if (s == 1.0) return unitDistance(particle, d);
    const SurfaceDistance unit = unitDistance(particle, d / s); // distances scale with the size
    return {s * unit.lower, s * unit.upper};
}

SurfaceDistance ExactPoreSizes::unitDistance(int particle, const Vector3d& d) const {
    if (shape_.isSphere()) {
        const double distance = std::max(0.0, d.norm() - shape_.semiAxis());
        return {distance, distance};
    }
    const Vector3d xBody = rotations_[particle].transpose() * d;
    const Vector3d y = shape_.closestPoint(xBody);
    const Vector3d gap = xBody - y;
    const double upper = gap.norm();
    if (upper == 0.0) return {};
    // The certificate of closestPoint: n.x - h(n) <= dist(x, body) <= |x - y|.
    const Vector3d n = gap / upper;
    return {std::clamp(n.dot(xBody) - shape_.support(n), 0.0, upper), upper};
}

std::array<int, 3> ExactPoreSizes::homeCell(const Vector3d& xWrapped) const {
    return cells_.cells().coordinates(cells_.cells().cellContaining(xWrapped));
}

int ExactPoreSizes::particleContaining(const Vector3d& x) const {
    const Vector3d xw = wrapIntoBox(x, boxLength_);
    const std::array<int, 3> home = homeCell(xw);
    const int reach = std::min(1, cells_.cellsPerSide() / 2); // cells >= circumradius
    const double rc2 = circumradius_ * circumradius_;
    int found = -1;
    for (int ox = -reach; ox <= reach && found < 0; ++ox)
        for (int oy = -reach; oy <= reach && found < 0; ++oy)
            for (int oz = -reach; oz <= reach && found < 0; ++oz)
                forEachInCell({home[0] + ox, home[1] + oy, home[2] + oz},
                              [&](int j, const Vector3d&) {
                                  if (found >= 0) return;
                                  const Vector3d d = minimumImage(xw - positions_[j], boxLength_);
                                  if (d.squaredNorm() <= rc2 && inside(j, d)) found = j;
                              });
    return found;
}

SurfaceDistance ExactPoreSizes::poreSizeBounds(const Vector3d& x) const {
    struct Candidate {
        double lower; ///< |d| - s_j circumradius <= distance to this particle image
        int particle;
        Vector3d d; ///< x minus the image's centre
    };
    const Vector3d xw = wrapIntoBox(x, boxLength_);
    const std::array<int, 3> home = homeCell(xw);
    std::vector<Candidate> candidates;
    double bestUpper = std::numeric_limits<double>::infinity(); // min of |d| - inradius
    for (int s = 0;; ++s) {
        // Shell s: the cells (and their periodic images) at Chebyshev offset s from home.
        for (int ox = -s; ox <= s; ++ox)
            for (int oy = -s; oy <= s; ++oy)
                for (int oz = -s; oz <= s; ++oz) {
                    if (std::max({std::abs(ox), std::abs(oy), std::abs(oz)}) != s) continue;
                    forEachInCell({home[0] + ox, home[1] + oy, home[2] + oz},
                                  [&](int j, const Vector3d& shift) {
                                      const Vector3d d = xw - (positions_[j] + shift);
                                      const double centre = d.norm(), s = relativeSize(j);
                                      const double lower = centre - circumradius_ * s;
                                      if (lower >= bestUpper) return;
                                      candidates.push_back({lower, j, d});
                                      bestUpper = std::min(bestUpper, centre - inradius_ * s);
                                  });
                }
        // Every image not yet visited has its centre at least s cells away.
        if (s * cells_.cells().width() - circumradius_ >= bestUpper) break;
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.lower < b.lower; });
    SurfaceDistance best{std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity()};
    for (const Candidate& candidate : candidates) {
        if (candidate.lower >= best.upper) break;
        const SurfaceDistance next = particleDistance(candidate.particle, candidate.d);
        best = {std::min(best.lower, next.lower), std::min(best.upper, next.upper)};
        if (best.upper == 0.0) return {};
    }
    return best;
}

ExactPoreSizeDistribution::ExactPoreSizeDistribution(ExactPoreSizeParameters parameters)
    : parameters_(parameters) {
    if (parameters_.randomPoints < 1)
        throw std::invalid_argument("exact pore sizes: the number of random points K = " +
                                    std::to_string(parameters_.randomPoints) + " (need >= 1)");
    if (parameters_.densityBins < 1)
        throw std::invalid_argument("exact pore sizes: densityBins = " +
                                    std::to_string(parameters_.densityBins) + " (need >= 1)");
}

namespace {

/// A chunk of the exact sampler, or chunks joined: the pore sizes, their largest certificate gap,
/// the largest.
struct SampleChunk {
    explicit SampleChunk(double separation) : top(16, 0.0), spread(16, separation) {}
    /// Appends a later chunk: its sizes after these, its largest points offered after these.
    void add(const SampleChunk& later) {
        sizes.insert(sizes.end(), later.sizes.begin(), later.sizes.end());
        errorBound = std::max(errorBound, later.errorBound);
        top.offer(later.top);
        spread.offer(later.spread);
    }
    std::vector<double> sizes;
    double errorBound = 0.0;
    LargestPoints top;    ///< the largest points
    LargestPoints spread; ///< the largest of distinct pores
};

/// The distinct sizes of a sample, ascending, with their counts, and the sums of the sample.
void distinctSizes(std::vector<double> all, std::vector<double>& sizes,
                   std::vector<std::int64_t>& counts, PoreSizeSums& sums) {
    std::sort(all.begin(), all.end());
    for (const double delta : all) {
        sums.add(delta);
        if (!sizes.empty() && sizes.back() == delta) {
            ++counts.back();
        } else {
            sizes.push_back(delta);
            counts.push_back(1);
        }
    }
}

/// The exact pore sizes of chunk c's random points of the void (its own stream of the seed;
/// points inside a particle are drawn again).
SampleChunk sampleChunk(const ExactPoreSizes& pores, const ExactPoreSizeParameters& parameters,
                        double separation, std::int64_t c) {
    const double length = pores.boxLength();
    Random generator = Random::stream(parameters.seed, c);
    const std::int64_t points =
        std::min(kRandomPointChunk, parameters.randomPoints - c * kRandomPointChunk);
    SampleChunk chunk(separation);
    chunk.sizes.reserve(points);
    std::int64_t draws = 0;
    while (static_cast<std::int64_t>(chunk.sizes.size()) < points) {
        if (++draws > 1000 * points)
            throw std::domain_error("exact pore sizes: no void found in " +
                                    std::to_string(draws - 1) +
                                    " random points (the particles fill the box)");
        Vector3d x;
        for (int a = 0; a < 3; ++a)
            x[a] = length * generator.uniform();
        const SurfaceDistance delta = pores.poreSizeBounds(x);
        if (!(delta.upper > 0.0)) continue; // inside a particle: draw again
        chunk.sizes.push_back(delta.upper);
        chunk.errorBound = std::max(chunk.errorBound, delta.upper - delta.lower);
        chunk.top.offer(delta.upper, x);
        chunk.spread.offer(delta.upper, x);
    }
    return chunk;
}

/// The exact pore sizes of K uniformly random points of the void, in fixed chunks joined in
/// order (the result does not depend on the threads).
SampleChunk sampleVoid(const ExactPoreSizes& pores, const ExactPoreSizeParameters& parameters,
                       double separation, const Progress& progress) {
    const std::int64_t chunks =
        (parameters.randomPoints + kRandomPointChunk - 1) / kRandomPointChunk;
    return orderedReduce(
        chunks, SampleChunk(separation),
        [&](std::int64_t c) {
            progress.checkInterrupt();
            return sampleChunk(pores, parameters, separation, c);
        },
        [](SampleChunk& sample, const SampleChunk& later) { sample.add(later); }, progress);
}

} // namespace

PoreSizeDistributionResult ExactPoreSizeDistribution::compute(const Packing& packing,
                                                              const Progress& progress) const {
    const auto started = std::chrono::steady_clock::now();
    const ExactPoreSizes pores(packing);
    const double length = pores.boxLength();
    const std::int64_t k = parameters_.randomPoints;
    // Starts of the largest pore at least 4 point spacings apart (distinct pores).
    const double spacing = length / std::cbrt(static_cast<double>(k));
    SampleChunk sample = sampleVoid(pores, parameters_, 4.0 * spacing, progress);
    std::vector<double> sizes;
    std::vector<std::int64_t> counts;
    PoreSizeSums sums;
    distinctSizes(std::move(sample.sizes), sizes, counts, sums);
    PoreSizeDistributionResult r =
        poreSizeStatistics(sizes, counts, packing.shape().meanWidth(), parameters_.densityBins);
    r.method = "exact";
    r.parameters.randomPoints = k;
    r.parameters.seed = parameters_.seed;
    setStandardErrors(r, sums);
    r.errorBound = sample.errorBound;
    r.maxSampled = r.max;
    // First simplex: half the spacing of K points in the box, a scale the sample cannot resolve.
    r.max = std::max(r.max, largestPore([&pores](const Vector3d& x) { return pores.poreSize(x); },
                                        pores.boxLength(), sample.top, sample.spread, 0.5 * spacing)
                                .size);
    r.saturated = r.max < 0.5 * r.meanWidth; // paper Sec. V A
    r.runtimeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
}

} // namespace sbpack

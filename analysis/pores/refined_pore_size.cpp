#include "pores/refined_pore_size.hpp"

#include "contacts/cell_list.hpp"
#include "parallel/parallel.hpp"
#include "pores/largest_pore.hpp"
#include "pores/random_points.hpp"
#include "random/random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

namespace sbpack {

VoxelRefiner::VoxelRefiner(const ExactPoreSizes& pores, double maxPoreSize)
    : pores_(pores), spheres_(pores.isSphere()) {
    const double boxLength = pores.boxLength();
    const double range = (2.0 * pores.circumradius() + 2.0 * maxPoreSize) * (1.0 + 1e-12);
    if (!(range <= 0.5 * boxLength)) return; // a small box: the general search
    range_ = range;
    const int n = pores.size();
    std::vector<Vector3d> positions(n);
    for (int j = 0; j < n; ++j)
        positions[j] = pores.position(j);
    std::vector<std::vector<Neighbour>> lists(n);
    forEachNeighbourPair(positions, boxLength, range, [&](int i, int j, const Vector3d& d) {
        lists[i].push_back({d.norm(), j, d}); // d = r_j - r_i
        lists[j].push_back({d.norm(), i, -d});
    });
    start_.assign(n + 1, 0);
    for (int j = 0; j < n; ++j) {
        std::sort(lists[j].begin(), lists[j].end(),
                  [](const Neighbour& a, const Neighbour& b) { return a.distance < b.distance; });
        start_[j + 1] = start_[j] + static_cast<int>(lists[j].size());
    }
    neighbours_.reserve(start_.back());
    for (const auto& list : lists)
        neighbours_.insert(neighbours_.end(), list.begin(), list.end());
}

SurfaceDistance VoxelRefiner::poreSize(const Vector3d& x, int feature) const {
    if (feature < 0 || range_ == 0.0) return pores_.poreSizeBounds(x);
    const double rc = pores_.circumradius();
    const Vector3d df = image(x - pores_.position(feature));
    SurfaceDistance best = pores_.particleDistance(feature, df);
    const double centre = df.norm();
    if (best.upper + rc + centre > range_) return pores_.poreSizeBounds(x); // beyond the lists
    for (int a = start_[feature]; a < start_[feature + 1]; ++a) {
        const Neighbour& neighbour = neighbours_[a];
        if (neighbour.distance >= best.upper + rc + centre) break;
        const Vector3d d = df - neighbour.offset; // x minus the neighbour's centre
        const double reach = best.upper + rc;
        if (d.squaredNorm() >= reach * reach) continue; // |d| - r_c >= best: cannot be nearer
        if (!spheres_ && pores_.distanceLowerBound(neighbour.particle, d) >= best.upper) continue;
        const SurfaceDistance next = pores_.particleDistance(neighbour.particle, d);
        best = {std::min(best.lower, next.lower), std::min(best.upper, next.upper)};
    }
    return best;
}

int VoxelRefiner::particleContaining(const Vector3d& s, int hint) const {
    if (hint >= 0 && range_ > 0.0) {
        const Vector3d d = image(s - pores_.position(hint));
        if (pores_.inside(hint, d)) return hint;
        // A particle containing s has its centre within r_c of s, so within |d| + r_c of hint's.
        const double rc = pores_.circumradius();
        const double reach = d.norm() + rc;
        for (int a = start_[hint]; a < start_[hint + 1] && neighbours_[a].distance < reach; ++a) {
            const Vector3d e = d - neighbours_[a].offset; // s minus the neighbour's centre
            if (e.squaredNorm() <= rc * rc && pores_.inside(neighbours_[a].particle, e))
                return neighbours_[a].particle;
        }
    }
    return pores_.particleContaining(s);
}

namespace {

/// F(delta) is binned at a / kBinsPerVoxel.
constexpr int kBinsPerVoxel = 256;
/// Start points of the largest pore's maximisation: the largest, and the largest at least
/// kStartSeparation voxels apart.
constexpr int kLargestStarts = 16;
constexpr double kStartSeparation = 4.0;

/// What one chunk of voxels accumulates.
struct Tally {
    Tally(std::size_t bins, double separation)
        : histogram(bins, 0), top(kLargestStarts, 0.0), spread(kLargestStarts, separation) {}
    std::vector<std::int64_t> histogram;
    PoreSizeSums sums;
    double largest = 0.0;
    double errorBound = 0.0;
    LargestPoints top;    ///< the largest points
    LargestPoints spread; ///< the largest of distinct pores

    void add(const Tally& other) {
        for (std::size_t b = 0; b < histogram.size(); ++b)
            histogram[b] += other.histogram[b];
        sums.add(other.sums);
        largest = std::max(largest, other.largest);
        errorBound = std::max(errorBound, other.errorBound);
        top.offer(other.top);
        spread.offer(other.spread);
    }
};

/// The indices (i, j, k) of voxel v = (i * M + j) * M + k of an M^3 grid.
std::array<std::int64_t, 3> voxelIndices(std::int64_t v, std::int64_t m) {
    return {v / (m * m), v / m % m, v % m};
}

/// The centre of voxel v of an M^3 grid of voxel size a.
Vector3d voxelCentre(std::int64_t v, std::int64_t m, double a) {
    const auto [i, j, k] = voxelIndices(v, m);
    return Vector3d(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5,
                    static_cast<double>(k) + 0.5) *
           a;
}

/// The refinement of one pass over voxels: the particle of each feature voxel (remembered for
/// the next voxel, which often shares it), its refined pore size, the tally.
class VoxelPass {
  public:
    VoxelPass(const PoreSizeMap& map, const ExactPoreSizes& pores, const VoxelRefiner& refiner)
        : map_(map), pores_(pores), refiner_(refiner), m_(map.voxels()), a_(map.voxelSize()),
          h_(a_ / kBinsPerVoxel) {}

    double binWidth() const { return h_; }

    /// Refines the void voxel at x, whose feature voxel is `feature`, into the tally.
    void refine(std::uint32_t feature, const Vector3d& x, Tally& tally) {
        if (feature != lastFeature_) {
            lastFeature_ = feature;
            lastParticle_ = refiner_.particleContaining(centre(feature), lastParticle_);
        }
        const SurfaceDistance d = refiner_.poreSize(x, lastParticle_);
        const auto bin = std::min<std::size_t>(tally.histogram.size() - 1,
                                               static_cast<std::size_t>(d.upper / h_));
        ++tally.histogram[bin];
        tally.sums.add(d.upper);
        tally.largest = std::max(tally.largest, d.upper);
        tally.errorBound = std::max(tally.errorBound, d.upper - d.lower);
        tally.top.offer(d.upper, x);
        tally.spread.offer(d.upper, x);
    }

    /// Refines every void voxel of the planes [first, last) into the tally.
    void refinePlanes(std::int64_t first, std::int64_t last, Tally& tally) {
        const std::int64_t m = m_;
        const std::uint32_t* squared = map_.squaredDistances().data();
        const std::uint32_t* features = map_.features().data();
        for (std::int64_t i = first; i < last; ++i)
            for (std::int64_t j = 0; j < m; ++j) {
                const std::int64_t row = (i * m + j) * m;
                Vector3d x((static_cast<double>(i) + 0.5) * a_, (static_cast<double>(j) + 0.5) * a_,
                           0.0);
                for (std::int64_t k = 0; k < m; ++k)
                    if (squared[row + k] != 0) {
                        x.z() = (static_cast<double>(k) + 0.5) * a_;
                        refine(features[row + k], x, tally);
                    }
            }
    }

    /// The centre of voxel v.
    Vector3d centre(std::int64_t v) const { return voxelCentre(v, m_, a_); }

  private:
    const PoreSizeMap& map_;
    const ExactPoreSizes& pores_;
    const VoxelRefiner& refiner_;
    int m_;
    double a_, h_;
    std::uint32_t lastFeature_ = 0xffffffffu;
    int lastParticle_ = -1;
};

} // namespace

RefinedPoreSizeDistribution::RefinedPoreSizeDistribution(PoreSizeParameters parameters)
    : parameters_(parameters) {
    static_cast<void>(PoreSizeDistribution(parameters)); // the same checks
}

namespace {

/// Random points drawn and ordered together: a round of this many chunks.
constexpr std::int64_t kChunksPerRound = 64;

/// Voxel v's block of 8^3 voxels in an M^3 grid, as one index.
std::int64_t blockOf(std::int64_t v, std::int64_t m) {
    const std::int64_t blocks = (m + 7) / 8;
    const auto [i, j, k] = voxelIndices(v, m);
    return ((i / 8) * blocks + j / 8) * blocks + k / 8;
}

/// A random void voxel and its feature voxel.
struct RandomVoxel {
    std::int64_t voxel;
    std::uint32_t feature;
};

/// The random void voxels of chunk c (its own stream of the seed, as PoreSizeDistribution).
std::vector<RandomVoxel> randomVoxels(const PoreSizeMap& map, const PoreSizeParameters& parameters,
                                      std::int64_t c) {
    const std::int64_t m = map.voxels();
    Random generator = Random::stream(parameters.seed, c);
    std::vector<RandomVoxel> chunk;
    for (const std::int64_t v : randomVoidVoxels(
             map.squaredDistances().data(), m * m * m, map.voidFraction(),
             std::min(kRandomPointChunk, parameters.randomPoints - c * kRandomPointChunk),
             generator))
        chunk.push_back({v, map.features()[v]});
    return chunk;
}

/// The random void voxels of chunks [first, last), ordered by the 8^3 block of their feature
/// voxels, whose voxels mostly lie in one particle: VoxelRefiner::particleContaining then mostly
/// finds it at its hint. One sort of 64-bit keys: the block above the voxel's place in the round
/// (< 2^20 of them).
std::vector<RandomVoxel> randomVoxelsByFeatureBlock(const PoreSizeMap& map,
                                                    const PoreSizeParameters& parameters,
                                                    std::int64_t first, std::int64_t last,
                                                    const Progress& progress) {
    const std::int64_t m = map.voxels();
    const std::vector<RandomVoxel> voxels = orderedReduce(
        last - first, std::vector<RandomVoxel>(),
        [&](std::int64_t i) { return randomVoxels(map, parameters, first + i); },
        [](std::vector<RandomVoxel>& all, const std::vector<RandomVoxel>& chunk) {
            all.insert(all.end(), chunk.begin(), chunk.end());
        },
        progress);
    constexpr int kPlaceBits = 20;
    static_assert(kChunksPerRound * kRandomPointChunk <= std::int64_t{1} << kPlaceBits);
    std::vector<std::uint64_t> keys(voxels.size());
    for (std::size_t i = 0; i < voxels.size(); ++i)
        keys[i] = static_cast<std::uint64_t>(blockOf(voxels[i].feature, m)) << kPlaceBits | i;
    std::sort(keys.begin(), keys.end());
    std::vector<RandomVoxel> ordered(voxels.size());
    for (std::size_t i = 0; i < keys.size(); ++i)
        ordered[i] = voxels[keys[i] & ((std::uint64_t{1} << kPlaceBits) - 1)];
    return ordered;
}

/// Refines every void voxel, or K random void voxels, into one tally per chunk (fixed chunks,
/// random voxels drawn and ordered in fixed rounds of chunks: the result does not depend on the
/// threads); the tallies summed in order.
Tally tallyVoxels(const PoreSizeMap& map, const ExactPoreSizes& pores, const VoxelRefiner& refiner,
                  const PoreSizeParameters& parameters, std::size_t bins,
                  const Progress& progress) {
    const int m = map.voxels();
    const double separation = kStartSeparation * map.voxelSize();
    const bool sampled = parameters.randomPoints > 0;
    if (sampled) checkRandomVoidFraction(map.voidFraction(), m);
    const std::int64_t planesPerChunk = std::max<std::int64_t>(1, m / 64);
    const std::int64_t chunks =
        sampled ? (parameters.randomPoints + kRandomPointChunk - 1) / kRandomPointChunk
                : (m + planesPerChunk - 1) / planesPerChunk;
    const std::int64_t chunksPerRound = sampled ? kChunksPerRound : chunks;
    Tally all(bins, separation);
    for (std::int64_t round = 0; round < chunks; round += chunksPerRound) {
        const std::int64_t end = std::min(chunks, round + chunksPerRound);
        const std::vector<RandomVoxel> points =
            sampled ? randomVoxelsByFeatureBlock(map, parameters, round, end, progress)
                    : std::vector<RandomVoxel>();
        const auto tallyChunk = [&](std::int64_t i) {
            progress.checkInterrupt();
            VoxelPass pass(map, pores, refiner);
            Tally tally(bins, separation);
            const std::int64_t c = round + i;
            if (!sampled) {
                pass.refinePlanes(c * planesPerChunk,
                                  std::min<std::int64_t>(m, (c + 1) * planesPerChunk), tally);
                return tally;
            }
            const auto mine = std::span(points).subspan(
                i * kRandomPointChunk,
                std::min<std::size_t>(kRandomPointChunk, points.size() - i * kRandomPointChunk));
            for (const RandomVoxel& v : mine)
                pass.refine(v.feature, pass.centre(v.voxel), tally);
            return tally;
        };
        all = orderedReduce(
            end - round, std::move(all), tallyChunk,
            [](Tally& total, const Tally& tally) { total.add(tally); }, progress);
    }
    return all;
}

} // namespace

namespace {

/// The pore size at any point x by the refiner: the particle holding the feature of x's voxel
/// starts the search (any particle would keep it exact; a near one keeps it short). Serial: the
/// function remembers the last particle as its next hint.
PoreSizeFunction refinedPoreSize(const PoreSizeMap& map, const ExactPoreSizes& pores,
                                 const VoxelRefiner& refiner) {
    const int m = map.voxels();
    const double a = map.voxelSize();
    return [&map, &pores, &refiner, m, a, hint = -1](const Vector3d& x) mutable {
        const Vector3d w = wrapIntoBox(x, pores.boxLength());
        std::int64_t v = 0;
        for (int k = 0; k < 3; ++k)
            v = v * m + std::clamp(static_cast<std::int64_t>(w[k] / a), std::int64_t{0},
                                   std::int64_t{m} - 1);
        hint = refiner.particleContaining(voxelCentre(map.features()[v], m, a), hint);
        return refiner.poreSize(w, hint).upper;
    };
}

} // namespace

PoreSizeDistributionResult RefinedPoreSizeDistribution::compute(const PoreSizeMap& map,
                                                                const Packing& packing,
                                                                const Progress& progress) const {
    const Stopwatch clock;
    if (!map.hasFeatures())
        throw std::invalid_argument("refined pore sizes: the map has no feature transform "
                                    "(periodicFeatureTransform)");
    if (std::abs(map.boxLength() - packing.boxLength) > 1e-9 * packing.boxLength)
        throw std::invalid_argument("refined pore sizes: the map is not of this packing's box");
    const ExactPoreSizes pores(packing);
    const double a = map.voxelSize();
    // Voxel distances bound the pore sizes: a feature voxel's centre is inside a particle.
    const double maxPore = a * std::sqrt(static_cast<double>(map.maxSquaredDistance()));
    const auto bins = static_cast<std::size_t>(std::ceil(maxPore / a * kBinsPerVoxel)) + 2;
    const VoxelRefiner refiner(pores, maxPore);
    const Tally all = tallyVoxels(map, pores, refiner, parameters_, bins, progress);
    PoreSizeDistributionResult r =
        binnedPoreSizeStatistics(all.histogram, a / kBinsPerVoxel, all.sums, all.largest,
                                 packing.shape().meanWidth(), parameters_.densityBins);
    const bool sampled = parameters_.randomPoints > 0;
    r.method = sampled ? "random voxels refined" : "refined";
    r.parameters = parameters_;
    r.voxels = map.voxels();
    r.voxelSize = a;
    r.errorBound = all.errorBound;
    r.maxSampled = all.largest;
    if (sampled)
        setStandardErrors(r, all.sums);
    else
        r.maxUpperBound = all.largest + 0.5 * std::sqrt(3.0) * a;
    r.max = std::max(r.maxSampled, largestPore(refinedPoreSize(map, pores, refiner),
                                               map.boxLength(), all.top, all.spread, 0.5 * a)
                                       .size);
    r.saturated = r.max < 0.5 * r.meanWidth; // paper Sec. V A
    r.runtimeSeconds = clock.seconds();
    return r;
}

} // namespace sbpack

#pragma once
// Pore-size distribution of the void phase (paper Sec. II B, Eqs. 13-15; docs/design.md §5, §6):
// the complementary cumulative F(delta), the density P(delta), the moments <delta>, <delta^2>, the
// largest pore and the saturation check, in length units and scaled by the mean width w.

#include "pores/distance_transform.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sbpack {

struct PoreSizeParameters {
    /// K: 0 = every void voxel (default); K > 0 = K random points of the void, each given the
    /// pore size of the voxel it lies in (the paper's sampling, Sec. III B).
    std::int64_t randomPoints = 0;
    std::uint64_t seed = 1; ///< of the random points (results do not depend on the threads)
    int densityBins = 64;   ///< bins of the histogram of P(delta) on [0, max]
    bool serial = false;    ///< run the parallel loops in order on one thread
};

/// F(delta), P(delta) and moments of one sample of pore sizes, with what produced it. Lengths are
/// in the packing's length units; the *OverWidth forms are divided by the mean width w.
struct PoreSizeDistributionResult {
    std::string method;            ///< "voxels", "random voxels" or "exact" (voxel-free)
    PoreSizeParameters parameters; ///< K, seed, bins (the voxel-free reference fills its own)
    int voxels = 0;                ///< M (0 for the voxel-free reference)
    double voxelSize = 0.0;        ///< a = L / M (0 for the voxel-free reference)
    double meanWidth = 0.0;        ///< w
    std::int64_t samples = 0;      ///< void voxels or random void points in the statistics

    /// F as a right-continuous step function: F[j] = fraction of the sample with pore size >
    /// delta[j], constant on [delta[j], delta[j + 1]); delta[0] = 0, F[0] = 1, F.back() = 0.
    std::vector<double> delta;
    std::vector<double> F;            ///< Eq. 13, dimensionless
    std::vector<double> densityDelta; ///< bin centres of P(delta)
    std::vector<double> density;      ///< P(delta), 1 / length, integrates to 1
    double mean = 0.0;                ///< <delta> = int F d delta (Eq. 14)
    double secondMoment = 0.0;        ///< <delta^2> = 2 int F delta d delta (Eq. 15)
    double max = 0.0;                 ///< largest pore size of the sample
    bool saturated = false;           ///< max < w / 2 (paper Sec. V A)
    double runtimeSeconds = 0.0;

    double meanOverWidth() const { return mean / meanWidth; }
    double secondMomentOverWidth2() const { return secondMoment / (meanWidth * meanWidth); }
    double maxOverWidth() const { return max / meanWidth; }
    std::vector<double> deltaOverWidth() const;
    std::vector<double> densityDeltaOverWidth() const;
    /// P(delta) w: the density of delta / w.
    std::vector<double> densityTimesWidth() const;
};

/// The statistical part of a result (delta, F, density, moments, max, samples, saturated) from
/// the distinct pore sizes of a sample, ascending and > 0, and how often each occurs. Moments are
/// the sample means of delta and delta^2, which equal Eqs. 14-15 applied to the step function F.
/// Throws std::invalid_argument for empty, unsorted, non-positive or non-finite input, a
/// non-positive count, densityBins < 1 or meanWidth not finite and positive.
PoreSizeDistributionResult poreSizeStatistics(std::span<const double> sizes,
                                              std::span<const std::int64_t> counts,
                                              double meanWidth, int densityBins);

/// Largest vertical gap sup_delta |F_a(delta) - F_b(delta)| between two results' step functions
/// (exact: both are constant between the union of their jump points).
double largestGap(const PoreSizeDistributionResult& a, const PoreSizeDistributionResult& b);

/// Compute object: the pore-size distribution of a pore-size map (paper Secs. II B, III B).
class PoreSizeDistribution {
  public:
    /// Throws std::invalid_argument for randomPoints < 0 or densityBins < 1.
    explicit PoreSizeDistribution(PoreSizeParameters parameters);

    /// Statistics over every void voxel, or K random void points (parameters). Throws
    /// std::invalid_argument unless meanWidth is finite and positive.
    PoreSizeDistributionResult compute(const PoreSizeMap& map, double meanWidth) const;
    /// The statistics from histogram[n] = the number of sampled voxels at squared distance n
    /// (voxel units; n = 0 solid, not counted) of an M^3 grid of voxel size a: what compute()
    /// does after its histogram, and what the ranks of a distributed grid do after summing
    /// theirs (docs/scale-out.md). runtimeSeconds is left 0.
    PoreSizeDistributionResult fromHistogram(std::span<const std::int64_t> histogram, int voxels,
                                             double voxelSize, double meanWidth) const;

    const PoreSizeParameters& parameters() const { return parameters_; }

  private:
    PoreSizeParameters parameters_;
};

} // namespace sbpack

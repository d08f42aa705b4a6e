#pragma once
// Pore-size distribution of the void phase (paper Sec. II B, Eqs. 13-15; docs/design.md §5, §6):
// the complementary cumulative F(delta), the density P(delta), the moments <delta>, <delta^2>, the
// largest pore and the saturation check, in length units and scaled by the mean width w.

#include "pores/distance_transform.hpp"

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sbpack {

/// How the pores analysis measures pore sizes (--pores; README, "Pore sizes: error against run
/// time"): "voxel", the distance between voxel centres (Sec. III B); "refined", the certified
/// distance from each void voxel centre to the nearest particle surface
/// (RefinedPoreSizeDistribution); "exact", K random points of the void without voxels
/// (ExactPoreSizeDistribution).
enum class PoreMethod { Voxel, Refined, Exact };

/// Throws std::invalid_argument naming --pores unless name is voxel, refined or exact.
PoreMethod poreMethodFromName(std::string_view name);
std::string_view poreMethodName(PoreMethod method);

struct PoreSizeParameters {
    /// K: 0 = every void voxel (default); K > 0 = K random points of the void, each given the
    /// pore size of the voxel it lies in (the paper's sampling, Sec. III B).
    std::int64_t randomPoints = 0;
    std::uint64_t seed = 1; ///< of the random points (results do not depend on the threads)
    /// Bins of the histogram of P(delta) on [0, max]; on voxels fewer than max / a (each wider
    /// than a voxel)
    int densityBins = 64;
};

/// F(delta), P(delta) and moments of one sample of pore sizes, with what produced it. Lengths are
/// in the packing's length units; the *OverWidth forms are divided by the mean width w.
struct PoreSizeDistributionResult {
    /// "voxels", "random voxels", "refined", "random voxels refined" or "exact" (voxel-free)
    std::string method;
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
    /// Largest pore size: of the sample (voxels), or of a local maximisation of the distance to
    /// the nearest surface from the sample's largest (refined, exact; largestPore).
    double max = 0.0;
    bool saturated = false; ///< max < w / 2 (paper Sec. V A)
    double runtimeSeconds = 0.0;

    static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
    double maxSampled = kUnset; ///< refined, exact: the sample's largest, before maximising
    /// Refined over every void voxel: a certified upper bound on the largest pore, the sample's
    /// largest upper bound plus sqrt(3)/2 a (any void point is that near a voxel centre, and the
    /// pore size is 1-Lipschitz).
    double maxUpperBound = kUnset;
    /// Refined, exact: the largest certified |pore size - distance to the nearest surface| of a
    /// sample point (SurfaceDistance upper - lower).
    double errorBound = kUnset;
    /// Random samples: standard errors of <delta> and <delta^2>, the sample standard deviation
    /// of delta and delta^2 over sqrt(K).
    double meanStandardError = kUnset;
    double secondMomentStandardError = kUnset;
    /// Refined: F(delta) and P(delta) come from a histogram of this bin width (a / 256): F is
    /// exact at the bin edges delta[j], the moments and the largest pore are not binned.
    double binWidth = kUnset;

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

/// The sums of a sample of pore sizes from which its moments and standard errors follow.
struct PoreSizeSums {
    std::int64_t count = 0;
    double sum = 0.0, sumSquares = 0.0, sumCubes = 0.0, sumFourth = 0.0;
    void add(double delta, std::int64_t times = 1);
    void add(const PoreSizeSums& other);
};

/// Sets meanStandardError and secondMomentStandardError of r from the sums of a random sample
/// (sample variances with n - 1; NaN for fewer than two points).
void setStandardErrors(PoreSizeDistributionResult& r, const PoreSizeSums& sums);

/// The statistical part of a result from a histogram of pore sizes in bins [j h, (j + 1) h)
/// (counts[j]) and the exact sums of the same sample: F at the bin edges delta[j] = j h (the
/// fraction of the sample in bins >= j, exact there up to sizes equal to an edge) and 0 at the
/// largest size, P(delta) by re-binning onto densityBins bins of [0, max] (bins assigned by their
/// centres), the moments from the sums. Throws std::invalid_argument for an empty sample,
/// a non-positive h, largest not in the last non-empty bin, or as poreSizeStatistics.
PoreSizeDistributionResult binnedPoreSizeStatistics(std::span<const std::int64_t> counts, double h,
                                                    const PoreSizeSums& sums, double largest,
                                                    double meanWidth, int densityBins);

/// Compute object: the pore-size distribution of a pore-size map (paper Secs. II B, III B).
class PoreSizeDistribution {
  public:
    /// Throws std::invalid_argument for randomPoints < 0 or densityBins < 1.
    explicit PoreSizeDistribution(PoreSizeParameters parameters);

    /// Statistics over every void voxel, or K random void points (parameters). Throws
    /// std::invalid_argument unless meanWidth is finite and positive.
    PoreSizeDistributionResult compute(const PoreSizeMap& map, double meanWidth,
                                       const Progress& progress) const;
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

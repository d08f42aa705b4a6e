// Refined pore sizes (each void voxel centre's distance to the nearest surface) against closed
// forms, the exact sampler and brute force; the largest pore by local maximisation.
#include "io/text_io.hpp"
#include "parallel/parallel.hpp"
#include "pores/distance_transform.hpp"
#include "pores/exact_pore_size.hpp"
#include "pores/largest_pore.hpp"
#include "pores/pore_size_distribution.hpp"
#include "pores/refined_pore_size.hpp"
#include "progress/progress.hpp"
#include "test_packings.hpp"
#include "voxels/voxelization.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace sbpack {
namespace {

/// The feature-transformed pore-size map of a packing on an M^3 grid (as the pores stage).
PoreSizeMap featureMap(const Packing& packing, int m) {
    const Voxelization voxels = Voxelizer({m}).compute(packing, Progress());
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    voxels.copySolidMask(mask);
    return periodicFeatureTransform(mask, m, voxels.voxelSize());
}

PoreSizeDistributionResult refined(const Packing& packing, int m, std::int64_t points = 0) {
    PoreSizeParameters parameters;
    parameters.randomPoints = points;
    return RefinedPoreSizeDistribution(parameters)
        .compute(featureMap(packing, m), packing, Progress());
}

/// Right-continuous value of the step function F at x.
double stepF(const PoreSizeDistributionResult& r, double x) {
    return r.F[std::upper_bound(r.delta.begin(), r.delta.end(), x) - r.delta.begin() - 1];
}

TEST(RefinedPoreSize, SingleSphereMatchesTheClosedFormAndFindsTheCorner) {
    // F(delta) = (L^3 - 4/3 pi (R + delta)^3) / (L^3 - 4/3 pi R^3) for R + delta <= L / 2; the
    // largest pore is the point farthest from the sphere, its centre + (L/2, L/2, L/2):
    // sqrt(3) L / 2 - R. Every voxel's pore size is |x - c| - R, exact.
    const ThreadBudget budget(2);
    const double r = 0.5, length = 2.0;
    const Packing packing = testing::singleParticle(1.0, r, length, Vector3d(0.93, 1.1, 0.71));
    const PoreSizeDistributionResult s = refined(packing, 96);
    EXPECT_EQ(s.method, "refined");
    EXPECT_LE(s.errorBound, 1e-15);
    const double ball = 4.0 / 3.0 * std::numbers::pi, v = std::pow(length, 3);
    for (const double delta : {0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5})
        EXPECT_NEAR(stepF(s, delta), (v - ball * std::pow(r + delta, 3)) / (v - ball * r * r * r),
                    0.002)
            << "delta = " << delta;
    const double corner = std::sqrt(3.0) * length / 2.0 - r;
    EXPECT_NEAR(s.max, corner, 1e-9);
    EXPECT_LE(s.maxSampled, s.max);
    EXPECT_GE(s.maxUpperBound, corner);
    EXPECT_FALSE(s.saturated); // the corner is farther than w / 2 = 0.5
}

TEST(RefinedPoreSize, SimpleCubicLatticeLargestPoreIsTheCellCentre) {
    // 125 aligned p = 1.5 superballs (R = 0.5) on a simple-cubic lattice of spacing 1: the largest
    // pore is the centre of a lattice cell, whose nearest surface points are the eight corners
    // R 3^{-1/(2p)} (1, 1, 1) of the diagonal: delta_max = sqrt(3) (1/2 - R 3^{-1/3}).
    const ThreadBudget budget(2);
    const Packing packing = readTextPacking(std::string(SBPACK_DATA_DIR) + "/sc-lattice-p1.5.txt");
    const PoreSizeDistributionResult s = refined(packing, 100);
    const double expected = std::sqrt(3.0) * (0.5 - 0.5 * std::cbrt(1.0 / 3.0));
    EXPECT_NEAR(s.max, expected, 1e-8);
    EXPECT_LE(s.maxSampled, expected + 1e-12);
    EXPECT_GE(s.maxUpperBound, expected);
    EXPECT_LE(s.errorBound, 1e-12);
    // The lattice is its own unit cell: the same statistics on every cell, so a random subset of
    // the voxels agrees with all of them within its standard error.
    const PoreSizeDistributionResult sampled = refined(packing, 100, 200000);
    EXPECT_EQ(sampled.method, "random voxels refined");
    EXPECT_NEAR(sampled.mean, s.mean, 4.0 * sampled.meanStandardError);
    EXPECT_NEAR(sampled.secondMoment, s.secondMoment, 4.0 * sampled.secondMomentStandardError);
}

TEST(RefinedPoreSize, AgreesWithTheExactSamplerOnRandomSuperballs) {
    // Jittered, randomly rotated superballs: the refined grid statistics and the voxel-free
    // random points estimate the same F(delta) and moments (Eqs. 13-15).
    const ThreadBudget budget(2);
    for (const double p : {0.85, 1.5}) {
        const Packing packing = testing::latticePacking(p, 4, 1.35, 0.08, 5);
        const PoreSizeDistributionResult s = refined(packing, 120);
        ExactPoreSizeParameters parameters;
        parameters.randomPoints = 400000;
        const PoreSizeDistributionResult e =
            ExactPoreSizeDistribution(parameters).compute(packing, Progress());
        EXPECT_NEAR(s.mean, e.mean, 4.0 * e.meanStandardError + 2e-3 * e.mean) << "p = " << p;
        EXPECT_NEAR(s.secondMoment, e.secondMoment,
                    4.0 * e.secondMomentStandardError + 2e-3 * e.secondMoment)
            << "p = " << p;
        EXPECT_LT(largestGap(s, e), 0.01) << "p = " << p;
        EXPECT_LE(s.errorBound, 1e-11) << "p = " << p;
        EXPECT_NEAR(s.max, e.max, 1e-7) << "p = " << p; // the same local maximum
        EXPECT_LE(s.max, s.maxUpperBound) << "p = " << p;
    }
}

TEST(RefinedPoreSize, NeighbourSearchEqualsTheGeneralSearchFromAnyFeature) {
    // VoxelRefiner is exact whatever particle it starts from: against ExactPoreSizes' own
    // search at random points, starting from the right particle, a wrong one and none.
    const Packing packing = testing::latticePacking(1.5, 4, 1.3, 0.1, 9);
    const ExactPoreSizes pores(packing);
    const VoxelRefiner refiner(pores, 0.5);
    ASSERT_TRUE(refiner.usesNeighbourLists());
    std::mt19937_64 generator(4);
    std::uniform_real_distribution<double> uniform(0.0, packing.boxLength);
    std::uniform_int_distribution<int> particle(0, static_cast<int>(packing.size()) - 1);
    int tested = 0;
    for (int n = 0; n < 3000; ++n) {
        const Vector3d x(uniform(generator), uniform(generator), uniform(generator));
        const double expected = pores.poreSize(x);
        if (expected == 0.0 || expected > 0.5) continue;
        for (const int start : {particle(generator), -1})
            ASSERT_NEAR(refiner.poreSize(x, start).upper, expected, 1e-14) << x.transpose();
        ++tested;
    }
    EXPECT_GT(tested, 1000);
}

TEST(RefinedPoreSize, RejectsAMapWithoutFeatures) {
    const Packing packing = testing::singleParticle(1.0, 0.5, 2.0, Vector3d(1.0, 1.0, 1.0));
    const Voxelization voxels = Voxelizer({16}).compute(packing, Progress());
    std::vector<std::uint8_t> mask(16 * 16 * 16);
    voxels.copySolidMask(mask);
    const PoreSizeMap plain = periodicDistanceTransform(mask, 16, voxels.voxelSize());
    EXPECT_THROW(RefinedPoreSizeDistribution({}).compute(plain, packing, Progress()),
                 std::invalid_argument);
    EXPECT_THROW(RefinedPoreSizeDistribution({-1, 1, 64}), std::invalid_argument);
}

TEST(PoreSizeStatistics, BinnedStatisticsKeepTheSampleMomentsAndFAtTheEdges) {
    const std::vector<double> sizes = {0.013, 0.021, 0.022, 0.047, 0.05};
    const std::vector<std::int64_t> counts = {3, 1, 2, 5, 1};
    PoreSizeSums sums;
    const double h = 0.01;
    std::vector<std::int64_t> histogram(6, 0);
    for (std::size_t j = 0; j < sizes.size(); ++j) {
        sums.add(sizes[j], counts[j]);
        histogram[static_cast<std::size_t>(sizes[j] / h)] += counts[j];
    }
    const PoreSizeDistributionResult exact = poreSizeStatistics(sizes, counts, 1.0, 4);
    const PoreSizeDistributionResult binned =
        binnedPoreSizeStatistics(histogram, h, sums, 0.05, 1.0, 4);
    EXPECT_DOUBLE_EQ(binned.mean, exact.mean);
    EXPECT_DOUBLE_EQ(binned.secondMoment, exact.secondMoment);
    EXPECT_DOUBLE_EQ(binned.max, 0.05);
    for (const double edge : binned.delta)
        EXPECT_DOUBLE_EQ(stepF(binned, edge), stepF(exact, edge)) << edge;
    EXPECT_THROW(binnedPoreSizeStatistics(histogram, h, sums, 0.2, 1.0, 4), std::invalid_argument);
}

TEST(PoreSizeStatistics, StandardErrorsAreTheSampleDeviationsOverRootK) {
    PoreSizeSums sums;
    for (const double d : {1.0, 2.0, 3.0})
        sums.add(d);
    PoreSizeDistributionResult r;
    setStandardErrors(r, sums);
    EXPECT_DOUBLE_EQ(r.meanStandardError, 1.0 / std::sqrt(3.0)); // sd 1
    // delta^2 = 1, 4, 9: mean 14/3, sample variance (1 + 4 + 9 - ...) = 49/3 - ... = 16.33 / ...
    const double mean = 14.0 / 3.0;
    const double variance =
        ((1 - mean) * (1 - mean) + (4 - mean) * (4 - mean) + (9 - mean) * (9 - mean)) / 2.0;
    EXPECT_NEAR(r.secondMomentStandardError, std::sqrt(variance / 3.0), 1e-12);
}

TEST(LargestPore, NelderMeadClimbsToTheFarthestPointFromOneSphere) {
    const double length = 3.0;
    const Packing packing = testing::singleParticle(1.0, 0.5, length, Vector3d(1.0, 1.0, 1.0));
    const ExactPoreSizes pores(packing);
    const PoreSizeFunction size = [&pores](const Vector3d& x) { return pores.poreSize(x); };
    const std::vector<Vector3d> starts = {Vector3d(2.2, 2.7, 2.3)};
    const LargestPore best = largestPore(size, length, starts, 0.1);
    EXPECT_NEAR(best.size, std::sqrt(3.0) * length / 2.0 - 0.5, 1e-9);
    EXPECT_NEAR((best.position - Vector3d(2.5, 2.5, 2.5)).norm(), 0.0, 1e-6);
    EXPECT_THROW(largestPore(size, length, {}, 0.1), std::invalid_argument);
    EXPECT_THROW(largestPore(size, length, starts, 0.0), std::invalid_argument);
}

TEST(ExactPoreSize, SamplerRecordsStandardErrorsAndACertificate) {
    const ThreadBudget budget(2);
    const Packing packing = testing::latticePacking(1.5, 3, 1.4, 0.1, 3);
    ExactPoreSizeParameters parameters;
    parameters.randomPoints = 20000;
    const PoreSizeDistributionResult e =
        ExactPoreSizeDistribution(parameters).compute(packing, Progress());
    EXPECT_GT(e.meanStandardError, 0.0);
    EXPECT_LT(e.meanStandardError, 0.02 * e.mean);
    EXPECT_LE(e.errorBound, 1e-11);
    EXPECT_GE(e.max, e.maxSampled);
}

} // namespace
} // namespace sbpack

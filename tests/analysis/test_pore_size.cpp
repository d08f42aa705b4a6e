#include "parallel/parallel.hpp"
#include "pores/exact_pore_size.hpp"
#include "pores/pore_size_distribution.hpp"
#include "pores/random_points.hpp"
#include "test_packings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace sbpack {
namespace {

// The samplers' random void voxels (pores/random_points.hpp) are uniform over the void and
// never solid: on a grid of 64 voxels whose void is every third voxel, 2.1e5 draws hit each of
// the 22 void voxels 9545 times on average; a chi-square over them stays within its 21 degrees
// of freedom's 1e-6 quantile (about 65), and the draws come in ascending order.
TEST(RandomVoidVoxels, AreUniformOverTheVoidAndNeverSolid) {
    std::vector<std::uint32_t> squared(64, 0);
    for (std::size_t v = 0; v < squared.size(); v += 3)
        squared[v] = 1;
    const double voids = 22.0, draws = 210000.0;
    Random generator = Random::stream(7, 0);
    std::vector<std::int64_t> counts(64, 0);
    std::vector<std::int64_t> sample;
    for (int batch = 0; batch < 10; ++batch) { // batches of differing needs
        sample = randomVoidVoxels(squared.data(), 64, voids / 64.0, 21000, generator);
        ASSERT_EQ(sample.size(), 21000U);
        EXPECT_TRUE(std::is_sorted(sample.begin(), sample.end()));
        for (const std::int64_t v : sample)
            ++counts[static_cast<std::size_t>(v)];
    }
    double chiSquare = 0.0;
    for (std::size_t v = 0; v < counts.size(); ++v) {
        if (squared[v] == 0) {
            EXPECT_EQ(counts[v], 0) << v;
            continue;
        }
        const double expected = draws / voids;
        chiSquare += (counts[v] - expected) * (counts[v] - expected) / expected;
    }
    EXPECT_LT(chiSquare, 65.0);
    // A wrong guess of the void fraction changes the batches, not the distribution.
    EXPECT_EQ(randomVoidVoxels(squared.data(), 64, 0.9, 5000, generator).size(), 5000U);
}

// A grid whose void is too small for random voxels (over 1000 draws a voxel) is refused with an
// error that names the option, instead of drawing for hours.
TEST(RandomVoidVoxels, AVanishingVoidIsRefusedWithItsOption) {
    EXPECT_NO_THROW(checkRandomVoidFraction(1e-3, 100));
    try {
        checkRandomVoidFraction(1.0 / (64.0 * 64.0 * 64.0), 64);
        FAIL() << "no error";
    } catch (const std::domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("--pore-points 0"), std::string::npos) << e.what();
    }
}

/// Solid mask of spheres (centre-inside rule, minimum image), for tests only.
std::vector<std::uint8_t> sphereMask(const std::vector<Vector3d>& centres, double radius,
                                     double length, int m) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m, 0);
    const double a = length / m;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k) {
                const Vector3d x((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a);
                for (const Vector3d& c : centres)
                    if (minimumImage(x - c, length).norm() < radius)
                        mask[(static_cast<std::size_t>(i) * m + j) * m + k] = 1;
            }
    return mask;
}

std::vector<Vector3d> randomCentres(int count, double length, std::mt19937_64& generator) {
    std::uniform_real_distribution<double> uniform(0.0, length);
    std::vector<Vector3d> centres(count);
    for (auto& c : centres)
        c = Vector3d(uniform(generator), uniform(generator), uniform(generator));
    return centres;
}

/// Right-continuous value of the step function F at x.
double stepF(const PoreSizeDistributionResult& r, double x) {
    return r.F[std::upper_bound(r.delta.begin(), r.delta.end(), x) - r.delta.begin() - 1];
}

Quaterniond randomRotation(std::mt19937_64& generator) {
    std::normal_distribution<double> gauss;
    return Quaterniond(gauss(generator), gauss(generator), gauss(generator), gauss(generator))
        .normalized();
}

class PoreSizeOfSpheres : public ::testing::Test {
  protected:
    void SetUp() override {
        std::mt19937_64 generator(99);
        mask = sphereMask(randomCentres(12, length, generator), 0.7, length, m);
    }
    const int m = 28;
    const double length = 4.0;
    const double meanWidth = 1.4;
    std::vector<std::uint8_t> mask;
};

TEST_F(PoreSizeOfSpheres, FStartsAtOneAndTheMomentsAreTheIntegralsOfF) {
    const PoreSizeMap map = periodicDistanceTransform(mask, m, length / m);
    const PoreSizeDistributionResult r =
        PoreSizeDistribution({}).compute(map, meanWidth, Progress());
    EXPECT_EQ(r.method, "voxels");
    EXPECT_EQ(r.samples, map.voidCount());
    ASSERT_GE(r.delta.size(), 3u);
    EXPECT_EQ(r.delta.front(), 0.0);
    EXPECT_EQ(r.F.front(), 1.0); // F(0) = 1
    EXPECT_EQ(stepF(r, 0.5 * length / m), 1.0);
    EXPECT_EQ(r.F.back(), 0.0);
    EXPECT_EQ(r.delta.back(), r.max);
    EXPECT_TRUE(std::is_sorted(r.F.rbegin(), r.F.rend()));

    // Direct numerical integration of Eqs. 14-15 (midpoint rule over the step function) ...
    const int steps = 400000;
    const double h = 1.05 * r.max / steps;
    double first = 0.0, second = 0.0;
    for (int s = 0; s < steps; ++s) {
        const double x = (s + 0.5) * h;
        first += stepF(r, x) * h;
        second += 2.0 * stepF(r, x) * x * h;
    }
    EXPECT_NEAR(r.mean, first, 1e-5 * r.mean);
    EXPECT_NEAR(r.secondMoment, second, 1e-5 * r.secondMoment);
    // ... and the sample means straight from the distance transform.
    double sum = 0.0, sumSquares = 0.0, largest = 0.0;
    for (const std::uint32_t d2 : map.squaredDistances())
        if (d2 > 0) {
            const double delta = map.voxelSize() * std::sqrt(static_cast<double>(d2));
            sum += delta;
            sumSquares += delta * delta;
            largest = std::max(largest, delta);
        }
    EXPECT_NEAR(r.mean, sum / map.voidCount(), 1e-12 * r.mean);
    EXPECT_NEAR(r.secondMoment, sumSquares / map.voidCount(), 1e-12 * r.secondMoment);
    EXPECT_DOUBLE_EQ(r.max, largest);
    EXPECT_EQ(r.saturated, r.max < 0.5 * meanWidth);
    EXPECT_DOUBLE_EQ(r.meanOverWidth(), r.mean / meanWidth);
    EXPECT_DOUBLE_EQ(r.deltaOverWidth().back(), r.max / meanWidth);

    // P(delta) is a normalised density whose histogram moments are close to <delta>.
    double norm = 0.0, histogramMean = 0.0;
    const double width = r.densityDelta[1] - r.densityDelta[0];
    for (std::size_t b = 0; b < r.density.size(); ++b) {
        norm += r.density[b] * width;
        histogramMean += r.density[b] * r.densityDelta[b] * width;
    }
    EXPECT_NEAR(norm, 1.0, 1e-12);
    EXPECT_NEAR(histogramMean, r.mean, 0.5 * width);
    // On voxels each density bin is wider than a voxel, so none falls empty between the
    // discrete sizes sqrt(n) a, n = 1, 2, 3, 4, 5, 6, 8, ... (a comb).
    EXPECT_GT(width, map.voxelSize());
    EXPECT_EQ(static_cast<double>(r.density.size()),
              std::min(64.0, std::ceil(r.max / map.voxelSize()) - 1.0));
    for (std::size_t b = 0; b < r.density.size(); ++b)
        EXPECT_GT(r.density[b], 0.0) << "empty bin " << b << " of " << r.density.size();
}

TEST_F(PoreSizeOfSpheres, RandomVoidPointsAreReproducibleAndApproachAllVoxels) {
    const ThreadBudget budget(2);
    const PoreSizeMap map = periodicDistanceTransform(mask, m, length / m);
    const Progress parallel;
    const PoreSizeDistributionResult all =
        PoreSizeDistribution({}).compute(map, meanWidth, parallel);
    PoreSizeParameters parameters;
    parameters.randomPoints = 200000;
    parameters.seed = 5;
    const PoreSizeDistributionResult sampled =
        PoreSizeDistribution(parameters).compute(map, meanWidth, parallel);
    Progress inOrder;
    inOrder.setSerial(true);
    const PoreSizeDistributionResult serial =
        PoreSizeDistribution(parameters).compute(map, meanWidth, inOrder);
    EXPECT_EQ(sampled.method, "random voxels");
    EXPECT_EQ(sampled.samples, 200000);
    EXPECT_EQ(sampled.F, serial.F);
    EXPECT_EQ(sampled.delta, serial.delta);
    // Kolmogorov-Smirnov distance of 200000 samples: ~1.36 / sqrt(K) = 0.003 at 95 %.
    EXPECT_LT(largestGap(sampled, all), 0.006);
    EXPECT_NEAR(sampled.mean, all.mean, 0.01 * all.mean);
    parameters.seed = 6;
    EXPECT_NE(PoreSizeDistribution(parameters).compute(map, meanWidth, parallel).F, sampled.F);
}

TEST(PoreSizeStatistics, LargestGapOfTwoStepFunctions) {
    // a: sizes 1, 2 (equal weight); b: sizes 1.5 (all). F_a = 1, 0.5, 0; F_b = 1, 0.
    const std::vector<double> sizesA = {1.0, 2.0}, sizesB = {1.5};
    const std::vector<std::int64_t> countsA = {1, 1}, countsB = {4};
    const auto a = poreSizeStatistics(sizesA, countsA, 1.0, 4);
    const auto b = poreSizeStatistics(sizesB, countsB, 1.0, 4);
    EXPECT_DOUBLE_EQ(largestGap(a, b), 0.5);
    EXPECT_DOUBLE_EQ(largestGap(a, a), 0.0);
    EXPECT_DOUBLE_EQ(a.mean, 1.5);
    EXPECT_DOUBLE_EQ(a.secondMoment, 2.5);
    EXPECT_FALSE(a.saturated); // max 2 >= w / 2 = 0.5
    const std::vector<double> unsorted = {2.0, 1.0};
    EXPECT_THROW(poreSizeStatistics(unsorted, countsA, 1.0, 4), std::invalid_argument);
    EXPECT_THROW(poreSizeStatistics(sizesA, countsA, 0.0, 4), std::invalid_argument);
    EXPECT_THROW(poreSizeStatistics(sizesA, countsA, 1.0, 0), std::invalid_argument);
    EXPECT_THROW(PoreSizeDistribution({-1, 1, 64}), std::invalid_argument);
}

TEST(ExactPoreSize, SingleSphereIsExactIncludingPeriodicImages) {
    const double r = 0.5, length = 2.5;
    const Vector3d centre(0.3, 2.2, 1.25);
    const ExactPoreSizes pores(testing::singleParticle(1.0, r, length, centre));
    std::mt19937_64 generator(3);
    std::uniform_real_distribution<double> uniform(-length, 2.0 * length);
    for (int n = 0; n < 2000; ++n) {
        const Vector3d x(uniform(generator), uniform(generator), uniform(generator));
        const double expected = std::max(0.0, minimumImage(x - centre, length).norm() - r);
        ASSERT_NEAR(pores.poreSize(x), expected, 1e-15) << x.transpose();
    }
    EXPECT_EQ(pores.poreSize(centre), 0.0);
    // Nearest through the boundary: 1.7 away inside the box, 0.8 through the face x = 0.
    EXPECT_NEAR(pores.poreSize(Vector3d(2.0, 2.2, 1.25)), 0.8 - r, 1e-15);
}

TEST(ExactPoreSize, SingleSphereDistributionMatchesTheClosedForm) {
    // For R + delta <= L / 2, F(delta) = (L^3 - 4/3 pi (R + delta)^3) / (L^3 - 4/3 pi R^3).
    const ThreadBudget budget(2);
    const double r = 0.5, length = 2.0;
    const Packing packing = testing::singleParticle(1.0, r, length, Vector3d(1.0, 1.0, 1.0));
    ExactPoreSizeParameters parameters;
    parameters.randomPoints = 100000;
    const PoreSizeDistributionResult result =
        ExactPoreSizeDistribution(parameters).compute(packing, Progress());
    Progress inOrder;
    inOrder.setSerial(true);
    EXPECT_EQ(ExactPoreSizeDistribution(parameters).compute(packing, inOrder).F, result.F);
    EXPECT_EQ(result.method, "exact");
    EXPECT_EQ(result.samples, 100000);
    EXPECT_DOUBLE_EQ(result.meanWidth, 1.0);
    const double ball = 4.0 / 3.0 * std::numbers::pi;
    const double v = std::pow(length, 3);
    for (const double delta : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5}) {
        const double expected = (v - ball * std::pow(r + delta, 3)) / (v - ball * std::pow(r, 3));
        EXPECT_NEAR(stepF(result, delta), expected, 0.005) << "delta = " << delta;
    }
    EXPECT_LE(result.max, std::sqrt(3.0) - r); // the box corner
}

TEST(ExactPoreSize, ClosestPointOnAxesAndDiagonalsIsExact) {
    const double r = 0.7;
    for (const double p : {0.5, 0.75, 1.0, 1.5, 3.0, 10.0, 200.0}) {
        const Superball shape(p, r);
        for (const double t : {0.71, 1.0, 3.0}) {
            const Vector3d onAxis(0.0, -t, 0.0);
            EXPECT_NEAR((onAxis - closestPoint(shape, onAxis)).norm(), t - r, 1e-14 * t)
                << "p = " << p;
            const Vector3d diagonal(t, -t, t);
            const double corner = r * std::pow(3.0, -1.0 / (2.0 * p));
            if (t > corner) {
                EXPECT_NEAR((diagonal - closestPoint(shape, diagonal)).norm(),
                            std::sqrt(3.0) * (t - corner), 1e-14 * t)
                    << "p = " << p << ", t = " << t;
            }
        }
        const Vector3d inside(0.1, 0.2, -0.1);
        EXPECT_EQ(closestPoint(shape, inside), inside);
    }
}

TEST(ExactPoreSize, ClosestPointIsCertifiedByTheSupportFunction) {
    // For y the returned point and n = (x - y) / |x - y|: n.x - h(n) <= dist <= |x - y|, so a
    // small gap certifies the distance; y must lie on the surface.
    std::mt19937_64 generator(11);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> radius(0.0, 1.5);
    for (const double p : {0.5, 0.6, 0.85, 1.5, 3.0, 10.0}) {
        const Superball shape(p, 0.5);
        int tested = 0;
        for (int n = 0; n < 2000; ++n) {
            Vector3d x(gauss(generator), gauss(generator), gauss(generator));
            x *= (0.5 + radius(generator)) / x.norm();
            if (shape.gauge(x) <= 1.0) continue;
            const Vector3d y = closestPoint(shape, x);
            const double upper = (x - y).norm();
            const Vector3d normal = (x - y) / upper;
            const double lower = normal.dot(x) - shape.support(normal);
            ASSERT_LE(upper - lower, 1e-11) << "p = " << p << ", x = " << x.transpose();
            ASSERT_NEAR(shape.gauge(y), 1.0, 1e-12) << "p = " << p;
            ++tested;
        }
        EXPECT_GT(tested, 500);
    }
}

/// The cell search against every image of every particle, each by closestPoint of its own shape;
/// of a mixture (docs/mixtures.md), semi-axes 0.24, 0.32, 0.4 in turn.
void expectCellSearchEqualsBruteForce(double p, bool mixture) {
    std::mt19937_64 generator(17);
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    packing.semiAxis = 0.4;
    packing.boxLength = 4.0;
    std::uniform_real_distribution<double> uniform(0.0, packing.boxLength);
    for (int n = 0; n < 25; ++n) {
        packing.positions.emplace_back(uniform(generator), uniform(generator), uniform(generator));
        packing.orientations.push_back(randomRotation(generator));
        if (mixture) packing.semiAxes.push_back(0.08 * (3 + n % 3));
    }
    const ExactPoreSizes pores(packing);
    for (int n = 0; n < 120; ++n) {
        const Vector3d x(uniform(generator), uniform(generator), uniform(generator));
        double expected = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < packing.size(); ++j)
            for (int a = -1; a <= 1; ++a)
                for (int b = -1; b <= 1; ++b)
                    for (int c = -1; c <= 1; ++c) {
                        const Vector3d image =
                            packing.positions[j] + packing.boxLength * Vector3d(a, b, c);
                        const Vector3d body =
                            packing.orientations[j].toRotationMatrix().transpose() * (x - image);
                        const Superball shape(packing.shapeSpec.superballExponent().value(),
                                              packing.semiAxisOf(j));
                        expected = std::min(expected, (body - closestPoint(shape, body)).norm());
                    }
        ASSERT_NEAR(pores.poreSize(x), expected, 1e-14) << x.transpose();
    }
}

TEST(ExactPoreSize, CellSearchEqualsBruteForceOverAllImages) {
    expectCellSearchEqualsBruteForce(1.5, false);
}

TEST(ExactPoreSize, CellSearchEqualsBruteForceForAMixture) {
    for (const double p : {1.0, 1.5, 0.8})
        expectCellSearchEqualsBruteForce(p, true);
}

TEST(ExactPoreSize, RejectsBadInput) {
    Packing empty;
    EXPECT_THROW(ExactPoreSizes{empty}, std::invalid_argument);
    EXPECT_THROW(ExactPoreSizeDistribution({0, 1, 64}), std::invalid_argument);
}

} // namespace
} // namespace sbpack

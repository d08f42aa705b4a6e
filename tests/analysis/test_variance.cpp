// The local volume-fraction variance (analysis/variance, docs/local-structure.md §2): the
// spectral route against a real-space quadrature for the Debye medium, the two routes against
// each other, and the tails of a Poisson-like and a hyperuniform packing.
#include "variance/volume_fraction_variance.hpp"

#include "../common/order_lattices.hpp"
#include "hyperuniformity/debye_medium.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "test_packings.hpp"
#include "test_spectra.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sbpack {
namespace {

const Progress quiet;
constexpr double kPi = std::numbers::pi;

TEST(Variance, WindowFactorIsTheSphereTransformAndJoinsItsSeries) {
    EXPECT_EQ(sphereWindowFactor(0.0), 1.0);
    const double x = 0.1 * (1.0 + 1e-12); // the closed form just above the series' end
    EXPECT_NEAR(sphereWindowFactor(x), sphereWindowFactor(0.1 * (1.0 - 1e-12)), 1e-13);
    // The first zero of F: tan x = x at x = 4.4934094579.
    EXPECT_NEAR(sphereWindowFactor(4.4934094579090641), 0.0, 1e-12);
}

/// sigma_V^2(R) of the Debye medium, chi(r) = phi (1 - phi) exp(-r / a), in real space:
/// (1 / v(R)) int_0^2R 4 pi r^2 chi(r) alpha(r; R) dr, alpha = 1 - 3 r / (4 R) + r^3 / (16 R^3)
/// the two windows' intersection over v(R); Simpson's rule.
double debyeVarianceRealSpace(double phi, double a, double radius) {
    const int n = 20000;
    const double h = 2.0 * radius / n, v = 4.0 / 3.0 * kPi * radius * radius * radius;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double r = i * h, s = r / radius;
        const double f = 4.0 * kPi * r * r * std::exp(-r / a) * (1.0 - 0.75 * s + s * s * s / 16);
        sum += f * (i == 0 || i == n ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    return phi * (1.0 - phi) * sum * h / 3.0 / v;
}

TEST(Variance, SpectralRouteOfTheDebyeMediumIsItsRealSpaceIntegral) {
    const double phi = 0.3, a = 1.0, box = 40.0;
    const DiscreteSpectrum s = testing::debyeBoxSpectrum(phi, a, box, 40);
    // The periodic box leaves out Q = 0, whose share of the integral is chi_V(0) / V: the box's
    // own phi does not fluctuate (docs/local-structure.md §2).
    const double zeroMode = debyeSpectralDensity(0.0, phi, a) / (box * box * box);
    for (double radius : {1.0, 2.0, 4.0, 8.0}) {
        const double expected = debyeVarianceRealSpace(phi, a, radius);
        EXPECT_NEAR((spectralVariance(s, radius) + zeroMode) / expected, 1.0, 2e-3)
            << "R = " << radius;
    }
}

/// chi_V = Q^alpha exp(-Q^2) (unit length) on the wave vectors |n_i| <= reach of a box of edge
/// `box`: hyperuniform of exponent alpha, without noise.
DiscreteSpectrum powerLawBoxSpectrum(double alpha, double box, int reach) {
    DiscreteSpectrum s = testing::debyeBoxSpectrum(0.3, 1.0, box, reach);
    std::fill(s.sumByN2.begin(), s.sumByN2.end(), 0.0);
    for (int x = -reach; x <= reach; ++x)
        for (int y = -reach; y <= reach; ++y)
            for (int z = -reach; z <= reach; ++z) {
                const std::int64_t n2 = x * x + y * y + z * z;
                const double q = 2 * kPi * std::sqrt(static_cast<double>(n2)) / box;
                if (n2 != 0) s.sumByN2[n2] += std::pow(q, alpha) * std::exp(-q * q);
            }
    return s;
}

TEST(Variance, TheTailFitFindsTheSpectrumsExponentUpToOne) {
    // sigma^2 ~ R^-(3 + alpha) for alpha < 1; beyond, R^-4 (the windows' surface) leads and
    // the fit says so (saturated at the top of its grid).
    const DiscreteSpectrum beyond = powerLawBoxSpectrum(2.0, 120.0, 80);
    const VarianceResult surface = VolumeFractionVariance({}).compute(beyond, nullptr, quiet);
    ASSERT_TRUE(surface.exponent);
    EXPECT_TRUE(surface.exponent->saturated) << surface.exponent->alpha;
    for (const auto& [alpha, expected] : {std::pair{0.0, 0.0}, {0.5, 0.5}, {0.8, 0.8}}) {
        const DiscreteSpectrum s = powerLawBoxSpectrum(alpha, 120.0, 80);
        const VarianceResult r = VolumeFractionVariance({}).compute(s, nullptr, quiet);
        ASSERT_TRUE(r.exponent);
        EXPECT_FALSE(r.exponent->saturated);
        EXPECT_NEAR(r.exponent->alpha, expected, 0.05)
            << "alpha " << alpha << ": fit +- " << r.exponent->standardError;
    }
}

/// Both routes on the voxel grid of `packing`, the spectral one from the grid's own transform
/// (no cube form factor: the medium of the voxel centres that the sampled windows count).
VarianceResult bothRoutes(const Packing& packing, int m, int windows) {
    const Voxelization voxels = Voxelizer({m}).compute(packing, quiet);
    const VoxelFourierTransform transform(voxels, {FftPlanning::Estimate, {}}, quiet);
    VoxelSpectrumOptions plain;
    plain.cubeFormFactor = false;
    const DiscreteSpectrum s =
        voxelSpectrum(transform, voxels, packing.shape().meanWidth(), plain, quiet);
    VarianceParameters parameters;
    parameters.windows = windows;
    return VolumeFractionVariance(parameters).compute(s, &voxels, quiet);
}

TEST(Variance, TheTwoRoutesAgreeWithinTheSampledErrorBars) {
    const Packing rsa = testing::randomSequentialAddition(400, 0.3, 5);
    const VarianceResult r = bothRoutes(rsa, 96, 3000);
    ASSERT_EQ(r.sampled.size(), r.radius.size());
    ASSERT_GE(r.radius.size(), 10u);
    for (std::size_t i = 0; i < r.radius.size(); ++i) {
        EXPECT_GT(r.sampledError[i], 0.0);
        EXPECT_LT(std::abs(r.sampled[i] - r.spectral[i]), 4.0 * r.sampledError[i])
            << "R = " << r.radius[i] << ": sampled " << r.sampled[i] << " +- " << r.sampledError[i]
            << ", spectral " << r.spectral[i];
    }
}

TEST(Variance, APoissonLikePackingsTailIsRMinusThree) {
    // RSA: S(0) > 0, alpha = 0, sigma^2 ~ R^-3.
    const VarianceResult rsa = bothRoutes(testing::randomSequentialAddition(5000, 0.3, 9), 128, 0);
    ASSERT_TRUE(rsa.exponent);
    // The box's R <= L / 4 (L = 20.6 w) leaves the fit some curvature: +0.29 measured
    // (docs/local-structure.md §2); a hyperuniform tail would give 0.5 to 1.
    EXPECT_NEAR(rsa.exponent->alpha, 0.0, 0.35)
        << "+- " << rsa.exponent->standardError << " over " << rsa.exponent->points << " radii";
}

TEST(Variance, AUniformlyRandomizedLatticeFallsAsRMinusFour) {
    // Spheres of diameter 0.3 on a simple-cubic lattice of spacing 1, each moved uniformly over
    // its whole cell: the Bragg peaks cancel and chi_V ~ Q^2 (alpha = 2), so sigma^2 ~ R^-4 and
    // the fit saturates (bench/RESULTS.md, "Volume-fraction variance": 0.98 +- 0.11 at L = 16).
    Packing lattice =
        lattices::displaced(lattices::cubicCrystal(10, 1.0, lattices::kSimpleCubic), 0.5, 4);
    lattice.semiAxis = 0.15;
    const VarianceResult r = bothRoutes(lattice, 140, 0);
    ASSERT_TRUE(r.exponent);
    EXPECT_TRUE(r.exponent->saturated) << r.exponent->alpha << " +- " << r.exponent->standardError;
}

TEST(Variance, RefusesBadParametersAndAMismatchedGrid) {
    VarianceParameters p;
    p.windows = 5; // fewer than the batches
    EXPECT_THROW(VolumeFractionVariance{p}, std::invalid_argument);
    p.windows = 0;
    p.minRadiusW = 0.0;
    EXPECT_THROW(VolumeFractionVariance{p}, std::invalid_argument);
    const DiscreteSpectrum s = testing::debyeBoxSpectrum(0.3, 1.0, 10.0, 4);
    const Packing rsa = testing::randomSequentialAddition(20, 0.2, 3);
    const Voxelization voxels = Voxelizer({24}).compute(rsa, quiet);
    EXPECT_THROW(VolumeFractionVariance({}).compute(s, &voxels, quiet), std::invalid_argument);
}

} // namespace
} // namespace sbpack

#include "spectral/spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"

#include "test_packings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sbpack {
namespace {

const Progress quiet;

FftSettings estimateOnly() {
    return {FftPlanning::Estimate, {}}; // fast planning, no wisdom file
}

int signedIndex(int k, int m) {
    return 2 * k <= m ? k : k - m;
}

/// Rotated superballs crossing the box faces (a non-trivial indicator).
Packing superballs() {
    return testing::latticePacking(1.5, 3, 1.35, 0.03, 23);
}

TEST(SpectralDensity, ParsevalOnTheGrid) {
    // (1 / (phi V)) sum_{Q != 0} |F(Q)|^2 a^6 / V = 1 - phi, phi the voxel fraction: the
    // autocovariance of the voxel indicator at r = 0 is phi (1 - phi). Odd and even M (the
    // real-to-complex half space has a Nyquist plane only for even M).
    const Packing packing = superballs();
    for (const int m : {32, 33}) {
        const Voxelization voxels = Voxelizer({m}).compute(packing, quiet);
        const VoxelFourierTransform transform(voxels, estimateOnly(), quiet);
        const double a = voxels.voxelSize(), volume = std::pow(packing.boxLength, 3);
        double sum = 0.0;
        for (int kx = 0; kx < m; ++kx)
            for (int ky = 0; ky < m; ++ky)
                for (int kz = 0; kz <= m / 2; ++kz)
                    if (kx || ky || kz) sum += transform.weight(kz) * transform.power(kx, ky, kz);
        const double phi = voxels.phiVoxel();
        EXPECT_NEAR(sum * std::pow(a, 6) / volume / (phi * volume), 1.0 - phi, 1e-10) << m;
        EXPECT_DOUBLE_EQ(transform.power(0, 0, 0),
                         std::pow(static_cast<double>(voxels.solidCount()), 2));
    }
}

TEST(SpectralDensity, ParsevalWithTheCubeFormFactorNeedsEveryAlias) {
    // chi(Q) of the medium of voxel cubes at every Q = 2 pi n / L, n in Z^3, is
    // |F(n mod M)|^2 m_cube(Q)^2 / V: its sum over n != 0 obeys the same rule, which the grid
    // alone (m = 0 below) does not. The form factor is separable: per axis, sum over the
    // aliases n_i = k_i + M m of [cubeFormFactor along that axis]^2, up to |m| = K, plus the
    // tail a^2 sin^2(pi x) sum_{|m| > K} 1 / (pi (x + m))^2, x = k_i / M, by the midpoint rule.
    const Packing packing = superballs();
    const int m = 32;
    const Voxelization voxels = Voxelizer({m}).compute(packing, quiet);
    const VoxelFourierTransform transform(voxels, estimateOnly(), quiet);
    const double a = voxels.voxelSize(), boxLength = packing.boxLength;
    const double volume = std::pow(boxLength, 3);
    auto axisFactor2 = [&](double n) { // [a sinc(Q a / 2)]^2 along one axis, via the library
        const double f = cubeFormFactor(Vector3d(2.0 * std::numbers::pi * n / boxLength, 0, 0), a);
        return f * f / std::pow(a, 4);
    };
    const int aliases = 2000;
    std::vector<double> aliasSum(m), gridOnly(m);
    for (int k = 0; k < m; ++k) {
        const double x = static_cast<double>(signedIndex(k, m)) / m;
        double sum = 0.0;
        for (int alias = -aliases; alias <= aliases; ++alias)
            sum += axisFactor2(signedIndex(k, m) + static_cast<double>(m) * alias);
        const double s = std::sin(std::numbers::pi * x);
        sum += a * a * s * s / (std::numbers::pi * std::numbers::pi) *
               (1.0 / (aliases + 0.5 + x) + 1.0 / (aliases + 0.5 - x));
        aliasSum[k] = sum;
        gridOnly[k] = axisFactor2(signedIndex(k, m));
    }
    double all = 0.0, grid = 0.0;
    for (int kx = 0; kx < m; ++kx)
        for (int ky = 0; ky < m; ++ky)
            for (int kz = 0; kz <= m / 2; ++kz) {
                if (!(kx || ky || kz)) continue;
                const double p = transform.weight(kz) * transform.power(kx, ky, kz) / volume;
                // -k_z (stored as k_z) has the same factor: sinc^2 is even.
                all += p * aliasSum[kx] * aliasSum[ky] * aliasSum[kz];
                grid += p * gridOnly[kx] * gridOnly[ky] * gridOnly[kz];
            }
    const double phi = voxels.phiVoxel();
    EXPECT_NEAR(all / (phi * volume), 1.0 - phi, 1e-10);
    EXPECT_LT(grid / (phi * volume), 0.9 * (1.0 - phi)); // the aliases matter
}

TEST(SpectralDensity, FormFactors) {
    const double r = 0.7, volume = 4.0 * std::numbers::pi * r * r * r / 3.0;
    EXPECT_DOUBLE_EQ(sphereFormFactor(0.0, r), volume);
    for (const double x : {0.0999999, 0.1000001, 2.0, 4.4934094579}) { // last: tan x = x
        const double q = x / r;
        const double direct =
            4.0 * std::numbers::pi * (std::sin(x) - x * std::cos(x)) / (q * q * q);
        EXPECT_NEAR(sphereFormFactor(q, r), direct, 1e-11 * volume) << x;
    }
    EXPECT_NEAR(sphereFormFactor(4.4934094579 / r, r), 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(cubeFormFactor(Vector3d::Zero(), 0.3), 0.027);
    // A cube's form factor vanishes at Q_i a / 2 = pi.
    EXPECT_NEAR(cubeFormFactor(Vector3d(2.0 * std::numbers::pi / 0.3, 1.0, 2.0), 0.3), 0.0, 1e-17);
}

TEST(SpectralDensity, SphereVoxelPathAgreesWithTheExactOneAtSmallQ) {
    // 64 spheres (phi = 0.27) with D = 19 voxels. At small Q the voxelized spheres scatter as
    // the true ones up to the voxel error: their volume error (chi ~ v^2) and the phase error
    // Q dc of their centroids, shifted by dc ~ a^2 / R by the voxel surface.
    const Packing packing = testing::latticePacking(1.0, 4, 1.25, 0.1, 31);
    const int m = 96;
    const Voxelization voxels = Voxelizer({m}).compute(packing, quiet);
    SpectralDensityParameters parameters;
    parameters.maxQw = 6.0;
    parameters.fft = estimateOnly();
    const SpectralDensityResult result =
        SpectralDensity(parameters).compute(packing, voxels, quiet);
    ASSERT_TRUE(result.exactSphere.has_value());
    const ShellAverage& exact = result.exactSphere->exact;
    ASSERT_EQ(exact.size(), result.shells.size());
    const double volumeError = std::abs(voxels.phiVoxel() / voxels.phiExact() - 1.0);
    const double a = voxels.voxelSize();
    for (std::size_t s = 0; s < exact.size(); ++s) {
        EXPECT_DOUBLE_EQ(result.shells.q[s], exact.q[s]);
        EXPECT_EQ(result.shells.count[s], exact.count[s]);
        const double qw = result.shells.q[s] * result.meanWidth;
        if (qw > 4.0) continue;
        const double q = result.shells.q[s];
        EXPECT_NEAR(result.shells.value[s] / exact.value[s], 1.0,
                    2.0 * volumeError + q * a * a / packing.semiAxis)
            << "Q w = " << qw;
    }
    EXPECT_LT(result.exactSphere->maxErrorOverPeak, 0.05);
}

TEST(SpectralDensity, ValidatesItsInput) {
    SpectralDensityParameters negative;
    negative.maxQw = -1.0;
    EXPECT_THROW(SpectralDensity{negative}, std::invalid_argument);
    const Packing packing = superballs();
    const Voxelization voxels = Voxelizer({32}).compute(packing, quiet);
    Packing other = packing;
    other.boxLength *= 1.01;
    SpectralDensityParameters parameters;
    parameters.fft = estimateOnly();
    EXPECT_THROW(SpectralDensity(parameters).compute(other, voxels, quiet), std::invalid_argument);
    EXPECT_THROW(sphereSpectralDensity(packing, 4, quiet), std::invalid_argument); // p = 1.5
}

} // namespace
} // namespace sbpack

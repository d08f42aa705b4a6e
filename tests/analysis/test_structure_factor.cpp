#include "structure/collective_density.hpp"
#include "structure/structure_factor.hpp"

#include "test_packings.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <numbers>
#include <random>
#include <set>

namespace sbpack {
namespace {

const Progress quiet;

bool inHalfSpace(const std::array<int, 3>& n) {
    return n[0] > 0 || (n[0] == 0 && n[1] > 0) || (n[0] == 0 && n[1] == 0 && n[2] > 0);
}

TEST(CollectiveDensity, CoversTheHalfSpaceOnceAndMatchesTheDirectSum) {
    std::mt19937_64 rng(17);
    const double boxLength = 3.7;
    std::uniform_real_distribution<double> where(0.0, boxLength);
    std::vector<Vector3d> positions(60);
    for (Vector3d& r : positions)
        r = Vector3d(where(rng), where(rng), where(rng));
    const std::int64_t maxN2 = 30;
    const DensityModes modes = collectiveDensity(positions, boxLength, maxN2, quiet);

    std::set<std::array<int, 3>> seen;
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const auto& n = modes.n[m];
        EXPECT_TRUE(inHalfSpace(n));
        EXPECT_LE(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], maxN2);
        EXPECT_TRUE(seen.insert(n).second) << "repeated wave vector";
        std::complex<double> rho = 0.0;
        for (const Vector3d& r : positions)
            rho += std::polar(1.0, -2.0 * std::numbers::pi *
                                       (n[0] * r.x() + n[1] * r.y() + n[2] * r.z()) / boxLength);
        EXPECT_NEAR(modes.intensity[m], std::norm(rho), 1e-11 * positions.size());
    }
    std::size_t ball = 0; // integer vectors with 1 <= |n|^2 <= maxN2: half of them are kept
    for (int x = -6; x <= 6; ++x)
        for (int y = -6; y <= 6; ++y)
            for (int z = -6; z <= 6; ++z)
                ball += x * x + y * y + z * z <= maxN2 && (x || y || z);
    EXPECT_EQ(2 * modes.size(), ball);
}

TEST(StructureFactor, SimpleCubicLatticeHasBraggPeaksOnly) {
    // N = 125 on a 5^3 lattice: S = N where n is a multiple of 5 along every axis, else 0.
    const int cells = 5;
    const Packing lattice = testing::latticePacking(1.5, cells, 1.0, 0.0, 1, true, 0.25);
    const auto n = static_cast<double>(lattice.size());
    const DensityModes modes =
        collectiveDensity(lattice.positions, lattice.boxLength, 12 * 12, quiet);
    int bragg = 0;
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const auto& k = modes.n[m];
        const double s = modes.intensity[m] / n;
        if (k[0] % cells == 0 && k[1] % cells == 0 && k[2] % cells == 0) {
            EXPECT_NEAR(s, n, 1e-9 * n);
            ++bragg;
        } else {
            EXPECT_LT(s, 1e-20 * n) << k[0] << ' ' << k[1] << ' ' << k[2];
        }
    }
    EXPECT_EQ(bragg, 28); // n = 5 m: half of the 6 + 12 + 8 + 6 + 24 m with |m|^2 <= 5

    // Shell-averaged: shell 5 holds the 6 vectors (+-5, 0, 0)... among its others.
    const StructureFactorResult result =
        StructureFactor(
            {12.4 * 2.0 * std::numbers::pi * lattice.shape().meanWidth() / lattice.boxLength})
            .compute(lattice, quiet);
    ASSERT_EQ(result.maxShell, 12);
    EXPECT_NEAR(result.shells.value[4], n * 6.0 / result.shells.count[4], 1e-9 * n);
    EXPECT_LT(result.shells.value[0], 1e-20);
}

TEST(StructureFactor, ValidatesItsParameters) {
    EXPECT_THROW(StructureFactor({0.0}), std::invalid_argument);
    EXPECT_THROW(StructureFactor({std::numeric_limits<double>::infinity()}), std::invalid_argument);
    const Packing lattice = testing::latticePacking(1.0, 2, 1.0, 0.0, 1, true);
    EXPECT_THROW(StructureFactor({0.5}).compute(lattice, quiet), std::invalid_argument);
}

} // namespace
} // namespace sbpack

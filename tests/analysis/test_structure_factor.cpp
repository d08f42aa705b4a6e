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

namespace sbpack {
namespace {

/// CsCl: large particles (A) on a c^3 simple cubic lattice, small ones (B) on its cube centres.
Packing caesiumChloride(int cells) {
    Packing packing = testing::latticePacking(1.0, cells, 1.0, 0.0, 1, true, 0.1);
    const std::size_t corners = packing.size();
    packing.semiAxes.assign(corners, 0.5);
    for (std::size_t i = 0; i < corners; ++i) {
        packing.positions.push_back(
            wrapIntoBox(packing.positions[i] + Vector3d::Constant(0.5), packing.boxLength));
        packing.orientations.push_back(Quaterniond::Identity());
        packing.semiAxes.push_back(0.3);
    }
    return packing;
}

// docs/mixtures.md: the partials of a known structure. On shell c (the vectors c (1, 0, 0) and
// their images among the shell's others) each species' lattice has its Bragg peak, S_aa = N_a,
// and the two are in antiphase, Re(rho_A rho_B*) = -N_A N_B: the bcc extinction, S = 0.
TEST(StructureFactor, TheCaesiumChloridePartialsHaveTheirBraggPeaksAndCancelInTheTotal) {
    const int cells = 4;
    const Packing cscl = caesiumChloride(cells);
    const double nA = 64.0;
    const StructureFactorResult result =
        StructureFactor({6.4 * 2.0 * std::numbers::pi * cscl.shape().meanWidth() / cscl.boxLength})
            .compute(cscl, quiet);
    ASSERT_TRUE(result.partials.has_value());
    const PartialStructureFactors& s = *result.partials;
    EXPECT_DOUBLE_EQ(s.fractionA, 0.5);
    const std::size_t shell = cells - 1; // shell c, counted from 1
    const double bragg = 6.0 / static_cast<double>(result.shells.count[shell]);
    EXPECT_NEAR(s.aa[shell], nA * bragg, 1e-9 * nA);
    EXPECT_NEAR(s.bb[shell], nA * bragg, 1e-9 * nA);
    EXPECT_NEAR(s.ab[shell], -nA * bragg, 1e-9 * nA);
    EXPECT_NEAR(result.shells.value[shell], 0.0, 1e-9 * nA);
    EXPECT_NEAR(s.aa[0], 0.0, 1e-12 * nA); // no Bragg vector in shell 1
}

// The sum rule S = x_A S_AA + x_B S_BB + 2 sqrt(x_A x_B) S_AB on a disordered binary packing: the
// total from one sum over all particles, the partials from each species' own.
TEST(StructureFactor, ABinaryMixturesPartialsSumToTheTotal) {
    Packing packing = testing::latticePacking(1.0, 5, 1.3, 0.3, 23);
    std::mt19937_64 rng(5);
    for (std::size_t i = 0; i < packing.size(); ++i)
        packing.semiAxes.push_back(rng() % 3 == 0 ? 0.5 : 0.35);
    const StructureFactorResult result = StructureFactor({20.0}).compute(packing, quiet);
    ASSERT_TRUE(result.partials.has_value());
    const PartialStructureFactors& s = *result.partials;
    const double xA = s.fractionA, xB = 1.0 - xA;
    EXPECT_GT(xA, 0.2);
    EXPECT_LT(xA, 0.5);
    for (std::size_t k = 0; k < result.shells.size(); ++k)
        EXPECT_NEAR(xA * s.aa[k] + xB * s.bb[k] + 2.0 * std::sqrt(xA * xB) * s.ab[k],
                    result.shells.value[k], 1e-10)
            << "shell " << k + 1;
    // Identical particles, and three sizes: no partials.
    packing.semiAxes[0] = 0.4;
    EXPECT_FALSE(StructureFactor({20.0}).compute(packing, quiet).partials.has_value());
    packing.semiAxes.clear();
    EXPECT_FALSE(StructureFactor({20.0}).compute(packing, quiet).partials.has_value());
}

} // namespace
} // namespace sbpack

#include "voxels/voxelization.hpp"

#include "test_packings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

const Progress quiet;

/// The particle holding a voxel centre by the definition, independently of the voxelizer: the
/// minimum image of the centre relative to it is inside it (rc < L/2, so no other image can
/// contain it); -1 for none.
int holderByDefinition(const Packing& packing, int m, int i, int j, int k) {
    const double a = packing.boxLength / m;
    const Vector3d centre((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a);
    for (std::size_t n = 0; n < packing.size(); ++n) {
        const Superball shape(packing.shapeSpec.superballExponent().value(),
                              packing.semiAxisOf(n)); // a mixture's own size
        const Vector3d d = minimumImage(centre - packing.positions[n], packing.boxLength);
        if (shape.contains(packing.orientations[n].toRotationMatrix().transpose() * d))
            return static_cast<int>(n);
    }
    return -1;
}

void expectMatchesDefinition(const Packing& packing, int m) {
    const Voxelization voxels = Voxelizer({m}).compute(packing, quiet);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m, 7);
    voxels.copySolidMask(mask);
    const std::vector<std::uint32_t> labels = Voxelizer({m}).particleLabels(packing, quiet);
    std::int64_t solid = 0, wrong = 0, wrongLabels = 0;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k) {
                const int holder = holderByDefinition(packing, m, i, j, k);
                const bool expected = holder >= 0;
                const std::size_t index = (static_cast<std::size_t>(i) * m + j) * m + k;
                solid += expected;
                wrong += mask[index] != (expected ? 1 : 0) || voxels.solid(i, j, k) != expected;
                wrongLabels += labels[index] != static_cast<std::uint32_t>(holder + 1);
            }
    EXPECT_EQ(wrong, 0) << "p = " << packing.shapeSpec.superballExponent().value() << ", M = " << m;
    EXPECT_EQ(wrongLabels, 0) << "particle labels, p = "
                              << packing.shapeSpec.superballExponent().value() << ", M = " << m;
    EXPECT_EQ(voxels.solidCount(), solid);
    EXPECT_DOUBLE_EQ(voxels.phiVoxel(), static_cast<double>(solid) / (double(m) * m * m));
}

TEST(Voxelization, MatchesTheCentreInParticleDefinition) {
    // Rotated superballs from near-octahedra to near-cubes, several crossing the box faces.
    for (const double p : {0.5, 0.6, 1.0, 1.25, 1.5, 3.0, 8.5}) {
        const double rc = Superball(p, 0.5).circumradius();
        const Packing packing = testing::latticePacking(p, 3, 2.0 * rc + 0.2, 0.05, 11);
        expectMatchesDefinition(packing, Voxelizer::minimumVoxels(packing) + 5);
    }
}

// docs/mixtures.md: each particle at its own size (semi-axes 0.25-0.5, rotated, across the box
// faces), voxel by voxel and label by label; phi_voxel then converges to sum_i v_i / L^3.
TEST(Voxelization, AMixtureMatchesTheDefinitionAtEachParticlesSize) {
    for (const double p : {0.7, 1.0, 2.5}) {
        const double rc = Superball(p, 0.5).circumradius();
        Packing packing = testing::latticePacking(p, 3, 2.0 * rc + 0.2, 0.05, 7);
        for (std::size_t i = 0; i < packing.size(); ++i)
            packing.semiAxes.push_back(0.5 - 0.25 * static_cast<double>(i % 5) / 4.0);
        ASSERT_EQ(packing.semiAxis, 0.5);
        expectMatchesDefinition(packing, Voxelizer::minimumVoxels(packing) + 3);
        const Voxelization fine = Voxelizer({400}).compute(packing, quiet);
        EXPECT_NEAR(fine.phiExact(), packing.packingFraction(), 1e-15);
        EXPECT_NEAR(fine.phiVoxel() / fine.phiExact(), 1.0, 2e-3) << "p = " << p;
    }
}

TEST(Voxelization, FullBlocksAndEdgeBlocks) {
    // A large sphere: whole 8^3 blocks inside it are stored as tiles; M = 61 leaves partial
    // blocks at the upper faces.
    for (const int m : {64, 61}) {
        const Packing packing = testing::singleParticle(1.0, 0.45, 1.0, Vector3d(0.5, 0.48, 0.52));
        expectMatchesDefinition(packing, m);
    }
}

TEST(Voxelization, WrapsAcrossTheBoundary) {
    // A sphere centred on a voxel corner: at the box's corner its voxels sit at all 8 corners of
    // the grid; at the box centre, the same number of voxels.
    const int m = 40;
    const Voxelization corner =
        Voxelizer({m}).compute(testing::singleParticle(1.0, 0.5, 4.0, Vector3d::Zero()), quiet);
    for (const int i : {0, m - 1})
        for (const int j : {0, m - 1})
            for (const int k : {0, m - 1})
                EXPECT_TRUE(corner.solid(i, j, k)) << i << ' ' << j << ' ' << k;
    EXPECT_FALSE(corner.solid(m / 2, m / 2, m / 2));
    EXPECT_TRUE(corner.solid(-1, m, 2 * m)); // indices are periodic
    const Voxelization centre = Voxelizer({m}).compute(
        testing::singleParticle(1.0, 0.5, 4.0, Vector3d::Constant(2.0)), quiet);
    EXPECT_EQ(corner.solidCount(), centre.solidCount());
}

TEST(Voxelization, SphereFractionConvergesToTheExactOne) {
    // The error of one sphere's voxel count depends on where it sits: average it over positions
    // (fixed seed). It must fall with every doubling of M (the lattice-point error of a ball
    // falls like M^{-3/2} on average) and be small at D = 64 voxels.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> where(0.0, 2.0);
    std::vector<Vector3d> positions(12);
    for (Vector3d& r : positions)
        r = Vector3d(where(rng), where(rng), where(rng));
    double previous = std::numeric_limits<double>::infinity();
    for (const int m : {16, 32, 64, 128, 256}) {
        double meanError = 0.0;
        for (const Vector3d& r : positions) {
            const Voxelization voxels =
                Voxelizer({m}).compute(testing::singleParticle(1.0, 0.5, 2.0, r), quiet);
            meanError += std::abs(voxels.phiVoxel() / voxels.phiExact() - 1.0) / positions.size();
        }
        EXPECT_LT(meanError, previous) << "M = " << m;
        previous = meanError;
    }
    EXPECT_LT(previous, 1e-4); // M = 256: 64 voxels across the sphere
}

TEST(Voxelization, RejectsCoarseGridsAndOversizedParticles) {
    const Packing packing = testing::singleParticle(1.5, 0.5, 5.0, Vector3d::Constant(1.0));
    EXPECT_EQ(Voxelizer::minimumVoxels(packing), 20); // 4 voxels across D = 1 in L = 5
    EXPECT_THROW(Voxelizer({19}).compute(packing, quiet), VoxelResolutionError);
    EXPECT_NO_THROW(Voxelizer({20}).compute(packing, quiet));
    EXPECT_THROW(Voxelizer({0}), VoxelResolutionError);
    EXPECT_THROW(Voxelizer({Voxelizer::kMaxVoxels + 1}), VoxelResolutionError);
    const Packing tooLarge = testing::singleParticle(1.0, 0.6, 1.0, Vector3d::Constant(0.5));
    EXPECT_THROW(Voxelizer({40}).compute(tooLarge, quiet), VoxelResolutionError);
}

TEST(Voxelization, ABoxNoGridResolvesIsNamedSo) {
    // sbgen --phi-init 1e-300 once wrote L = 2.2e100: "use M >= -2147483648" (issue 65).
    const Packing huge = testing::singleParticle(1.5, 0.5, 2.2e100, Vector3d::Constant(1.0));
    EXPECT_EQ(Voxelizer::minimumVoxels(huge), Voxelizer::kMaxVoxels + 1);
    try {
        Voxelizer::checkResolution(huge, 300);
        ADD_FAILURE() << "a box of 1e100 diameters was resolved";
    } catch (const VoxelResolutionError& e) {
        EXPECT_NE(std::string(e.what()).find("no grid can (M <= 65536): the box is too large"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Voxelization, IndicatorLeavesRowPaddingAlone) {
    const int m = 24;
    const Packing packing = testing::singleParticle(1.0, 0.5, 2.0, Vector3d(1.0, 0.3, 1.7));
    const Voxelization voxels = Voxelizer({m}).compute(packing, quiet);
    const std::int64_t stride = 2 * (m / 2 + 1);
    std::vector<double> values(static_cast<std::size_t>(m * m * stride), -1.0);
    voxels.copySolidIndicator(values, stride);
    double sum = 0.0;
    for (std::int64_t row = 0; row < m * m; ++row) {
        for (std::int64_t k = 0; k < m; ++k)
            sum += values[row * stride + k];
        for (std::int64_t k = m; k < stride; ++k)
            EXPECT_EQ(values[row * stride + k], -1.0);
    }
    EXPECT_EQ(sum, static_cast<double>(voxels.solidCount()));
    EXPECT_THROW(voxels.copySolidIndicator(values, stride + 1), std::invalid_argument);
    std::vector<std::uint8_t> small(10);
    EXPECT_THROW(voxels.copySolidMask(small), std::invalid_argument);
}

TEST(Voxelization, WritesAVdbFileAtomically) {
    const fs::path dir = fs::temp_directory_path() / "sbpack-test-vdb";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const Packing packing = testing::latticePacking(1.5, 2, 1.5, 0.0, 3);
    const Voxelization voxels = Voxelizer({24}).compute(packing, quiet);
    voxels.writeVdb(dir / "grid.vdb");
    std::ifstream in(dir / "grid.vdb", std::ios::binary);
    unsigned char magic[4] = {};
    in.read(reinterpret_cast<char*>(magic), 4);
    EXPECT_EQ(magic[0], 0x20); // OpenVDB's magic number 0x56444220 ("VDB "), little endian
    EXPECT_EQ(magic[1], 0x42);
    EXPECT_EQ(magic[2], 0x44);
    EXPECT_EQ(magic[3], 0x56);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    EXPECT_THROW(voxels.writeVdb(dir / "missing" / "grid.vdb"), std::exception);
    fs::remove_all(dir);
}

} // namespace
} // namespace sbpack

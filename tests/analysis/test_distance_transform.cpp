#include "pores/distance_transform.hpp"

#include "io/atomic_file.hpp"
#include "parallel/parallel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {
namespace {

std::int64_t indexOf(int m, int i, int j, int k) {
    return (static_cast<std::int64_t>(i) * m + j) * m + k;
}

/// Squared minimum-image offset along one periodic axis of M voxels.
std::int64_t wrappedSquare(int delta, int m) {
    const int d = std::abs(delta) % m;
    const int w = std::min(d, m - d);
    return static_cast<std::int64_t>(w) * w;
}

/// Brute force: squared minimum-image distance from every voxel to the nearest solid voxel.
std::vector<std::uint32_t> bruteForce(const std::vector<std::uint8_t>& mask, int m) {
    std::vector<std::array<int, 3>> solids;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k)
                if (mask[indexOf(m, i, j, k)] != 0) solids.push_back({i, j, k});
    std::vector<std::uint32_t> out(mask.size());
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k) {
                std::int64_t best = std::numeric_limits<std::int64_t>::max();
                for (const auto& s : solids)
                    best = std::min(best, wrappedSquare(i - s[0], m) + wrappedSquare(j - s[1], m) +
                                              wrappedSquare(k - s[2], m));
                out[indexOf(m, i, j, k)] = static_cast<std::uint32_t>(best);
            }
    return out;
}

std::vector<std::uint8_t> randomMask(int m, double solidFraction, std::mt19937_64& generator) {
    std::bernoulli_distribution solid(solidFraction);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    for (auto& v : mask)
        v = solid(generator) ? 1 : 0;
    return mask;
}

std::vector<std::uint32_t> asVector(const PoreSizeMap& map) {
    return {map.squaredDistances().begin(), map.squaredDistances().end()};
}

TEST(DistanceTransform, EqualsBruteForceOnRandomPeriodicGridsOddAndEven) {
    const ThreadBudget budget(2);
    Progress inOrder;
    inOrder.setSerial(true);
    std::mt19937_64 generator(20240611);
    int grids = 0;
    for (const int m : {2, 3, 4, 5, 6, 7, 8, 9, 12, 15, 16})
        for (const double fraction : {0.002, 0.03, 0.3, 0.8}) {
            const std::vector<std::uint8_t> mask = randomMask(m, fraction, generator);
            const auto solids = std::count(mask.begin(), mask.end(), 1);
            if (solids == 0 || solids == static_cast<long>(mask.size())) continue;
            const std::vector<std::uint32_t> expected = bruteForce(mask, m);
            const PoreSizeMap map = periodicDistanceTransform(mask, m, 0.5);
            ASSERT_EQ(asVector(map), expected) << "M = " << m << ", solid fraction " << fraction;
            ASSERT_EQ(asVector(periodicDistanceTransform(mask, m, 0.5, inOrder)), expected);
            EXPECT_EQ(map.voidCount(), static_cast<std::int64_t>(mask.size()) - solids);
            EXPECT_EQ(map.maxSquaredDistance(),
                      *std::max_element(expected.begin(), expected.end()));
            ++grids;
        }
    EXPECT_GE(grids, 35); // the sparse grids of the smallest M may have no solid voxel
}

TEST(DistanceTransform, LongThinPoresAndEmptyColumnsMatchBruteForce) {
    // Few solid voxels: most lines have no site at all, and the periodic images span the box.
    std::mt19937_64 generator(7);
    for (const int m : {10, 11, 17}) {
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m, 0);
        std::uniform_int_distribution<int> index(0, m - 1);
        for (int s = 0; s < 3; ++s)
            mask[indexOf(m, index(generator), index(generator), index(generator))] = 1;
        EXPECT_EQ(asVector(periodicDistanceTransform(mask, m, 1.0)), bruteForce(mask, m));
    }
}

TEST(DistanceTransform, LargerSparseGridsTakeBothLineAlgorithmsExactly) {
    // Lines with values above 32^2 take the parabola envelope, the others the local scan. In a
    // sparse grid of M = 80 or 81 most x columns have no solid (infinite values along y), most
    // z lines have finite values far above 32^2 after the y pass, and the rest are small.
    std::mt19937_64 generator(2024);
    for (const int m : {80, 81}) {
        const std::vector<std::uint8_t> mask = randomMask(m, 0.0004, generator);
        ASSERT_GT(std::count(mask.begin(), mask.end(), 1), 150);
        ASSERT_EQ(asVector(periodicDistanceTransform(mask, m, 1.0)), bruteForce(mask, m))
            << "M = " << m;
    }
}

/// Every feature is a solid voxel at exactly the voxel's transformed (minimum-image) distance, a
/// solid voxel's feature is itself, and the distances are those of the plain transform.
void expectFeaturesConsistent(const std::vector<std::uint8_t>& mask, int m) {
    const PoreSizeMap plain = periodicDistanceTransform(mask, m, 1.0);
    const PoreSizeMap map = periodicFeatureTransform(mask, m, 1.0);
    ASSERT_TRUE(map.hasFeatures());
    EXPECT_FALSE(plain.hasFeatures());
    EXPECT_TRUE(plain.features().empty());
    ASSERT_EQ(asVector(map), asVector(plain)) << "M = " << m;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k) {
                const std::int64_t v = indexOf(m, i, j, k);
                const std::int64_t f = map.features()[v];
                ASSERT_NE(mask[f], 0) << "M = " << m << ": feature of " << v << " is void";
                const int fi = static_cast<int>(f / (std::int64_t{m} * m));
                const int fj = static_cast<int>((f / m) % m), fk = static_cast<int>(f % m);
                ASSERT_EQ(wrappedSquare(i - fi, m) + wrappedSquare(j - fj, m) +
                              wrappedSquare(k - fk, m),
                          map.squaredDistances()[v])
                    << "M = " << m << " at " << i << ' ' << j << ' ' << k;
                if (mask[v] != 0) {
                    ASSERT_EQ(f, v);
                }
            }
}

TEST(FeatureTransform, NearestSolidVoxelOnRandomGridsBothLineAlgorithms) {
    std::mt19937_64 generator(77);
    for (const int m : {2, 7, 16, 17})
        for (const double fraction : {0.02, 0.3, 0.9}) {
            std::vector<std::uint8_t> mask = randomMask(m, fraction, generator);
            mask.front() = 1; // at least one solid and one void voxel
            mask.back() = 0;
            expectFeaturesConsistent(mask, m);
        }
    // Sparse grids: envelope lines (values above 32^2) and columns without solid.
    for (const int m : {80, 81})
        expectFeaturesConsistent(randomMask(m, 0.0004, generator), m);
}

TEST(FeatureTransform, RefusesGridsWhoseIndicesOverflow) {
    const std::vector<std::uint8_t> mask(8, 1);
    try {
        periodicFeatureTransform(mask, maxFeatureTransformVoxels + 1, 1.0);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("feature transform: M = 1626"), std::string::npos)
            << e.what();
    }
}

TEST(DistanceTransform, OneVoidVoxel) {
    for (const int m : {3, 4}) {
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m, 1);
        mask[indexOf(m, 1, 2, 0)] = 0;
        const PoreSizeMap map = periodicDistanceTransform(mask, m, 0.25);
        EXPECT_EQ(map.voidCount(), 1);
        EXPECT_EQ(map.maxSquaredDistance(), 1u);
        for (std::size_t v = 0; v < mask.size(); ++v)
            EXPECT_EQ(map.squaredDistances()[v], mask[v] == 0 ? 1u : 0u);
    }
}

TEST(DistanceTransform, OneSolidVoxelInAVoidBox) {
    for (const int m : {9, 10}) {
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m, 0);
        const std::array<int, 3> s = {2, 7, 4};
        mask[indexOf(m, s[0], s[1], s[2])] = 1;
        const PoreSizeMap map = periodicDistanceTransform(mask, m, 1.0);
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j)
                for (int k = 0; k < m; ++k)
                    ASSERT_EQ(map.squaredDistances()[indexOf(m, i, j, k)],
                              wrappedSquare(i - s[0], m) + wrappedSquare(j - s[1], m) +
                                  wrappedSquare(k - s[2], m))
                        << "M = " << m << " at " << i << ' ' << j << ' ' << k;
        const std::int64_t half = m / 2;
        EXPECT_EQ(map.maxSquaredDistance(), static_cast<std::uint32_t>(3 * half * half));
    }
}

TEST(DistanceTransform, PeriodicWrapAcrossEachFace) {
    // A solid voxel on the face i = 0 (then j = 0, k = 0) is nearest to the void voxel on the
    // opposite face, one voxel away through the boundary, not M - 1 voxels inside the box.
    const int m = 12;
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m, 0);
        std::array<int, 3> solid = {5, 6, 7}, opposite = {5, 6, 7};
        solid[axis] = 0;
        opposite[axis] = m - 1;
        mask[indexOf(m, solid[0], solid[1], solid[2])] = 1;
        // A second solid voxel well inside, so the answer is not the only solid's distance.
        mask[indexOf(m, 6, 6, 6)] = 1;
        const PoreSizeMap map = periodicDistanceTransform(mask, m, 1.0);
        EXPECT_EQ(map.squaredDistances()[indexOf(m, opposite[0], opposite[1], opposite[2])], 1u)
            << "axis " << axis;
        std::array<int, 3> twoAway = solid;
        twoAway[axis] = m - 2;
        EXPECT_EQ(map.squaredDistances()[indexOf(m, twoAway[0], twoAway[1], twoAway[2])], 4u);
    }
}

TEST(DistanceTransform, RejectsNoSolidNoVoidAndBadArguments) {
    const int m = 6;
    const std::vector<std::uint8_t> voidOnly(m * m * m, 0), solidOnly(m * m * m, 1);
    EXPECT_THROW(periodicDistanceTransform(voidOnly, m, 1.0), std::domain_error);
    EXPECT_THROW(periodicDistanceTransform(solidOnly, m, 1.0), std::domain_error);
    std::vector<std::uint8_t> mask(m * m * m, 0);
    mask[3] = 1;
    EXPECT_THROW(periodicDistanceTransform(mask, m + 1, 1.0), std::invalid_argument);
    EXPECT_THROW(periodicDistanceTransform(mask, m, 0.0), std::invalid_argument);
    EXPECT_THROW(periodicDistanceTransform(mask, m, std::nan("")), std::invalid_argument);
    EXPECT_THROW(periodicDistanceTransform({}, 0, 1.0), std::invalid_argument);
}

TEST(DistanceTransform, RefusesTooLargeGridWithTheEstimate) {
    EXPECT_EQ(poreSizeMemoryBytes(500), 625'000'000u);
    EXPECT_THROW(checkPoreSizeMemory(0), std::invalid_argument);
    EXPECT_THROW(checkPoreSizeMemory(maxPoreSizeVoxels + 1), std::invalid_argument);
    EXPECT_NO_THROW(checkPoreSizeMemory(64));
    try {
        checkPoreSizeMemory(16000); // 2.0e13 bytes
        FAIL() << "M = 16000 should not fit in memory";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("about 20480.0 GB"), std::string::npos) << e.what();
    }
}

TEST(DistanceTransform, WritesAnOpenVdbFileAtomically) {
    const int m = 10;
    std::vector<std::uint8_t> mask(m * m * m, 0);
    mask[indexOf(m, 1, 2, 3)] = 1;
    const PoreSizeMap map = periodicDistanceTransform(mask, m, 0.3);
    const auto dir = std::filesystem::temp_directory_path() / "sbpack_test_pores";
    std::filesystem::create_directories(dir);
    const auto file = dir / "pores.vdb";
    std::filesystem::remove(file);
    map.writeVdb(file);
    std::ifstream in(file, std::ios::binary);
    std::int32_t magic = 0;
    in.read(reinterpret_cast<char*>(&magic), sizeof(magic));
    EXPECT_EQ(magic, 0x56444220); // OpenVDB's file magic number
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos);
    EXPECT_THROW(map.writeVdb(dir / "missing" / "pores.vdb"), OutputPathError);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace sbpack

// Cell list, contact network and rattler removal (paper Sec. III A; docs/design.md §2, §3).

#include "contacts/cell_list.hpp"
#include "contacts/contact_network.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace sbpack {
namespace {

using PairSet = std::set<std::pair<int, int>>;

PairSet bruteForcePairs(const std::vector<Vector3d>& positions, double boxLength, double range) {
    PairSet pairs;
    const int n = static_cast<int>(positions.size());
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (minimumImage(positions[j] - positions[i], boxLength).squaredNorm() < range * range)
                pairs.emplace(i, j);
    return pairs;
}

/// Pairs from the cell list; fails the test on a repeated pair, i >= j or a wrong displacement.
PairSet cellListPairs(const std::vector<Vector3d>& positions, double boxLength, double range) {
    PairSet pairs;
    forEachNeighbourPair(positions, boxLength, range, [&](int i, int j, const Vector3d& d) {
        EXPECT_LT(i, j);
        EXPECT_TRUE(pairs.emplace(i, j).second) << "pair (" << i << ", " << j << ") visited twice";
        EXPECT_EQ(d, minimumImage(positions[j] - positions[i], boxLength));
    });
    return pairs;
}

std::vector<Vector3d> randomPoints(int count, double boxLength, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, boxLength);
    std::vector<Vector3d> points(count);
    for (auto& r : points)
        r = Vector3d(uniform(rng), uniform(rng), uniform(rng));
    return points;
}

TEST(CellList, MatchesBruteForceForSeveralBoxSizes) {
    const double range = 1.0;
    // L / range from the smallest allowed box (2, a single cell) through 3 (still one cell: the
    // margin keeps the cell edge above range) to many cells.
    for (const double boxLength : {2.0, 2.5, 3.0, 3.2, 4.0, 7.3, 12.0}) {
        const int count = static_cast<int>(4.0 * boxLength * boxLength * boxLength);
        const auto points = randomPoints(count, boxLength, 12345);
        const PairSet expected = bruteForcePairs(points, boxLength, range);
        EXPECT_EQ(cellListPairs(points, boxLength, range), expected) << "L = " << boxLength;
        EXPECT_FALSE(expected.empty());
    }
    EXPECT_EQ(CellList(randomPoints(10, 2.5, 1), 2.5, 1.0).cellsPerSide(), 1);
    EXPECT_EQ(CellList(randomPoints(1000, 7.3, 1), 7.3, 1.0).cellsPerSide(), 7);
}

TEST(CellList, PositionsOutsideTheBoxAreWrappedForBinning) {
    const double boxLength = 6.0;
    auto points = randomPoints(500, boxLength, 777);
    for (std::size_t i = 0; i < points.size(); i += 3)
        points[i].x() -= boxLength;
    for (std::size_t i = 1; i < points.size(); i += 3)
        points[i].z() += 2.0 * boxLength;
    EXPECT_EQ(cellListPairs(points, boxLength, 1.0), bruteForcePairs(points, boxLength, 1.0));
}

TEST(CellList, RangeExactlyAcrossThePeriodicBoundary) {
    // Dyadic lattice: many separations equal the range exactly, across the boundary too; the
    // criterion is strict (|d| < range) and particles sit on cell boundaries.
    const double boxLength = 4.0;
    const double range = 0.5;
    std::vector<Vector3d> points;
    for (int x = 0; x < 16; ++x)
        for (int y = 0; y < 16; y += 5)
            for (int z = 0; z < 16; z += 7)
                points.emplace_back(0.25 * x, 0.25 * y, 0.25 * z);
    // One ulp inside the range across the boundary: 3.75 + ulp is 0.5 - ulp from 0.25.
    points.emplace_back(std::nextafter(3.75, 4.0), 1.1, 1.1);
    points.emplace_back(0.25, 1.1, 1.1);
    const PairSet expected = bruteForcePairs(points, boxLength, range);
    EXPECT_EQ(cellListPairs(points, boxLength, range), expected);
    const int last = static_cast<int>(points.size()) - 1;
    EXPECT_TRUE(expected.count({last - 1, last}));
    // Exactly at range across the boundary: (0, 0, 0) and (3.5, 0, 0) are 0.5 apart.
    EXPECT_FALSE(expected.count({0, 14 * 4 * 3}));
    // Range of exactly half the box is still unambiguous.
    EXPECT_EQ(cellListPairs(points, boxLength, 2.0), bruteForcePairs(points, boxLength, 2.0));
}

TEST(CellList, RejectsInvalidInput) {
    const auto points = randomPoints(10, 4.0, 3);
    EXPECT_THROW(CellList(points, 4.0, 2.0 + 1e-12), std::invalid_argument);
    EXPECT_THROW(CellList(points, 4.0, 0.0), std::invalid_argument);
    EXPECT_THROW(CellList(points, -4.0, 1.0), std::invalid_argument);
    EXPECT_THROW(CellList(points, 4.0, std::numeric_limits<double>::quiet_NaN()),
                 std::invalid_argument);
    auto bad = points;
    bad[3].y() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(CellList(bad, 4.0, 1.0), std::invalid_argument);
}

/// Lattice packing: basis points (in units of the lattice constant) repeated cells^3 times.
Packing latticePacking(double p, double semiAxis, double latticeConstant, int cells,
                       const std::vector<Vector3d>& basis) {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    packing.semiAxis = semiAxis;
    packing.boxLength = cells * latticeConstant;
    for (int x = 0; x < cells; ++x)
        for (int y = 0; y < cells; ++y)
            for (int z = 0; z < cells; ++z)
                for (const Vector3d& b : basis) {
                    packing.positions.push_back(latticeConstant * (Vector3d(x, y, z) + b));
                    packing.orientations.push_back(Quaterniond::Identity());
                }
    return packing;
}

Packing simpleCubic(double p, double semiAxis, double latticeConstant, int cells) {
    return latticePacking(p, semiAxis, latticeConstant, cells, {Vector3d::Zero()});
}

void expectEveryCount(const ContactResult& result, int count) {
    for (std::size_t i = 0; i < result.counts.size(); ++i)
        ASSERT_EQ(result.counts[i], count) << "particle " << i;
}

TEST(ContactNetwork, SimpleCubicTouchingSpheresHaveSixContacts) {
    for (const int cells : {4, 5}) {
        const Packing packing = simpleCubic(1.0, 0.5, 1.0, cells);
        const ContactResult result = ContactNetwork({}).compute(packing);
        const int n = cells * cells * cells;
        EXPECT_EQ(result.contacts.size(), 3u * n);
        expectEveryCount(result, 6);
        EXPECT_EQ(result.meanContactNumber, 6.0);
        EXPECT_EQ(result.rattlerFraction, 0.0);
        EXPECT_EQ(std::count(result.rattler.begin(), result.rattler.end(), true), 0);
        EXPECT_EQ(result.overlappingPairs, 0);
        EXPECT_NEAR(result.worstGap, 0.0, 1e-14);
        EXPECT_TRUE(std::is_sorted(result.contacts.begin(), result.contacts.end()));
    }
}

TEST(ContactNetwork, ContactCriterionResolvesGapsOfTheTolerance) {
    // Lattice constant 2R (1 + 2e-10): every gap is 2e-10 D (paper Sec. III A criterion 1e-10 D).
    const double semiAxis = 0.5;
    const Packing packing = simpleCubic(1.0, semiAxis, 2.0 * semiAxis * (1.0 + 2e-10), 5);

    const ContactResult strict = ContactNetwork({.tolerance = 1e-10}).compute(packing);
    EXPECT_TRUE(strict.contacts.empty());
    expectEveryCount(strict, 0);
    EXPECT_EQ(strict.rattlerFraction, 1.0);
    EXPECT_EQ(strict.meanContactNumber, 0.0);
    // No pair lies within the contact range 2 circumradius + tolerance D.
    EXPECT_EQ(strict.worstGap, std::numeric_limits<double>::infinity());
    EXPECT_EQ(strict.worstPairA, -1);
    EXPECT_EQ(strict.worstPairB, -1);

    const ContactResult loose = ContactNetwork({.tolerance = 1e-9}).compute(packing);
    EXPECT_EQ(loose.meanContactNumber, 6.0);
    EXPECT_EQ(loose.rattlerFraction, 0.0);
    EXPECT_NEAR(loose.worstGap, 2e-10 * 2.0 * semiAxis, 1e-14);
    EXPECT_EQ(loose.parameters.tolerance, 1e-9);
}

TEST(ContactNetwork, FaceCentredCubicTouchingSpheresHaveTwelveContacts) {
    // Nearest neighbours a / sqrt(2) = 2R.
    const double semiAxis = 0.5;
    const std::vector<Vector3d> basis = {
        {0.0, 0.0, 0.0}, {0.5, 0.5, 0.0}, {0.5, 0.0, 0.5}, {0.0, 0.5, 0.5}};
    const Packing packing =
        latticePacking(1.0, semiAxis, 2.0 * std::sqrt(2.0) * semiAxis, 4, basis);
    const ContactResult result = ContactNetwork({}).compute(packing);
    expectEveryCount(result, 12);
    EXPECT_EQ(result.meanContactNumber, 12.0);
    EXPECT_EQ(result.rattlerFraction, 0.0);
}

TEST(ContactNetwork, ContactPointsLieHalfwayFromTheFirstSphere) {
    const std::vector<Vector3d> basis = {
        {0.0, 0.0, 0.0}, {0.5, 0.5, 0.0}, {0.5, 0.0, 0.5}, {0.0, 0.5, 0.5}};
    const Packing packing = latticePacking(1.0, 0.5, std::sqrt(2.0), 3, basis);
    const ContactResult result = ContactNetwork({}).compute(packing);
    ASSERT_EQ(result.points.size(), result.contacts.size());
    for (std::size_t c = 0; c < result.contacts.size(); ++c) {
        const auto [i, j] = result.contacts[c];
        const Vector3d d =
            minimumImage(packing.positions[j] - packing.positions[i], 3.0 * std::sqrt(2.0));
        EXPECT_LT((result.points[c] - 0.5 * d).norm(), 1e-14) << "contact " << c;
    }
}

TEST(ContactNetwork, AlignedSuperballsTouchingFaceToFaceHaveSixContacts) {
    // p = 1.5: circumradius 3^(1/6) R reaches beyond the face neighbours but not the diagonal ones.
    const Packing packing = simpleCubic(1.5, 0.5, 1.0, 4);
    const ContactResult result = ContactNetwork({}).compute(packing);
    expectEveryCount(result, 6);
    EXPECT_EQ(result.meanContactNumber, 6.0);
    EXPECT_EQ(result.rattlerFraction, 0.0);
    EXPECT_EQ(result.overlappingPairs, 0);
}

TEST(ContactNetwork, RattlerThresholdIsAParameter) {
    const Packing packing = simpleCubic(1.0, 0.5, 1.0, 4);
    const ContactResult result = ContactNetwork({.rattlerThreshold = 7}).compute(packing);
    expectEveryCount(result, 6);
    EXPECT_EQ(result.rattlerFraction, 1.0);
    EXPECT_EQ(result.meanContactNumber, 0.0);
    EXPECT_EQ(ContactNetwork({.rattlerThreshold = 6}).compute(packing).rattlerFraction, 0.0);
}

TEST(ContactNetwork, RattlerRemovalIsIterated) {
    // A square ring of four touching spheres with a tail of three from one corner, threshold 2:
    // counts ring (3, 2, 2, 2), tail (2, 2, 1). Only the tail end has fewer than 2 contacts, but
    // removing it exposes the next: the whole tail goes, the ring stays with 2 contacts each.
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.0);
    packing.semiAxis = 0.5;
    packing.boxLength = 20.0;
    const Vector3d origin(10.0, 10.0, 10.0);
    const Vector3d outward = -Vector3d(1.0, 1.0, 0.0).normalized();
    packing.positions = {origin,
                         origin + Vector3d(1.0, 0.0, 0.0),
                         origin + Vector3d(1.0, 1.0, 0.0),
                         origin + Vector3d(0.0, 1.0, 0.0),
                         origin + outward,
                         origin + 2.0 * outward,
                         origin + 3.0 * outward};
    packing.orientations.assign(packing.positions.size(), Quaterniond::Identity());

    const ContactResult result = ContactNetwork({.rattlerThreshold = 2}).compute(packing);
    EXPECT_EQ(result.counts, (std::vector<int>{3, 2, 2, 2, 2, 2, 1}));
    EXPECT_EQ(result.rattler, (std::vector<bool>{false, false, false, false, true, true, true}));
    EXPECT_EQ(result.rattlerFraction, 3.0 / 7.0);
    EXPECT_EQ(result.meanContactNumber, 2.0);
    const std::vector<std::pair<int, int>> expected = {{0, 1}, {0, 3}, {0, 4}, {1, 2},
                                                       {2, 3}, {4, 5}, {5, 6}};
    EXPECT_EQ(result.contacts, expected);

    // Default threshold 4: nobody has four contacts, everything is a rattler.
    EXPECT_EQ(ContactNetwork({}).compute(packing).rattlerFraction, 1.0);
}

TEST(ContactNetwork, WorstGapFindsAPlantedOverlap) {
    for (const double p : {1.0, 1.5}) {
        const double semiAxis = 0.5;
        const double diameter = 2.0 * semiAxis;
        Packing packing = simpleCubic(p, semiAxis, diameter, 4);
        // Particle (1, 1, 1) moves by 1e-3 D towards (0, 1, 1): depth exactly 1e-3 D, since along
        // the body axis x both n . d is largest and h(n) = R smallest.
        const int moved = (1 * 4 + 1) * 4 + 1;
        const int neighbour = (0 * 4 + 1) * 4 + 1;
        packing.positions[moved].x() -= 1e-3 * diameter;
        const ContactResult result = ContactNetwork({}).compute(packing);
        EXPECT_NEAR(result.worstGap, -1e-3 * diameter, 1e-12) << "p = " << p;
        EXPECT_EQ(result.worstPairA, neighbour);
        EXPECT_EQ(result.worstPairB, moved);
        EXPECT_EQ(result.overlappingPairs, 1);
        // The moved particle loses its contacts in +x, y and z; the overlap still counts.
        EXPECT_EQ(result.counts[moved], 1);
        // Spheres have a closed form; a superball needs Newton iterations.
        if (p != 1.0) {
            EXPECT_GT(result.pairIterations, 0);
        }
    }
}

TEST(ContactNetwork, RejectsInvalidParametersAndPackings) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(ContactNetwork({.tolerance = -1e-10}), std::invalid_argument);
    EXPECT_THROW(ContactNetwork({.tolerance = nan}), std::invalid_argument);
    EXPECT_THROW(ContactNetwork({.tolerance = inf}), std::invalid_argument);
    EXPECT_THROW(ContactNetwork({.rattlerThreshold = 0}), std::invalid_argument);
    EXPECT_NO_THROW(ContactNetwork({.tolerance = 0.0, .rattlerThreshold = 1}));

    Packing packing = simpleCubic(1.0, 0.5, 1.0, 3);
    packing.orientations.pop_back();
    EXPECT_THROW(ContactNetwork({}).compute(packing), std::invalid_argument);
    // Box of two diameters: the contact range exceeds L / 2.
    EXPECT_THROW(ContactNetwork({}).compute(simpleCubic(1.0, 0.5, 1.0, 2)), std::invalid_argument);
}

} // namespace
} // namespace sbpack

// Set-Voronoi cells (analysis/voronoi, docs/local-structure.md §1): the lattices' analytic cells,
// the tiling of the box, and for equal spheres the ordinary Voronoi cells of the centres counted
// by brute force on the same grid, and for spheres of two sizes the additively weighted cells.
#include "voronoi/set_voronoi.hpp"

#include "../common/order_lattices.hpp"
#include "pores/distance_transform.hpp"
#include "test_packings.hpp"
#include "voxels/voxelization.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace sbpack {
namespace {

const Progress quiet;

/// Largest |phi_i - phi| over the cells.
double largestError(const SetVoronoiResult& r, double phi) {
    double worst = 0.0;
    for (double v : r.localPhi)
        worst = std::max(worst, std::abs(v - phi));
    return worst;
}

/// The lattice's cells are its Wigner-Seitz cells (mirror planes halfway between neighbours, for
/// spheres and for aligned superballs alike): every local phi is the lattice's phi, to a voxel
/// error that falls at least by 0.6 when M doubles (measured 0.05 to 0.41). M is not a multiple of
/// the cells along the box (on such a grid every particle is voxelised alike and the cells are
/// exact).
void expectLatticeCells(const Packing& lattice, double phi, int m) {
    const SetVoronoiResult coarse = SetVoronoi(m).compute(lattice, {}, quiet);
    const SetVoronoiResult fine = SetVoronoi(2 * m).compute(lattice, {}, quiet);
    // About 12 voxels per lattice spacing on the coarse grid: a cell face is placed to a voxel,
    // some 8 % of a cell (measured 3.5 to 11 %); their mean to 0.3 %.
    EXPECT_NEAR(coarse.all.mean, phi, 3e-3 * phi);
    EXPECT_LT(largestError(coarse, phi), 0.12 * phi);
    EXPECT_LT(largestError(fine, phi), 0.6 * largestError(coarse, phi))
        << "M = " << m << ": " << largestError(coarse, phi);
    EXPECT_LT(std::abs(fine.tilingError), 1e-12); // the cells tile the box
    EXPECT_NEAR(fine.all.harmonicMean, lattice.packingFraction(), 1e-12);
}

TEST(SetVoronoi, SimpleCubicSpheresHaveCubicCellsOfPhiPiOverSix) {
    expectLatticeCells(lattices::cubicCrystal(4, 1.0, lattices::kSimpleCubic),
                       std::numbers::pi / 6.0, 49);
}

TEST(SetVoronoi, FaceCentredSpheresHaveRhombicDodecahedraOfPhiPiOverThreeRootTwo) {
    expectLatticeCells(lattices::cubicCrystal(2, std::sqrt(2.0), lattices::kFaceCentred),
                       std::numbers::pi / (3.0 * std::sqrt(2.0)), 41);
}

TEST(SetVoronoi, AlignedSuperballsOnASimpleCubicLatticeHaveCubicCells) {
    const Packing lattice = testing::latticePacking(3.0, 3, 1.05, 0.0, 1, true, 0.13);
    expectLatticeCells(lattice, lattice.shape().volume() / std::pow(1.05, 3), 37);
}

/// For spheres the set-Voronoi cell is the additively weighted Voronoi cell, the points nearer
/// to the sphere's surface than to any other's, |x - r_n| - R_n: for equal spheres the Voronoi
/// cell of the centre. The voxels of each (brute force, minimum image) on the same grid.
std::vector<double> sphereVoronoiVolumes(const Packing& packing, int m) {
    const double a = packing.boxLength / m;
    std::vector<double> volumes(packing.size(), 0.0);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k) {
                const Vector3d x((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a);
                std::size_t nearest = 0;
                double best = 1e300;
                for (std::size_t n = 0; n < packing.size(); ++n) {
                    const double d =
                        minimumImage(x - packing.positions[n], packing.boxLength).norm() -
                        packing.semiAxisOf(n);
                    if (d < best) best = d, nearest = n;
                }
                volumes[nearest] += a * a * a;
            }
    return volumes;
}

/// The cells of `spheres` converge to sphereVoronoiVolumes as M doubles.
void expectSphereVoronoiCells(const Packing& rsa) {
    double previous = 1e300;
    for (int m : {24, 48}) {
        const SetVoronoiResult cells = SetVoronoi(m).compute(rsa, {}, quiet);
        const std::vector<double> voronoi = sphereVoronoiVolumes(rsa, m);
        double squares = 0.0;
        for (std::size_t n = 0; n < rsa.size(); ++n)
            squares += std::pow(cells.cellVolumes[n] / voronoi[n] - 1.0, 2);
        const double rms = std::sqrt(squares / rsa.size());
        EXPECT_LT(rms, 0.05) << "M = " << m;
        EXPECT_LT(rms, 0.7 * previous) << "M = " << m;
        previous = rms;
    }
}

TEST(SetVoronoi, EqualSpheresHaveTheVoronoiCellsOfTheirCentres) {
    expectSphereVoronoiCells(testing::randomSequentialAddition(40, 0.3, 7));
}

// docs/mixtures.md: spheres of two sizes (every third of diameter 0.72) have the additively
// weighted cells, the cells tile the box, and phi_i is each particle's own volume over its cell.
TEST(SetVoronoi, SpheresOfTwoSizesHaveTheirAdditivelyWeightedCells) {
    Packing rsa = testing::randomSequentialAddition(40, 0.3, 7);
    for (std::size_t n = 0; n < rsa.size(); ++n)
        rsa.semiAxes.push_back(n % 3 == 0 ? 0.36 : 0.5);
    expectSphereVoronoiCells(rsa);
    const SetVoronoiResult r = SetVoronoi(48).compute(rsa, {}, quiet);
    EXPECT_LT(std::abs(r.tilingError), 1e-12);
    for (std::size_t n = 0; n < rsa.size(); ++n)
        EXPECT_NEAR(r.localPhi[n] * r.cellVolumes[n],
                    4.0 / 3.0 * std::numbers::pi * std::pow(rsa.semiAxisOf(n), 3), 1e-12)
            << n;
}

TEST(SetVoronoi, RattlersSplitTheMomentsAndTheHarmonicMeanIsPhi) {
    const Packing rsa = testing::randomSequentialAddition(60, 0.35, 3);
    std::vector<bool> rattler(rsa.size(), false);
    for (std::size_t n = 0; n < rsa.size(); n += 3)
        rattler[n] = true;
    const SetVoronoiResult r = SetVoronoi(48).compute(rsa, rattler, quiet);
    ASSERT_TRUE(r.nonRattlers && r.rattlers);
    EXPECT_EQ(r.nonRattlers->count, 40);
    EXPECT_EQ(r.rattlers->count, 20);
    EXPECT_NEAR(r.all.mean, (40 * r.nonRattlers->mean + 20 * r.rattlers->mean) / 60, 1e-12);
    EXPECT_NEAR(r.all.harmonicMean, rsa.packingFraction(), 1e-12);
    double density = 0.0;
    for (double d : r.histogramDensity)
        density += d / SetVoronoi::kHistogramBins;
    EXPECT_NEAR(density, 1.0, 1e-12);
}

TEST(SetVoronoi, RefusesAGridBeyondTheFeatureTransformAndMismatchedRattlers) {
    EXPECT_THROW(SetVoronoi(maxFeatureTransformVoxels + 1), VoxelResolutionError);
    const Packing rsa = testing::randomSequentialAddition(10, 0.2, 3);
    EXPECT_THROW(SetVoronoi(24).compute(rsa, std::vector<bool>(3), quiet), std::invalid_argument);
}

} // namespace
} // namespace sbpack

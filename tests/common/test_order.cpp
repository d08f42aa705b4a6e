// The order metrics of common/order/ against lattice and ideal-gas truths
// (docs/order-metrics.md).

#include "order/bond_orientational_order.hpp"
#include "order/cubatic_order.hpp"
#include "order/neighbour_bonds.hpp"
#include "order/order_metrics.hpp"
#include "order/pair_correlation.hpp"
#include "order/solid_like.hpp"
#include "order/translational_order.hpp"

#include "contacts/contact_network.hpp"
#include "order_lattices.hpp"
#include "random/random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace sbpack {
namespace {

using namespace lattices;

/// N uniformly random points in a box of edge L (ideal gas).
Packing idealGas(int count, double boxLength, std::uint64_t seed) {
    Random random(seed);
    std::vector<Vector3d> positions(count);
    for (Vector3d& r : positions)
        r = boxLength * Vector3d(random.uniform(), random.uniform(), random.uniform());
    return pointPacking(positions, boxLength);
}

/// P_l(x), x clamped to [-1, 1] against round-off.
double legendre(int degree, double x) {
    return std::legendre(degree, std::clamp(x, -1.0, 1.0));
}

/// Q_l^2 from the addition theorem: sum_{a,b} P_l(u_a . u_b) / n^2 over bond vectors u.
double additionTheoremSquare(const std::vector<Vector3d>& bonds, int degree) {
    double sum = 0.0;
    for (const Vector3d& a : bonds)
        for (const Vector3d& b : bonds)
            sum += legendre(degree, a.normalized().dot(b.normalized()));
    return sum / std::pow(static_cast<double>(bonds.size()), 2);
}

/// The bond vectors of each particle, seen from it.
std::vector<std::vector<Vector3d>> bondsByParticle(const NeighbourBonds& bonds) {
    std::vector<std::vector<Vector3d>> byParticle(bonds.particleCount);
    for (const Bond& bond : bonds.bonds) {
        byParticle[bond.i].push_back(bond.vector);
        byParticle[bond.j].push_back(-bond.vector);
    }
    return byParticle;
}

// --- Steinhardt Q_l (docs/order-metrics.md §2) ---

struct LatticeCase {
    const char* name;
    const std::vector<Vector3d>* basis;
    double cutoff; ///< between the first and second shells, lattice constant 1
    int coordination;
    double q4; ///< Steinhardt, Nelson & Ronchetti 1983; closed forms in the comments
    double q6;
};

TEST(OrderSteinhardt, LatticesGiveTheirClosedForms) {
    const LatticeCase cases[] = {
        {"sc", &kSimpleCubic, 1.2, 6, 0.76376, 0.35355},   // sqrt(7/12), sqrt(1/8)
        {"bcc", &kBodyCentred, 0.93, 8, 0.50918, 0.62854}, // sqrt(7/27), sqrt(32/81)
        {"fcc", &kFaceCentred, 0.85, 12, 0.19094, 0.57452} // sqrt(7/192), 13 / sqrt(512)
    };
    for (const LatticeCase& lattice : cases) {
        SCOPED_TRACE(lattice.name);
        const Packing crystal = cubicCrystal(4, 1.0, *lattice.basis);
        const NeighbourBonds bonds = distanceBonds(crystal, lattice.cutoff);
        ASSERT_EQ(bonds.bonds.size(), crystal.size() * lattice.coordination / 2);
        const std::vector<Vector3d> shell = bondsByParticle(bonds)[0];
        for (int degree : {4, 6}) {
            const SteinhardtOrder order = steinhardtOrder(bonds, degree);
            const double closedForm = std::sqrt(additionTheoremSquare(shell, degree));
            EXPECT_NEAR(order.globalOrder, closedForm, 1e-12);
            EXPECT_NEAR(order.globalOrder, degree == 4 ? lattice.q4 : lattice.q6, 5e-6);
            EXPECT_NEAR(order.meanLocalOrder, closedForm, 1e-12);
            EXPECT_EQ(order.bondedParticles, crystal.size());
            for (std::size_t i = 0; i < crystal.size(); ++i) {
                EXPECT_EQ(order.neighbourCount[i], lattice.coordination);
                EXPECT_NEAR(order.localOrder[i], closedForm, 1e-12);
            }
        }
    }
}

/// A random network: 90 bonds of random direction and length among particles 0..39, and
/// particle 40 without a bond.
NeighbourBonds randomBonds(std::uint64_t seed) {
    Random random(seed);
    NeighbourBonds bonds{41, {}};
    while (bonds.bonds.size() < 90) {
        const auto i = static_cast<int>(random.uniform() * 40);
        const auto j = static_cast<int>(random.uniform() * 40);
        if (i < j) bonds.bonds.push_back({i, j, (0.5 + random.uniform()) * random.normalVector()});
    }
    return bonds;
}

TEST(OrderSteinhardt, HarmonicsObeyTheAdditionTheorem) {
    // sum_m |sum_a Y_lm(u_a)|^2 = (2l + 1) / (4 pi) sum_{a,b} P_l(u_a . u_b), odd l included
    // (Q_l = 0 there: each bond is seen from both ends), compared squared (the root of a
    // round-off near 0 is not); particle 40 has no bond: q_l = NaN, left out of the mean.
    const NeighbourBonds bonds = randomBonds(7);
    const auto byParticle = bondsByParticle(bonds);
    std::vector<Vector3d> all;
    for (const auto& own : byParticle)
        all.insert(all.end(), own.begin(), own.end());
    for (int degree = 0; degree <= 8; ++degree) {
        SCOPED_TRACE(degree);
        const SteinhardtOrder order = steinhardtOrder(bonds, degree);
        EXPECT_NEAR(std::pow(order.globalOrder, 2), additionTheoremSquare(all, degree), 1e-12);
        EXPECT_TRUE(std::isnan(order.localOrder[40]));
        double sum = 0.0;
        for (std::size_t i = 0; i < 40; ++i) {
            if (byParticle[i].empty()) continue;
            EXPECT_NEAR(std::pow(order.localOrder[i], 2),
                        additionTheoremSquare(byParticle[i], degree), 1e-12);
            sum += order.localOrder[i];
        }
        EXPECT_NEAR(order.meanLocalOrder, sum / static_cast<double>(order.bondedParticles), 1e-14);
    }
}

TEST(OrderSteinhardt, RotatingTheBondsChangesNothing) {
    Random random(11);
    const Eigen::Matrix3d rotation = random.rotation().toRotationMatrix();
    const NeighbourBonds fcc = distanceBonds(cubicCrystal(3, 1.0, kFaceCentred), 0.85);
    for (const NeighbourBonds& bonds : {randomBonds(5), fcc}) {
        NeighbourBonds rotated = bonds;
        for (Bond& bond : rotated.bonds)
            bond.vector = rotation * bond.vector;
        for (int degree : {4, 6}) {
            const SteinhardtOrder before = steinhardtOrder(bonds, degree);
            const SteinhardtOrder after = steinhardtOrder(rotated, degree);
            EXPECT_NEAR(after.globalOrder, before.globalOrder, 1e-12);
            EXPECT_NEAR(after.meanLocalOrder, before.meanLocalOrder, 1e-12);
            for (std::size_t i = 0; i < bonds.particleCount; ++i) {
                if (before.neighbourCount[i] > 0) {
                    EXPECT_NEAR(after.localOrder[i], before.localOrder[i], 1e-12);
                }
            }
        }
    }
    EXPECT_NEAR(steinhardtOrder(fcc, 6).globalOrder, 0.57452, 5e-6);
}

TEST(OrderSteinhardt, ContactNetworkOfTouchingFccSpheresGivesTheFccValues) {
    // Lattice constant sqrt 2: nearest neighbours at 1, spheres of diameter 1 touch.
    const Packing crystal = cubicCrystal(3, std::numbers::sqrt2, kFaceCentred);
    const ContactResult contacts = ContactNetwork(ContactParameters{}).compute(crystal);
    const NeighbourBonds bonds = contactBonds(crystal, contacts.contacts);
    ASSERT_EQ(bonds.bonds.size(), crystal.size() * 6);
    EXPECT_NEAR(steinhardtOrder(bonds, 6).globalOrder, 0.57452, 5e-6);
    EXPECT_NEAR(steinhardtOrder(bonds, 4).meanLocalOrder, 0.19094, 5e-6);
    const NeighbourBonds byDistance = distanceBonds(crystal, 1.2);
    EXPECT_NEAR(steinhardtOrder(byDistance, 6).globalOrder, steinhardtOrder(bonds, 6).globalOrder,
                1e-12);
}

TEST(OrderSteinhardt, RefusesWhatHasNoOrder) {
    const Packing crystal = cubicCrystal(2, 1.0, kSimpleCubic);
    const NeighbourBonds bonds = distanceBonds(crystal, 0.9); // L / 2 = 1
    EXPECT_THROW(steinhardtOrder(bonds, -1), std::invalid_argument);
    EXPECT_THROW(steinhardtOrder(NeighbourBonds{8, {}}, 6), std::invalid_argument);
    EXPECT_THROW(steinhardtOrder(NeighbourBonds{8, {{0, 1, Vector3d::Zero()}}}, 6),
                 std::invalid_argument);
    EXPECT_THROW(steinhardtOrder(NeighbourBonds{2, {{0, 2, Vector3d::UnitX()}}}, 6),
                 std::invalid_argument);
    EXPECT_THROW(contactBonds(crystal, {{0, 8}}), std::invalid_argument);
    EXPECT_THROW(contactBonds(crystal, {{3, 3}}), std::invalid_argument);
    EXPECT_THROW(distanceBonds(crystal, 1.1), std::invalid_argument);
    EXPECT_THROW(distanceBonds(crystal, 0.0), std::invalid_argument);
}

// Issue 65 item 5: two identical particles (a valid, overlapping input) share a centre; their
// pair has no bond direction and is left out of every bond set, counted, and the order metrics
// of the rest are those of the crystal without the copy.
TEST(OrderSteinhardt, CoincidentCentresAreLeftOutAndCounted) {
    const Packing crystal = cubicCrystal(3, 1.0, kSimpleCubic);
    Packing doubled = crystal;
    doubled.positions.push_back(crystal.positions[4]);
    doubled.orientations.push_back(crystal.orientations[4]);
    const int copy = static_cast<int>(crystal.size());
    const NeighbourBonds byDistance = distanceBonds(doubled, 1.2);
    EXPECT_EQ(byDistance.coincident, 1u);
    const NeighbourBonds lattice = distanceBonds(crystal, 1.2);
    EXPECT_EQ(byDistance.bonds.size(), lattice.bonds.size() + 6); // the copy's six neighbours
    const NeighbourBonds byContact = contactBonds(doubled, {{4, copy}, {0, 1}});
    EXPECT_EQ(byContact.coincident, 1u);
    ASSERT_EQ(byContact.bonds.size(), 1u);
    EXPECT_EQ(byContact.bonds[0].j, 1);
    // the original and its copy each have the six lattice directions: the lattice's local q6
    const SteinhardtOrder q6 = steinhardtOrder(byDistance, 6);
    const double simpleCubic = steinhardtOrder(lattice, 6).localOrder[4];
    EXPECT_NEAR(simpleCubic, 0.35355339059327379, 1e-12); // sqrt(1/8), the sc value
    EXPECT_NEAR(q6.localOrder[4], simpleCubic, 1e-12);
    EXPECT_NEAR(q6.localOrder[copy], simpleCubic, 1e-12);
    EXPECT_NO_THROW(measureOrder(doubled));
}

// --- SANN neighbours and solid-like particles (docs/order-metrics.md §2 and §5) ---

/// Every particle solid-like, all in one cluster.
void expectAllSolidLike(const SolidLikeResult& result, std::size_t particles) {
    EXPECT_EQ(result.solidCount, particles);
    EXPECT_EQ(result.largestClusterSize, particles);
    EXPECT_DOUBLE_EQ(result.solidFraction, 1.0);
    EXPECT_DOUBLE_EQ(result.largestClusterFraction, 1.0);
}

TEST(OrderSann, LatticesGiveTheirFullShells) {
    // van Meel et al. 2012: sc 6 + 12 (R(18) = 1.44 a < sqrt 3 a), bcc 8 + 6, fcc and hcp 12; on
    // a Bravais lattice every particle sees the same shell, so d_l = 1 on every bond.
    struct Case {
        const char* name;
        Packing crystal;
        int shell;
        bool bravais;
    };
    const Case cases[] = {{"sc", cubicCrystal(5, 1.0, kSimpleCubic), 18, true},
                          {"bcc", cubicCrystal(4, 1.0, kBodyCentred), 14, true},
                          {"fcc", cubicCrystal(4, 1.0, kFaceCentred), 12, true},
                          {"hcp", hcpCrystal(1.0), 12, false}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const NeighbourBonds bonds = sannBonds(c.crystal);
        EXPECT_EQ(bonds.bonds.size(), c.crystal.size() * c.shell / 2);
        const SolidLikeResult result = SolidLikeParticles().compute(bonds);
        for (std::size_t i = 0; i < c.crystal.size(); ++i)
            EXPECT_EQ(result.neighbourCount[i], c.shell);
        for (double d : result.bondCorrelation)
            EXPECT_GT(d, c.bravais ? 1.0 - 1e-12 : 0.7);
        expectAllSolidLike(result, c.crystal.size());
    }
}

TEST(OrderSann, RefusesABoxTooSmallForTheShell) {
    // 8 sites of a simple-cubic lattice of edge 1 in a box of 2: no neighbour closer than L / 2.
    EXPECT_THROW(sannBonds(cubicCrystal(2, 1.0, kSimpleCubic)), std::runtime_error);
}

TEST(OrderSolidLike, BondCorrelationObeysTheAdditionTheorem) {
    // d_l(i, j) = sum_{a in i, b in j} P_l(u_a . u_b) / sqrt(same over i, i times over j, j).
    const NeighbourBonds bonds = randomBonds(13);
    const auto byParticle = bondsByParticle(bonds);
    for (int degree : {4, 6}) {
        SCOPED_TRACE(degree);
        const SolidLikeResult result = SolidLikeParticles({degree, 0.5, 3}).compute(bonds);
        for (std::size_t k = 0; k < bonds.bonds.size(); ++k) {
            const auto& a = byParticle[bonds.bonds[k].i];
            const auto& b = byParticle[bonds.bonds[k].j];
            double cross = 0.0;
            for (const Vector3d& u : a)
                for (const Vector3d& v : b)
                    cross += legendre(degree, u.normalized().dot(v.normalized()));
            const double self =
                std::sqrt(additionTheoremSquare(a, degree) * additionTheoremSquare(b, degree)) *
                static_cast<double>(a.size() * b.size());
            EXPECT_NEAR(result.bondCorrelation[k], cross / self, 1e-12);
        }
    }
}

TEST(OrderSolidLike, CountsCrystalBondsAndJoinsOnlySolidLikeParticles) {
    // A chain 0-1-2-3 of parallel bonds (d_l = 1 on each) beside a bond 4-5 crossing it:
    // crystal-like bonds xi = 1, 2, 2, 1; with at least 2 needed, 1 and 2 are solid-like and form
    // the largest cluster; 0 and 3 are not, though joined to it by crystal-like bonds.
    NeighbourBonds bonds{6, {}};
    for (int i = 0; i < 3; ++i)
        bonds.bonds.push_back({i, i + 1, Vector3d::UnitX()});
    bonds.bonds.push_back({4, 5, Vector3d::UnitY()});
    const SolidLikeResult result = SolidLikeParticles({6, 0.7, 2}).compute(bonds);
    EXPECT_EQ(result.crystalBonds, (std::vector<int>{1, 2, 2, 1, 1, 1}));
    EXPECT_EQ(result.solidLike, (std::vector<bool>{false, true, true, false, false, false}));
    EXPECT_EQ(result.solidCount, 2u);
    EXPECT_EQ(result.largestClusterSize, 2u);
    EXPECT_DOUBLE_EQ(result.largestClusterFraction, 2.0 / 6.0);
}

TEST(OrderSolidLike, TwoCrystallitesInAGasAreTwoClusters) {
    // Two equal fcc balls of 2.4 d in an ideal gas at the same density: none of the gas is
    // solid-like, each ball's core is (the largest cluster is one ball, half the solid-like
    // particles); the crystal-like bonds do not join the balls across the gas.
    Packing packing = idealGas(2000, std::cbrt(2000.0 / std::sqrt(2.0)), 3); // fcc's rho d^3
    const double edge = packing.boxLength;
    const std::size_t first =
        carveFccNucleus(packing, Vector3d::Constant(0.25 * edge), 2.4, 1.0, 1.0);
    const std::size_t second =
        carveFccNucleus(packing, Vector3d::Constant(0.75 * edge), 2.4, 1.0, 1.0);
    ASSERT_EQ(first, second);
    const std::size_t gas = packing.size() - first - second;
    const SolidLikeResult result = SolidLikeParticles().compute(sannBonds(packing));
    for (std::size_t i = 0; i < gas; ++i)
        EXPECT_FALSE(result.solidLike[i]) << i;
    EXPECT_GT(result.solidCount, first); // more than one ball's worth
    EXPECT_LE(result.largestClusterSize, first);
    EXPECT_GE(2 * result.largestClusterSize, result.solidCount);
}

TEST(OrderSolidLike, AnIdealGasHasNoCrystal) {
    const SolidLikeResult result = SolidLikeParticles().compute(sannBonds(idealGas(2000, 12.0, 5)));
    EXPECT_LT(result.solidFraction, 0.01);
    EXPECT_LT(result.largestClusterSize, 5u);
}

TEST(OrderSolidLike, RefusesParametersWithoutMeaning) {
    EXPECT_THROW(SolidLikeParticles({0, 0.7, 7}), std::invalid_argument);
    EXPECT_THROW(SolidLikeParticles({6, 1.0, 7}), std::invalid_argument);
    EXPECT_THROW(SolidLikeParticles({6, 0.7, 0}), std::invalid_argument);
    EXPECT_THROW(SolidLikeParticles().compute(NeighbourBonds{}), std::invalid_argument);
}

// --- g2 (docs/order-metrics.md §1) ---

TEST(OrderPairCorrelation, IdealGasIsOneWithinItsErrors) {
    const int count = 2000;
    const Packing gas = idealGas(count, std::cbrt(count), 3); // rho = 1
    const PairCorrelationResult g2 = PairCorrelation({6.0, 0.1}).compute(gas);
    ASSERT_EQ(g2.g2.size(), 60u);
    EXPECT_NEAR(g2.r.front(), 0.05, 1e-12);
    double chiSquare = 0.0, variance = 0.0; // (g2 - 1)^2 / err^2 ~ chi^2, Var = 2 + 1 / count
    for (std::size_t b = 0; b < g2.g2.size(); ++b) {
        const double z = (g2.g2[b] - 1.0) / g2.idealGasError[b];
        chiSquare += z * z;
        variance += 2.0 + g2.idealGasError[b] * g2.idealGasError[b];
    }
    EXPECT_NEAR(chiSquare, 60.0, 5.0 * std::sqrt(variance)) << "chi^2 = " << chiSquare;
}

TEST(OrderPairCorrelation, HistogramIsTheDirectPairCount) {
    const Packing gas = idealGas(300, 5.0, 4);
    const PairCorrelationResult g2 = PairCorrelation({2.4, 0.05}).compute(gas);
    const double w = gas.shape().meanWidth();
    std::vector<std::int64_t> direct(g2.pairCount.size(), 0);
    for (std::size_t i = 0; i < gas.size(); ++i)
        for (std::size_t j = i + 1; j < gas.size(); ++j) {
            const double r = minimumImage(gas.positions[j] - gas.positions[i], 5.0).norm() / w;
            if (r < 2.4) ++direct[static_cast<std::size_t>(r / 0.05)];
        }
    EXPECT_EQ(g2.pairCount, direct);
}

TEST(OrderPairCorrelation, FccCrystalHasDeltaPeaksAtItsShells) {
    // a = 1.0037: no shell lies within a hundredth of a bin of a bin edge (checked below).
    const double a = 1.0037, dr = 0.01;
    const Packing crystal = cubicCrystal(6, a, kFaceCentred);
    const PairCorrelationResult g2 = PairCorrelation({2.5, dr}).compute(crystal);
    const double w = g2.meanWidth, n = static_cast<double>(crystal.size());
    std::vector<std::int64_t> expected(g2.g2.size(), 0);
    for (const FccShell& shell : fccShells(12)) {
        const double r = shell.distance * a / std::numbers::sqrt2 / w;
        if (r >= 2.5) break;
        const double bin = r / dr;
        ASSERT_GT(bin - std::floor(bin), 0.01);
        ASSERT_LT(bin - std::floor(bin), 0.99);
        expected[static_cast<std::size_t>(bin)] +=
            static_cast<std::int64_t>(n * shell.coordination / 2);
    }
    EXPECT_EQ(g2.pairCount, expected);
    // The first minimum lies between the first two shells, in the middle of the empty gap.
    const double d = a / std::numbers::sqrt2 / w;
    const double minimum = firstMinimum(g2);
    EXPECT_GT(minimum, d);
    EXPECT_LT(minimum, std::numbers::sqrt2 * d);
    EXPECT_NEAR(minimum, 0.5 * (1.0 + std::numbers::sqrt2) * d, 2 * dr);
}

/// g2 = 0 below 1, then 1 + 2 e^{-(r - 1) / 0.5} cos(2 pi (r - 1)), plus noise of sd 0.05: first
/// minimum at 1 + (pi - atan(1 / pi)) / (2 pi) = 1.4510.
PairCorrelationResult dampedOscillation(double noise) {
    Random random(9);
    PairCorrelationResult g2;
    for (int b = 0; b < 400; ++b) {
        const double r = (b + 0.5) * 0.01, x = r - 1.0;
        g2.r.push_back(r);
        const double clean =
            r < 1.0 ? 0.0 : 1.0 + 2.0 * std::exp(-x / 0.5) * std::cos(2.0 * std::numbers::pi * x);
        g2.g2.push_back(clean + noise * random.normal());
    }
    return g2;
}

TEST(OrderPairCorrelation, FirstMinimumOfANoisyCurve) {
    const double exact =
        1.0 + (std::numbers::pi - std::atan(1.0 / std::numbers::pi)) / (2.0 * std::numbers::pi);
    EXPECT_NEAR(firstMinimum(dampedOscillation(0.0), 0), exact, 0.01);
    EXPECT_NEAR(firstMinimum(dampedOscillation(0.05), 4), exact, 0.04);
    PairCorrelationResult monotone;
    for (int b = 0; b < 100; ++b) {
        monotone.r.push_back(0.01 * b);
        monotone.g2.push_back(1.0 + std::exp(-0.01 * b));
    }
    EXPECT_THROW(firstMinimum(monotone), std::runtime_error);
    EXPECT_THROW(firstMinimum(monotone, -1), std::invalid_argument);
}

TEST(OrderPairCorrelation, RefusesBadParameters) {
    EXPECT_THROW(PairCorrelation({1.0, 0.0}), std::invalid_argument);
    EXPECT_THROW(PairCorrelation({1.0, 2.0}), std::invalid_argument);
    EXPECT_THROW(PairCorrelation({INFINITY, 0.1}), std::invalid_argument);
    const Packing gas = idealGas(50, 4.0, 1);
    EXPECT_THROW(PairCorrelation({2.1, 0.1}).compute(gas), std::invalid_argument); // L / 2 = 2
    EXPECT_THROW(PairCorrelation({1.0, 0.1}).compute(idealGas(1, 4.0, 1)), std::invalid_argument);
}

// --- Translational order T (docs/order-metrics.md §3) ---

TEST(OrderTranslational, FccShellsAreTheLatticeShells) {
    const int coordination[] = {12, 6, 24, 12, 24, 8, 48, 6, 36, 24, 24, 24, 72, 48};
    const double squaredDistance[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 15}; // no 14
    const std::vector<FccShell> shells = fccShells(14);
    ASSERT_EQ(shells.size(), 14u);
    for (int i = 0; i < 14; ++i) {
        EXPECT_EQ(shells[i].coordination, coordination[i]);
        EXPECT_NEAR(shells[i].distance, std::sqrt(squaredDistance[i]), 1e-15);
    }
    EXPECT_THROW(fccShells(0), std::invalid_argument);
}

TEST(OrderTranslational, PerfectFccIsOne) {
    for (double a : {1.0, 2.3}) {
        const Packing crystal = cubicCrystal(5, a, kFaceCentred); // N = 500
        const TranslationalOrderResult t = TranslationalOrder({}).compute(crystal);
        EXPECT_NEAR(t.order, 1.0, 1e-12);
        const double d = a / std::numbers::sqrt2 / crystal.shape().meanWidth();
        EXPECT_NEAR(t.nearestNeighbourDistance, d, 1e-12);
        for (std::size_t i = 0; i < t.occupation.size(); ++i) {
            EXPECT_NEAR(t.shellRadius[i], std::sqrt(i + 1.0) * d, 1e-12); // shells 1..12
            EXPECT_NEAR(t.occupation[i], t.fccOccupation[i], 1e-12);
        }
    }
}

TEST(OrderTranslational, IdealGasIsZeroWithinItsError) {
    const TranslationalOrder metric({});
    const TranslationalOrderResult t = metric.compute(idealGas(2000, std::cbrt(2000.0), 5));
    EXPECT_LT(t.order, 4.0 * t.idealGasError) << "T = " << t.order;
    // The error is the ideal gas's: the mean T^2 over 60 gases of 600 is its square (within the
    // spread of a mean of 60 chi^2_1 draws, sd 0.18).
    double meanSquare = 0.0, error = 0.0;
    for (int seed = 0; seed < 60; ++seed) {
        const TranslationalOrderResult gas = metric.compute(idealGas(600, 9.0, 100 + seed));
        meanSquare += gas.order * gas.order / 60.0;
        error = gas.idealGasError;
    }
    EXPECT_NEAR(meanSquare / (error * error), 1.0, 0.6);
}

TEST(OrderTranslational, RefusesOverlappingShellsAndSmallBoxes) {
    EXPECT_THROW(TranslationalOrder({12, 0.2}), std::invalid_argument); // sqrt 12 - sqrt 11 = 0.15
    EXPECT_THROW(TranslationalOrder({12, 0.0}), std::invalid_argument);
    EXPECT_THROW(TranslationalOrder({0, 0.1}), std::invalid_argument);
    EXPECT_NO_THROW(TranslationalOrder({3, 0.2}));
    const Packing small = cubicCrystal(4, 1.0, kFaceCentred); // L / 2 = 2.8 d: 7 shells fit
    EXPECT_THROW(TranslationalOrder({}).compute(small), std::invalid_argument);
    EXPECT_NEAR(TranslationalOrder({7, 0.1}).compute(small).order, 1.0, 1e-12);
}

// --- Cubatic P4 (docs/order-metrics.md §4) ---

std::vector<Quaterniond> randomOrientations(int count, std::uint64_t seed) {
    Random random(seed);
    std::vector<Quaterniond> orientations(count);
    for (Quaterniond& q : orientations)
        q = random.rotation();
    return orientations;
}

/// The 24 rotations of the cube: the signed permutation matrices of determinant 1.
std::vector<Quaterniond> cubicGroup() {
    std::vector<Quaterniond> group;
    const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& permutation : permutations)
        for (int signs = 0; signs < 8; ++signs) {
            Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
            for (int row = 0; row < 3; ++row)
                m(row, permutation[row]) = (signs >> row & 1) ? -1.0 : 1.0;
            if (m.determinant() > 0.0) group.emplace_back(m);
        }
    return group;
}

/// sum_{k,l} P_degree(u_ik . u_jl) of two particles' body axes.
double axisPairSum(const Quaterniond& qi, const Quaterniond& qj, int degree) {
    const Eigen::Matrix3d ri = qi.toRotationMatrix(), rj = qj.toRotationMatrix();
    double sum = 0.0;
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
            sum += legendre(degree, ri.col(k).dot(rj.col(l)));
    return sum;
}

TEST(OrderCubatic, IdenticalOrientationsGiveOne) {
    for (const Quaterniond& common : randomOrientations(3, 21)) {
        const std::vector<Quaterniond> aligned(50, common);
        EXPECT_NEAR(cubaticOrder(aligned).order, 1.0, 1e-12);
    }
}

TEST(OrderCubatic, TensorSumIsTheDirectDoubleSum) {
    const std::vector<Quaterniond> orientations = randomOrientations(40, 22);
    double direct = 0.0;
    for (std::size_t i = 0; i < orientations.size(); ++i)
        for (std::size_t j = 0; j < orientations.size(); ++j)
            if (i != j) direct += axisPairSum(orientations[i], orientations[j], 4);
    direct /= 40.0 * 39.0 * kAlignedAxisSum;
    EXPECT_NEAR(cubaticOrder(orientations).order, direct, 1e-12);
}

TEST(OrderCubatic, CubicTurnsOfEachParticleAndCommonRotationsChangeNothing) {
    const std::vector<Quaterniond> group = cubicGroup();
    ASSERT_EQ(group.size(), 24u);
    std::vector<Quaterniond> orientations = randomOrientations(30, 23);
    for (std::size_t i = 0; i < 5; ++i) // a partly aligned set: P4 well away from 0
        orientations[i] = orientations[0];
    const double before = cubaticOrder(orientations).order;
    Random random(24);
    const Quaterniond common = random.rotation();
    std::vector<Quaterniond> turned = orientations;
    for (Quaterniond& q : turned) // body-frame turn, then a common lab rotation
        q = common * q * group[static_cast<std::size_t>(random.uniform() * 24)];
    EXPECT_NEAR(cubaticOrder(turned).order, before, 1e-12);
}

TEST(OrderCubatic, RandomOrientationsAreZeroWithinTheirError) {
    const CubaticOrderResult p4 = cubaticOrder(randomOrientations(1000, 25));
    EXPECT_NEAR(p4.randomOrientationError, std::sqrt(2.0 / (9.0 * 1000 * 999)), 1e-15);
    EXPECT_LT(std::abs(p4.order), 4.0 * p4.randomOrientationError) << "P4 = " << p4.order;
    // The error of Eq. 4.4: the mean P4^2 of 400 sets of 40 is its square (sd about 0.07).
    double meanSquare = 0.0;
    for (int seed = 0; seed < 400; ++seed) {
        const double order = cubaticOrder(randomOrientations(40, 1000 + seed)).order;
        meanSquare += order * order / 400.0;
    }
    EXPECT_NEAR(meanSquare / (2.0 / (9.0 * 40 * 39)), 1.0, 0.3);
}

TEST(OrderCubatic, NematicP2OfCubicAxesVanishes) {
    // sum_{k,l} P2(u_ik . u_jl) = (3/2) |R_i^T R_j|_F^2 - 9/2 = 0 for any two triads, and each
    // triad with itself gives the normalisation 5.25.
    const std::vector<Quaterniond> orientations = randomOrientations(20, 26);
    for (const Quaterniond& qi : orientations) {
        EXPECT_NEAR(axisPairSum(qi, qi, 4), kAlignedAxisSum, 1e-13);
        for (const Quaterniond& qj : orientations)
            EXPECT_NEAR(axisPairSum(qi, qj, 2), 0.0, 1e-13);
    }
}

TEST(OrderCubatic, RefusesWhatIsNoOrientation) {
    EXPECT_THROW(cubaticOrder({Quaterniond::Identity()}), std::invalid_argument);
    EXPECT_THROW(cubaticOrder({Quaterniond::Identity(), Quaterniond(0, 0, 0, 0)}),
                 std::invalid_argument);
    EXPECT_THROW(cubaticOrder({Quaterniond::Identity(), Quaterniond(NAN, 0, 0, 0)}),
                 std::invalid_argument);
}

} // namespace
} // namespace sbpack

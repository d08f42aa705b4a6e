// The nearest jammed packing (docs/jamming.md §6.7): the jamming point of fcc spheres with gaps
// is their gap, a displaced sphere returns to its site, a touching fcc is jammed at once with
// every contact loaded alike; on a disordered superball packing the relaxation's forces are a
// self-stress of the network the contact analysis builds (two independent constructions of the
// contact geometry), and the second-order test takes them.

#include "contacts/contact_network.hpp"
#include "io/packing_io.hpp"
#include "jamming/jamming_test.hpp"
#include "jamming/soft_relaxation.hpp"
#include "pair/pair_geometry.hpp"

#include "order_lattices.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbpack {
namespace {

const std::string kData = SBPACK_DATA_DIR;

/// fcc unit spheres whose nearest neighbours are `gap` D apart, 2^3 cells (32 spheres).
Packing faceCentredWithGap(double gap) {
    return lattices::cubicCrystal(2, std::sqrt(2.0) * (1.0 + gap), lattices::kFaceCentred);
}

TEST(SoftRelaxation, TouchingFaceCentredCubicIsJammedAtOnceWithEveryContactLoadedAlike) {
    const JammingPoint point = findJammingPoint(faceCentredWithGap(0.0), {});
    ASSERT_TRUE(point.found);
    EXPECT_EQ(point.unjammedShell, 0.0);
    EXPECT_EQ(point.jammedShell, RelaxationParameters{}.smallestShell);
    EXPECT_EQ(point.relaxed.contacts, 6 * 32);
    // Each contact overlaps by the shell, the forces cancel by symmetry: nothing moves.
    EXPECT_NEAR(point.relaxed.meanForce, point.jammedShell, 1e-6 * point.jammedShell);
    EXPECT_LT(point.largestDisplacement, 1e-14);
}

TEST(SoftRelaxation, FaceCentredCubicWithGapsJamsWhereTheShellClosesThem) {
    for (const double gap : {3e-7, 2e-4}) {
        const JammingPoint point = findJammingPoint(faceCentredWithGap(gap), {});
        ASSERT_TRUE(point.found) << gap;
        EXPECT_LT(point.unjammedShell, gap);
        EXPECT_GE(point.jammedShell, gap);
        EXPECT_LE(point.jammedShell - point.unjammedShell, 0.05 * point.jammedShell);
        EXPECT_NEAR(point.relaxed.meanForce, point.jammedShell - gap, 1e-9 * gap);
        EXPECT_LT(point.largestDisplacement, 1e-12);
    }
}

TEST(SoftRelaxation, ADisplacedSphereReturnsToItsSiteAndTheJammingPointStays) {
    const double gap = 1e-4, shift = 0.6 * gap;
    Packing packing = faceCentredWithGap(gap);
    const int moved = 13;
    packing.positions[moved].x() += shift; // closer to its +x neighbours than the gap
    const JammingPoint point = findJammingPoint(packing, {});
    ASSERT_TRUE(point.found);
    EXPECT_LT(point.unjammedShell, gap);
    EXPECT_GE(point.jammedShell, gap);
    EXPECT_EQ(point.deepestOverlap, 0.0); // a motion of hard spheres: it only moves back
    // The centroid stays (no force moves it), so the others shift by shift / N along +x and
    // the sphere by (N - 1) shift / N back: against the others, it returns by the shift.
    const int n = static_cast<int>(packing.size());
    const Vector3d others = Vector3d(shift / n, 0.0, 0.0);
    for (int i = 0; i < n; ++i) {
        const Vector3d expected = i == moved ? others - Vector3d(shift, 0.0, 0.0) : others;
        EXPECT_LT((point.displacement[i] - expected).norm(), 1e-3 * shift) << i;
    }
}

TEST(SoftRelaxation, ItsForcesAreASelfStressOfTheContactAnalysesNetworkAndTheStressTestTakesThem) {
    // 40 superballs, p = 1.2 (sbgen, an ordered small box): hypostatic, no self-stress at the
    // jam check's tolerance; relaxed, a self-stress on the shell's network.
    const Packing packing = readPacking(kData + "/ordered-p1.2-40.h5");
    const JammingPoint point = findJammingPoint(packing, {});
    ASSERT_TRUE(point.found);
    EXPECT_GT(point.unjammedShell, 1e-6); // not jammed as sbgen left it
    EXPECT_LT(point.relaxed.balanceResidual, 1e-8);
    const ContactResult contacts =
        ContactNetwork({point.jammedShell * (1.0 + 1e-6), 4}).compute(point.relaxed.packing);
    const RigidityNetwork network = backboneNetwork(point.relaxed.packing, contacts);
    ASSERT_EQ(static_cast<int>(network.contacts.size()), point.relaxed.contacts);
    Eigen::VectorXd forces(network.contacts.size());
    for (std::size_t c = 0; c < network.contacts.size(); ++c)
        forces[static_cast<Eigen::Index>(c)] = point.jammedShell - contacts.gaps[c];
    const SelfStress stress = givenSelfStress(network, forces, 1e-6);
    EXPECT_LT(stress.balanceResidual, 1e-7);
    const JammingResult result =
        JammingTest({}).compute(network, JammingCategory::Collective, forces);
    ASSERT_TRUE(result.secondOrder.has_value());
    EXPECT_NE(result.secondOrder->verdict, SecondOrderVerdict::NoSelfStress);
    EXPECT_GT(result.secondOrder->floppyModes, 0);
}

/// Three p = 1.5 superballs at random orientations, the pairs (0, 1) and (0, 2) placed at a gap
/// of 0.01 D (within a shell of 0.02 D: f = 0.01), alone in a large box.
Packing threeSuperballs() {
    Packing packing;
    packing.p = 1.5;
    packing.semiAxis = 0.5;
    packing.boxLength = 10.0;
    packing.orientations = {Quaterniond(0.9, 0.2, -0.3, 0.1).normalized(),
                            Quaterniond(0.4, -0.5, 0.6, 0.2).normalized(),
                            Quaterniond(0.1, 0.8, 0.3, -0.5).normalized()};
    packing.positions = {Vector3d(3.0, 3.0, 3.0), Vector3d::Zero(), Vector3d::Zero()};
    const Vector3d directions[2] = {Vector3d(1.0, 0.1, 0.05).normalized(),
                                    Vector3d(0.4, 1.0, 0.2).normalized()};
    for (int j = 1; j <= 2; ++j) {
        double distance = 1.0;
        for (int k = 0; k < 40; ++k) { // the gap grows with the distance at slope n . d^ ~ 1
            const SuperballPair pair{packing.shape(), packing.orientations[0].toRotationMatrix(),
                                     packing.orientations[j].toRotationMatrix(),
                                     distance * directions[j - 1]};
            distance += 0.01 - signedDistance(pair).signedDistance;
        }
        packing.positions[j] = packing.positions[0] + distance * directions[j - 1];
    }
    return packing;
}

/// `packing` moved by dq in the unknowns' layout: r += dr, R = exp([dtheta]) R per particle.
Packing movedBy(Packing packing, const Eigen::VectorXd& dq) {
    const int n = static_cast<int>(packing.size());
    for (int i = 0; i < n; ++i) {
        packing.positions[i] += dq.segment<3>(3 * i);
        const Vector3d turn = dq.segment<3>(3 * (n + i));
        if (turn.norm() > 0.0)
            packing.orientations[i] =
                Quaterniond(Eigen::AngleAxisd(turn.norm(), turn.normalized())) *
                packing.orientations[i];
    }
    return packing;
}

double energyAt(const Packing& packing, int u, double hu, int w, double hw, double shell) {
    Eigen::VectorXd dq = Eigen::VectorXd::Zero(18);
    dq[u] += hu;
    dq[w] += hw;
    return overlapEnergy(movedBy(packing, dq), shell).energy;
}

// The assembled gradient and Hessian (rigidity columns, gap Hessians, their indices and signs)
// against differences of E itself, in the chart the steps use: one exponential per particle.
TEST(SoftRelaxation, TheEnergysGradientAndHessianAreItsFiniteDifferences) {
    const Packing packing = threeSuperballs();
    const double shell = 0.02, h = 1e-4;
    const OverlapEnergyTerms terms = overlapEnergy(packing, shell);
    ASSERT_GT(terms.energy, 0.0);
    ASSERT_EQ(terms.gradient.size(), 18);
    const double scale = terms.hessian.lpNorm<Eigen::Infinity>();
    for (int u = 0; u < 18; ++u) {
        const double slope =
            (energyAt(packing, u, h, u, 0.0, shell) - energyAt(packing, u, -h, u, 0.0, shell)) /
            (2.0 * h);
        EXPECT_NEAR(terms.gradient[u], slope, 1e-6 * terms.gradient.lpNorm<Eigen::Infinity>())
            << "unknown " << u;
        for (int w = 0; w < 18; ++w) {
            const double second =
                (energyAt(packing, u, h, w, h, shell) - energyAt(packing, u, h, w, -h, shell) -
                 energyAt(packing, u, -h, w, h, shell) + energyAt(packing, u, -h, w, -h, shell)) /
                (4.0 * h * h);
            EXPECT_NEAR(terms.hessian(u, w), second, 1e-5 * scale) << u << ", " << w;
        }
    }
}

TEST(SoftRelaxation, RejectsParametersOutOfRange) {
    const Packing packing = faceCentredWithGap(0.0);
    RelaxationParameters bad;
    bad.smallestShell = 0.0;
    EXPECT_THROW(findJammingPoint(packing, bad), std::invalid_argument);
    bad = {};
    bad.largestShell = 0.5;
    EXPECT_THROW(findJammingPoint(packing, bad), std::invalid_argument);
    bad = {};
    bad.bracketWidth = 1.0;
    EXPECT_THROW(minimiseOverlapEnergy(packing, 1e-6, bad), std::invalid_argument);
    bad = {};
    bad.maxIterations = 0;
    EXPECT_THROW(minimiseOverlapEnergy(packing, 1e-6, bad), std::invalid_argument);
}

} // namespace
} // namespace sbpack

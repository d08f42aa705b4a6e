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
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.5);
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
            const SuperballPair pair{
                packing.superball(), packing.orientations[0].toRotationMatrix(),
                packing.orientations[j].toRotationMatrix(), distance * directions[j - 1]};
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

/// threeSuperballs() moved to the box's corner and wrapped into `cell`: both pairs cross the
/// box's faces (their images carry F L m), their separations unchanged.
Packing threeSuperballsAcrossTheFaces(const Matrix3d& cell) {
    Packing packing = threeSuperballs();
    const Vector3d corner(9.6, 9.65, 9.7);
    for (int j = 2; j >= 0; --j) {
        const Vector3d r = corner + packing.positions[j] - packing.positions[0];
        packing.positions[j] = cell * wrapIntoBox(cell.inverse() * r, packing.boxLength);
    }
    return packing;
}

// The strains' entries (the box deforming, docs/jamming.md §6.8) against differences of E in the
// steps' chart, strainedCell; the unknowns scaled to lengths (a strain by L), so that one
// tolerance holds for every block. Leaving out the volume's rescaling in the Hessian fails it.
TEST(SoftRelaxation, TheStrainsGradientAndHessianAreItsFiniteDifferences) {
    BoxStrain start;
    start << 1e-3, -2e-3, 1.5e-3, 5e-4, -1e-3;
    const Matrix3d cell = strainedCell(Matrix3d::Identity(), start);
    const Packing packing = threeSuperballsAcrossTheFaces(cell);
    const double shell = 0.02, h = 1e-4;
    const OverlapEnergyTerms terms = overlapEnergy(packing, shell, cell);
    ASSERT_EQ(terms.gradient.size(), 18 + kBoxStrains);
    const auto length = [&](int u) { return u < 18 ? 1.0 : packing.boxLength; };
    const auto energy = [&](int u, double hu, int w, double hw) {
        Eigen::VectorXd dq = Eigen::VectorXd::Zero(18 + kBoxStrains);
        dq[u] += hu / length(u);
        dq[w] += hw / length(w);
        return overlapEnergy(movedBy(packing, dq.head(18)), shell,
                             strainedCell(cell, dq.tail<kBoxStrains>()))
            .energy;
    };
    ASSERT_GT(terms.gradient.tail<kBoxStrains>().norm(), 0.0); // the pairs cross the faces
    Eigen::MatrixXd scaled = terms.hessian;
    for (int u = 0; u < scaled.rows(); ++u)
        for (int w = 0; w < scaled.cols(); ++w)
            scaled(u, w) /= length(u) * length(w);
    const double scale = scaled.lpNorm<Eigen::Infinity>();
    for (int u = 0; u < 18 + kBoxStrains; ++u) {
        const double slope = (energy(u, h, u, 0.0) - energy(u, -h, u, 0.0)) / (2.0 * h);
        EXPECT_NEAR(terms.gradient[u] / length(u), slope, 1e-6 * terms.gradient.norm())
            << "unknown " << u;
        for (int w = 18; w < 18 + kBoxStrains; ++w) { // the strains' rows and columns
            const double second = (energy(u, h, w, h) - energy(u, h, w, -h) - energy(u, -h, w, h) +
                                   energy(u, -h, w, -h)) /
                                  (4.0 * h * h);
            EXPECT_NEAR(scaled(u, w), second, 1e-5 * scale) << u << ", " << w;
        }
    }
}

/// fcc spheres `gap` D apart (32 of them) in the tetragonal cell diag(l, l, l^-2), of the cube's
/// volume: the in-plane neighbours l a / sqrt(2) apart, the others a sqrt(l^2 + l^-4) / 2.
struct StretchedCrystal {
    Packing packing;
    Matrix3d cell;
};
StretchedCrystal stretchedFaceCentred(double gap, double stretch) {
    StretchedCrystal crystal{faceCentredWithGap(gap), Matrix3d::Identity()};
    crystal.cell.diagonal() << stretch, stretch, 1.0 / (stretch * stretch);
    for (Vector3d& r : crystal.packing.positions)
        r = crystal.cell * r;
    return crystal;
}

// A stretched fcc in a box free to deform returns to the cube at its volume, every contact
// loaded by shell - gap; in its stretched box held fixed nothing moves (each sphere is a centre
// of symmetry) and the two kinds of contact carry the two forces of their gaps.
TEST(SoftRelaxation, AStretchedFaceCentredCubicReturnsToTheCubeWhereTheBoxDeforms) {
    const double gap = 1e-3, shell = 1.5e-3, stretch = 1.0 + 2e-4;
    const StretchedCrystal crystal = stretchedFaceCentred(gap, stretch);
    RelaxationParameters free;
    free.deformBox = true;
    const SoftMinimum relaxed =
        minimiseOverlapEnergy(crystal.packing, shell, free, {}, crystal.cell);
    EXPECT_EQ(relaxed.verdict, SoftVerdict::Jammed);
    EXPECT_LT((relaxed.cell - Matrix3d::Identity()).norm(), 1e-9);
    EXPECT_EQ(relaxed.contacts, 6 * 32);
    EXPECT_NEAR(relaxed.meanForce, shell - gap, 1e-6 * (shell - gap));

    const SoftMinimum fixed = minimiseOverlapEnergy(crystal.packing, shell, {}, {}, crystal.cell);
    EXPECT_EQ(fixed.verdict, SoftVerdict::Jammed);
    EXPECT_EQ(fixed.cell, crystal.cell);
    const double spacing = std::sqrt(2.0) * (1.0 + gap); // a, the cube's fcc edge
    const double inPlane = shell - (stretch * spacing / std::sqrt(2.0) - 1.0);
    const double across =
        shell - (0.5 * spacing * std::sqrt(stretch * stretch + std::pow(stretch, -4.0)) - 1.0);
    EXPECT_NEAR(fixed.meanForce, (inPlane + 2.0 * across) / 3.0, 1e-9 * shell);
}

/// The symmetric part of the contact virial sum_c f_c n_c (x) d_c of a relaxed packing's
/// backbone, f_c = shell - s_c, built in its cell (relaxedContacts, backboneNetwork).
Matrix3d contactVirial(const JammingPoint& point) {
    const ContactResult contacts = relaxedContacts(point.relaxed, point.jammedShell * 1.000001, 4);
    const RigidityNetwork network =
        backboneNetwork(point.relaxed.packing, contacts, point.relaxed.cell);
    Matrix3d virial = Matrix3d::Zero();
    for (std::size_t c = 0, k = 0; c < contacts.contacts.size(); ++c) {
        const auto [i, j] = contacts.contacts[c];
        if (contacts.rattler[i] || contacts.rattler[j]) continue;
        const RigidContact& contact = network.contacts[k++];
        virial += (point.jammedShell - contacts.gaps[c]) * contact.normal *
                  (contact.leverI - contact.leverJ).transpose();
    }
    return 0.5 * (virial + virial.transpose());
}

/// The deviatoric part of `virial` over its pressure (a third of its trace, > 0).
double anisotropy(const Matrix3d& virial) {
    const double pressure = virial.trace() / 3.0;
    EXPECT_GT(pressure, 0.0);
    return (virial - pressure * Matrix3d::Identity()).norm() / pressure;
}

// sbgen's 100 spheres (seed 2, its defaults): jammed within 1e-10 D in their cubic box, but a
// shear at their volume unjams them (Dagois-Bohy et al. 2012); with the box free the nearest
// jammed packing lies further, its cell strained, and its stress is isotropic, as a minimum over
// the traceless strains must have it: what the strict test needs (docs/jamming.md §6.8). Relaxed
// in the cubic box, its stress keeps a shear part.
TEST(SoftRelaxation, WithTheBoxFreeTheRelaxedStressIsIsotropic) {
    const Packing packing = readPacking(kData + "/mrj-spheres-100.h5");
    const JammingPoint fixed = findJammingPoint(packing, {});
    RelaxationParameters free;
    free.deformBox = true;
    const JammingPoint point = findJammingPoint(packing, free);
    ASSERT_TRUE(fixed.found && point.found);
    EXPECT_EQ(fixed.boxStrain, 0.0);
    EXPECT_GT(point.unjammedShell, 10.0 * fixed.jammedShell);
    EXPECT_GT(point.boxStrain, 1e-4);
    EXPECT_NEAR(point.relaxed.cell.determinant(), 1.0, 1e-12);
    EXPECT_LT(anisotropy(contactVirial(point)), 1e-6);
    EXPECT_GT(anisotropy(contactVirial(fixed)), 1e-2);
    // The network in the strained cell against every pair and all 27 images (spheres: gap =
    // |d| - D), which no candidate search can miss.
    const Packing& relaxed = point.relaxed.packing;
    const Matrix3d& cell = point.relaxed.cell;
    const double diameter = relaxed.shape().diameter(), below = point.jammedShell * 1.000001;
    std::size_t touching = 0;
    for (std::size_t i = 0; i < relaxed.size(); ++i)
        for (std::size_t j = i + 1; j < relaxed.size(); ++j)
            for (int m = 0; m < 27; ++m) {
                const Vector3d image(m % 3 - 1, m / 3 % 3 - 1, m / 9 - 1);
                const Vector3d d =
                    relaxed.positions[j] - relaxed.positions[i] + cell * image * relaxed.boxLength;
                touching += d.norm() - diameter < below * diameter ? 1 : 0;
            }
    EXPECT_EQ(touching, relaxedContacts(point.relaxed, below, 4).contacts.size());
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

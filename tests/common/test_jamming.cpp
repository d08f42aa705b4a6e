// First-order jamming categories (docs/jamming.md): the rigidity matrix against finite differences
// of the exact pair distance, and the known answers of Torquato & Stillinger, J. Phys. Chem. B
// 105, 11849 (2001) and Donev, Torquato, Stillinger & Connelly, J. Comput. Phys. 197, 139 (2004)
// for sphere lattices, and for two lattices of two sizes (docs/mixtures.md); the MRJ sphere
// packing's answer is reported, not asserted.

#include "contacts/contact_network.hpp"
#include "contacts/jam_check.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"
#include "jamming/gordan_motion.hpp"
#include "jamming/jamming_test.hpp"
#include "jamming/rigidity_matrix.hpp"
#include "jamming/second_order.hpp"
#include "jamming/self_stress.hpp"
#include "pair/pair_geometry.hpp"
#include "random/random.hpp"

#include "order_lattices.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {
namespace {

const std::string kData = SBPACK_DATA_DIR;

/// Spheres of diameter 1 at the basis points (units of the lattice constant) of cells^3 cells.
Packing sphereLattice(double latticeConstant, int cells, const std::vector<Vector3d>& basis) {
    return lattices::cubicCrystal(cells, latticeConstant, basis, Vector3d::Zero());
}

Packing simpleCubic(int cells) {
    return sphereLattice(1.0, cells, {Vector3d::Zero()});
}

Packing bodyCentredCubic(int cells) {
    return sphereLattice(2.0 / std::sqrt(3.0), cells, {Vector3d::Zero(), Vector3d(0.5, 0.5, 0.5)});
}

RigidityNetwork networkOf(const Packing& packing, const ContactParameters& parameters = {}) {
    return backboneNetwork(packing, ContactNetwork(parameters).compute(packing));
}

JammingResult test(const RigidityNetwork& network, JammingCategory category,
                   const JammingParameters& parameters = {}) {
    return JammingTest(parameters).compute(network, category);
}

/// The contacts of unit spheres at `positions` in an orthorhombic periodic cell `box`, built
/// directly (centre-to-centre normals, midpoints): for cells a Packing cannot hold (hcp).
RigidityNetwork sphereNetwork(const std::vector<Vector3d>& positions, const Vector3d& box) {
    RigidityNetwork network;
    network.packingSize = static_cast<int>(positions.size());
    network.boxLength = box.maxCoeff();
    for (int i = 0; i < network.packingSize; ++i) {
        network.backbone.push_back(i);
        for (int j = i + 1; j < network.packingSize; ++j) {
            const Vector3d inBox = positions[j] - positions[i];
            Vector3d d = inBox;
            for (int k = 0; k < 3; ++k)
                d[k] -= box[k] * std::nearbyint(d[k] / box[k]);
            if (std::abs(d.norm() - 1.0) > 1e-9) continue;
            network.contacts.push_back({i, j, d.normalized(), 0.5 * d, -0.5 * d, d - inBox, 0.0});
        }
    }
    return network;
}

/// hcp of unit spheres in an orthorhombic cell of 4 x 2 x 2 cells (a, sqrt(3) a, c), 4 spheres
/// each: layers A at z = 0 and B at z = c / 2 over the triangles' centres, c = sqrt(8 / 3).
std::vector<Vector3d> hexagonalClosePacked(Vector3d& box) {
    const double s = std::sqrt(3.0), c = std::sqrt(8.0 / 3.0);
    const std::vector<Vector3d> basis = {{0.0, 0.0, 0.0},
                                         {0.5, 0.5 * s, 0.0},
                                         {0.5, s / 6.0, 0.5 * c},
                                         {0.0, 2.0 * s / 3.0, 0.5 * c}};
    box = Vector3d(4.0, 2.0 * s, 2.0 * c);
    std::vector<Vector3d> positions;
    for (int x = 0; x < 4; ++x)
        for (int y = 0; y < 2; ++y)
            for (int z = 0; z < 2; ++z)
                for (const Vector3d& b : basis)
                    positions.push_back(b + Vector3d(x, y * s, z * c));
    return positions;
}

/// eps from dq's strain components (dof's layout).
Matrix3d strainOf(const DegreesOfFreedom& dof, const Eigen::VectorXd& dq) {
    const auto e = [&](int k) { return dq[dof.strainComponent(k)]; };
    Matrix3d strain;
    strain << e(0), e(5), e(4), e(5), e(1), e(3), e(4), e(3), e(2);
    return strain;
}

/// The signed distance of a packing's pair (0, 1) moved by t dq, in the deformed box: the images
/// follow (I + t eps), each particle moves by t (dr'_k - eps r_k) beyond the affine field.
double movedDistance(const Packing& packing, const DegreesOfFreedom& dof, const Eigen::VectorXd& dq,
                     double t) {
    Matrix3d rotation[2];
    Vector3d nonAffine[2];
    const Matrix3d strain = strainOf(dof, dq);
    for (int k = 0; k < 2; ++k) {
        rotation[k] = packing.orientations[k].toRotationMatrix();
        nonAffine[k] = dq.segment<3>(dof.translation(k)) - strain * packing.positions[k];
        if (!dof.rotations) continue;
        const Vector3d theta = t * dq.segment<3>(dof.rotation(k));
        rotation[k] = Eigen::AngleAxisd(theta.norm(), theta.normalized()) * rotation[k];
    }
    const Vector3d d = minimumImage(packing.positions[1] - packing.positions[0], packing.boxLength);
    const Vector3d moved = d + t * (strain * d + nonAffine[1] - nonAffine[0]);
    return signedDistance(SuperballPair{packing.superball(), rotation[0], rotation[1], moved})
        .signedDistance;
}

TEST(RigidityMatrix, GapChangesAreTheDerivativesOfTheExactSignedDistance) {
    Random random(7);
    int crossing = 0;
    for (const double p : {0.85, 1.0, 1.5, 3.0}) {
        for (int trial = 0; trial < 10; ++trial) {
            Packing packing;
            packing.shapeSpec = sbpack::ShapeSpec::superball(p);
            packing.boxLength = 10.0;
            packing.orientations = {random.rotation(), random.rotation()};
            const Vector3d u = random.normalVector().normalized();
            const double touching =
                1.0 / scaleFactor(SuperballPair{packing.superball(),
                                                packing.orientations[0].toRotationMatrix(),
                                                packing.orientations[1].toRotationMatrix(), u})
                          .scaleFactor;
            // Across the box's corner for odd trials: the strain enters through the image.
            const Vector3d first = Vector3d::Constant(trial % 2 ? 0.1 : 5.0);
            packing.positions = {first, wrapIntoBox(first + (touching + 1e-4) * u, 10.0)};
            const RigidityNetwork network = networkOf(packing, {1e-3, 1});
            ASSERT_EQ(network.contacts.size(), 1u);
            crossing += !network.contacts[0].boxShift.isZero();
            const DegreesOfFreedom dof = degreesOfFreedom(network, JammingCategory::Strict);
            EXPECT_EQ(dof.count(), p == 1.0 ? 12 : 18);
            Eigen::VectorXd dq(dof.count());
            for (Eigen::Index k = 0; k < dq.size(); ++k)
                dq[k] = random.normal();
            const double h = 1e-5;
            const double numeric =
                (movedDistance(packing, dof, dq, h) - movedDistance(packing, dof, dq, -h)) /
                (2.0 * h);
            const double analytic =
                (rigidityMatrix(network, JammingCategory::Strict).transpose() * dq)[0];
            EXPECT_NEAR(analytic, numeric, 1e-6 * dq.norm()) << "p " << p << " trial " << trial;
        }
    }
    EXPECT_GE(crossing, 10); // of the 20 odd trials
}

TEST(RigidityMatrix, LocalSplitsEachContactIntoTheTwoParticlesTests) {
    const RigidityNetwork network = networkOf(simpleCubic(3));
    const Eigen::SparseMatrix<double> collective =
        rigidityMatrix(network, JammingCategory::Collective);
    const Eigen::SparseMatrix<double> local = rigidityMatrix(network, JammingCategory::Local);
    ASSERT_EQ(local.cols(), 2 * collective.cols());
    for (Eigen::Index c = 0; c < collective.cols(); ++c)
        EXPECT_LT((Eigen::VectorXd(local.col(2 * c)) + Eigen::VectorXd(local.col(2 * c + 1)) -
                   Eigen::VectorXd(collective.col(c)))
                      .norm(),
                  1e-15);
}

TEST(RigidityNetwork, DirectSphereNetworkMatchesTheContactNetworks) {
    const Packing fcc = readTextPacking(kData + "/fcc-spheres.txt");
    const RigidityNetwork fromContacts = networkOf(fcc);
    const RigidityNetwork direct = sphereNetwork(fcc.positions, Vector3d::Constant(fcc.boxLength));
    ASSERT_EQ(fromContacts.contacts.size(), direct.contacts.size());
    EXPECT_EQ(fromContacts.backbone, direct.backbone);
    EXPECT_FALSE(fromContacts.rotations);
    for (std::size_t c = 0; c < direct.contacts.size(); ++c) {
        const RigidContact &a = fromContacts.contacts[c], &b = direct.contacts[c];
        EXPECT_EQ(a.i, b.i);
        EXPECT_EQ(a.j, b.j);
        EXPECT_LT((a.normal - b.normal).norm(), 1e-14);
        EXPECT_LT((a.leverI - b.leverI).norm() + (a.leverJ - b.leverJ).norm(), 1e-14);
        EXPECT_LT(a.gap, 1e-14);
    }
}

TEST(JammingCategories, SimpleCubicIsLocallyButNotCollectivelyJammedARowSlides) {
    const Packing packing = simpleCubic(4);
    const RigidityNetwork network = networkOf(packing);
    EXPECT_EQ(test(network, JammingCategory::Local).verdict, FirstOrderVerdict::Jammed);
    const JammingResult collective = test(network, JammingCategory::Collective);
    EXPECT_EQ(collective.verdict, FirstOrderVerdict::Unjammed);
    EXPECT_FALSE(collective.opening);           // no contact opens at first order: rows slide
    EXPECT_FALSE(collective.opensEveryContact); // the rows' self-stresses: A^T A is singular
    EXPECT_LT(collective.largestOpening, 1e-9);
    ASSERT_TRUE(collective.flex);
    const UnjammingMotion& flex = *collective.flex;
    EXPECT_LT(flex.gapChange.cwiseAbs().maxCoeff(), 1e-9);
    // Every row along axis k moves rigidly along k: the k-components agree within the row.
    for (int a = 0; a < 64; ++a)
        for (int b = 0; b < 64; ++b)
            for (int k = 0; k < 3; ++k) {
                const Vector3d d = packing.positions[b] - packing.positions[a];
                if (std::abs(d[(k + 1) % 3]) + std::abs(d[(k + 2) % 3]) > 0.0) continue;
                EXPECT_NEAR(flex.displacement[a][k], flex.displacement[b][k], 1e-9);
            }
    EXPECT_GE(flex.moving.size(), 4u); // at least one whole row of 4
    EXPECT_EQ(test(network, JammingCategory::Strict).verdict, FirstOrderVerdict::Unjammed);
}

TEST(JammingCategories, SimpleCubicVacancyFreesItsSixNeighbours) {
    Packing packing = simpleCubic(4);
    packing.positions.erase(packing.positions.begin());
    packing.orientations.pop_back();
    const RigidityNetwork network = networkOf(packing);
    const JammingResult local = test(network, JammingCategory::Local);
    EXPECT_EQ(local.verdict, FirstOrderVerdict::Unjammed);
    ASSERT_TRUE(local.opening);
    // The vacancy's neighbours (1,0,0), (3,0,0), (0,1,0), (0,3,0), (0,0,1), (0,0,3), indexed
    // x 16 + y 4 + z - 1 after the erased particle 0.
    EXPECT_EQ(local.freed, (std::vector<int>{0, 2, 3, 11, 15, 47}));
}

TEST(JammingCategories, FaceCentredCubicIsStrictlyJammed) {
    const RigidityNetwork network = networkOf(readTextPacking(kData + "/fcc-spheres.txt"));
    for (const JammingCategory category :
         {JammingCategory::Local, JammingCategory::Collective, JammingCategory::Strict}) {
        const JammingResult result = test(network, category);
        EXPECT_EQ(result.verdict, FirstOrderVerdict::Jammed) << static_cast<int>(category);
        EXPECT_LT(result.largestOpening, 1e-9);
        EXPECT_TRUE(result.freed.empty());
    }
    EXPECT_EQ(test(network, JammingCategory::Collective).isostaticDeficit, 3 * 108 - 3 - 648);
}

TEST(JammingCategories, HexagonalClosePackedIsStrictlyJammed) {
    Vector3d box;
    const std::vector<Vector3d> positions = hexagonalClosePacked(box);
    const RigidityNetwork network = sphereNetwork(positions, box);
    ASSERT_EQ(network.contacts.size(), 6u * positions.size());
    for (const JammingCategory category :
         {JammingCategory::Local, JammingCategory::Collective, JammingCategory::Strict})
        EXPECT_EQ(test(network, category).verdict, FirstOrderVerdict::Jammed)
            << static_cast<int>(category);
}

TEST(JammingCategories, BodyCentredCubicIsLocallyButNotCollectivelyJammedSheetsSlide) {
    const Packing packing = bodyCentredCubic(4);
    const RigidityNetwork network = networkOf(packing);
    ASSERT_EQ(network.contacts.size(), 4u * packing.size());
    EXPECT_EQ(test(network, JammingCategory::Local).verdict, FirstOrderVerdict::Jammed);
    const JammingResult collective = test(network, JammingCategory::Collective);
    EXPECT_EQ(collective.verdict, FirstOrderVerdict::Unjammed);
    EXPECT_FALSE(collective.opening); // the uniform self-stress: nothing opens at first order
    EXPECT_TRUE(collective.flex);
    EXPECT_EQ(test(network, JammingCategory::Strict).verdict, FirstOrderVerdict::Unjammed);
    // The flex in closed form: the (1 -1 0) sheet x - y = 0 (mod L) slides along [1 1 0].
    const DegreesOfFreedom dof = degreesOfFreedom(network, JammingCategory::Collective);
    Eigen::VectorXd sheet = Eigen::VectorXd::Zero(dof.count());
    int moved = 0;
    for (int k = 0; k < dof.particles; ++k) {
        const Vector3d& r = packing.positions[k];
        const double offset = std::remainder(r.x() - r.y(), packing.boxLength);
        if (std::abs(offset) > 1e-9) continue;
        sheet.segment<3>(dof.translation(k)) = Vector3d(1.0, 1.0, 0.0);
        ++moved;
    }
    EXPECT_EQ(moved, 2 * 4 * 4); // two atoms per cell on the sheet, 4 x 4 cells
    EXPECT_LT((rigidityMatrix(network, JammingCategory::Collective).transpose() * sheet)
                  .cwiseAbs()
                  .maxCoeff(),
              1e-14);
}

/// `contacts` without those of particle `loose` whose normal, outward from it, has a positive
/// x component: nothing holds it along +x, though it keeps its other contacts (no rattler).
ContactResult withoutPlusXContacts(const ContactResult& contacts, int loose) {
    ContactResult kept = contacts;
    kept.contacts.clear();
    kept.gaps.clear();
    kept.normals.clear();
    kept.points.clear();
    for (std::size_t c = 0; c < contacts.contacts.size(); ++c) {
        const auto [i, j] = contacts.contacts[c];
        const double outward =
            i == loose ? contacts.normals[c].x() : (j == loose ? -contacts.normals[c].x() : 0.0);
        if (outward > 0.1) continue;
        kept.contacts.push_back(contacts.contacts[c]);
        kept.gaps.push_back(contacts.gaps[c]);
        kept.normals.push_back(contacts.normals[c]);
        kept.points.push_back(contacts.points[c]);
    }
    return kept;
}

/// The fcc scene with particle `loose`'s 4 contacts on its +x side left out: 8 remain.
TEST(JammingCategories, AParticleWithContactsInOneHalfSpaceIsFreedAndMovesAlone) {
    const Packing packing = readTextPacking(kData + "/fcc-spheres.txt");
    const ContactResult contacts = ContactNetwork({}).compute(packing);
    const int loose = 5;
    const ContactResult kept = withoutPlusXContacts(contacts, loose);
    ASSERT_EQ(kept.contacts.size(), contacts.contacts.size() - 4);
    const RigidityNetwork network = backboneNetwork(packing, kept);

    const JammingResult local = test(network, JammingCategory::Local);
    EXPECT_EQ(local.verdict, FirstOrderVerdict::Unjammed);
    EXPECT_EQ(local.freed, std::vector<int>{loose});
    for (const JammingCategory category : {JammingCategory::Collective, JammingCategory::Strict}) {
        const JammingResult result = test(network, category);
        EXPECT_EQ(result.verdict, FirstOrderVerdict::Unjammed);
        ASSERT_TRUE(result.opening);
        EXPECT_EQ(result.opening->moving, std::vector<int>{loose});
        EXPECT_LT((result.opening->displacement[loose] - Vector3d(1.0, 0.0, 0.0)).norm(), 1e-9);
        EXPECT_NEAR(result.largestOpening, 1.0 / std::sqrt(2.0), 1e-9);
    }
}

TEST(JammingCategories, GapsAllowMotionsOnlyOfTheirOwnSize) {
    // Lattice constant 1 + 1e-10: every contact has a gap of 1e-10 D.
    const RigidityNetwork network =
        networkOf(sphereLattice(1.0 + 1e-10, 4, {Vector3d::Zero()}), {1e-9, 4});
    JammingParameters parameters;
    parameters.useGaps = true;
    // Delta far above the gaps: the cage's motions lie below the tolerance, as if ideal.
    EXPECT_EQ(test(network, JammingCategory::Local, parameters).verdict, FirstOrderVerdict::Jammed);
    // Delta of the gaps' order: a particle crosses its cage, opening a contact by a gap.
    parameters.maxStep = 1e-9;
    const JammingResult cage = test(network, JammingCategory::Local, parameters);
    EXPECT_EQ(cage.verdict, FirstOrderVerdict::Unjammed);
    EXPECT_GT(cage.largestOpening, 0.5e-10);
    EXPECT_LT(cage.largestOpening, 2.0e-10 + 1e-15);
}

/// Donev et al. 2004's finite-gap test: every pair within `tolerance` D with its gap, Delta
/// = 10 D, unjammed only by a motion of a particle by more than 1 D (docs/jamming.md §4.1).
JammingParameters finiteGapTest() {
    JammingParameters parameters;
    parameters.useGaps = true;
    parameters.maxStep = 10.0;
    parameters.unjammingDistance = 1.0;
    return parameters;
}

TEST(FiniteGapTest, SimpleCubicRowsSlideByMoreThanADiameter) {
    // At 0.25 D only the 6 touching neighbours are in the network (the next at sqrt 2 D):
    // nothing stops a row sliding along itself, by Delta, far beyond 1 D.
    const Packing packing = simpleCubic(4);
    const RigidityNetwork network = networkOf(packing, {0.25, 4, true});
    ASSERT_EQ(network.contacts.size(), 3u * packing.size());
    EXPECT_EQ(test(network, JammingCategory::Local, finiteGapTest()).verdict,
              FirstOrderVerdict::Jammed);
    for (const JammingCategory category : {JammingCategory::Collective, JammingCategory::Strict}) {
        const JammingResult result = test(network, category, finiteGapTest());
        EXPECT_EQ(result.verdict, FirstOrderVerdict::Unjammed) << static_cast<int>(category);
        EXPECT_GT(result.largestDisplacement, 1.0);
        EXPECT_GE(result.freed.size(), 4u); // at least a row
    }
}

TEST(FiniteGapTest, FaceCentredCubicAndItsNextNeighboursAreStrictlyJammed) {
    // At 0.5 D the network holds the 12 touching neighbours and the 6 at sqrt 2 D (gap 0.41 D):
    // the polytope bounds every motion by the gaps, far below 1 D.
    const RigidityNetwork network =
        networkOf(readTextPacking(kData + "/fcc-spheres.txt"), {0.5, 4, true});
    ASSERT_EQ(network.contacts.size(), 9u * 108u);
    for (const JammingCategory category :
         {JammingCategory::Local, JammingCategory::Collective, JammingCategory::Strict}) {
        const JammingResult result = test(network, category, finiteGapTest());
        EXPECT_EQ(result.verdict, FirstOrderVerdict::Jammed) << static_cast<int>(category);
        EXPECT_LT(result.largestDisplacement, 1.0);
        EXPECT_TRUE(result.freed.empty());
    }
}

TEST(FiniteGapTest, AnFccSphereMovesWithinItsRhombicDodecahedralCage) {
    // fcc spheres with every nearest gap g: one sphere alone may move within the polytope
    // |n_k . d| <= g of its 12 neighbours, a rhombic dodecahedron whose vertices lie at
    // max-norm g sqrt 2 (on the axes) and g sqrt 2 / 2 (on the diagonals). A random load ends
    // at a vertex: unjammed at an unjamming distance of g / 2, jammed at 2 g.
    const double g = 1e-3, a = std::sqrt(2.0) * (1.0 + g);
    const Packing packing =
        sphereLattice(a, 3, {Vector3d::Zero(), {0.5, 0.5, 0.0}, {0.5, 0.0, 0.5}, {0.0, 0.5, 0.5}});
    const RigidityNetwork network = networkOf(packing, {2e-3, 4});
    ASSERT_EQ(network.contacts.size(), 6u * packing.size());
    JammingParameters parameters = finiteGapTest();
    parameters.unjammingDistance = 0.5 * g;
    const JammingResult loose = test(network, JammingCategory::Local, parameters);
    EXPECT_EQ(loose.verdict, FirstOrderVerdict::Unjammed);
    EXPECT_EQ(loose.freed.size(), packing.size());
    EXPECT_GE(loose.largestDisplacement, 0.5 * std::sqrt(2.0) * g * (1.0 - 1e-6));
    EXPECT_LE(loose.largestDisplacement, std::sqrt(2.0) * g * (1.0 + 1e-6));
    parameters.unjammingDistance = 2.0 * g;
    // Jammed at 2 g, and the solutions it measured still end at the cage's vertices.
    const JammingResult caged = test(network, JammingCategory::Local, parameters);
    EXPECT_EQ(caged.verdict, FirstOrderVerdict::Jammed);
    EXPECT_TRUE(caged.freed.empty());
    EXPECT_GE(caged.largestDisplacement, 0.5 * std::sqrt(2.0) * g * (1.0 - 1e-6));
    EXPECT_LE(caged.largestDisplacement, std::sqrt(2.0) * g * (1.0 + 1e-6));
}

TEST(FiniteGapTest, RefusesADistanceWithoutGapsOrBeyondTheStep) {
    JammingParameters parameters = finiteGapTest();
    EXPECT_NO_THROW(JammingTest{parameters});
    parameters.unjammingDistance = 20.0; // beyond Delta = 10: no motion could reach it
    EXPECT_THROW(JammingTest{parameters}, std::invalid_argument);
    parameters.unjammingDistance = 1.0;
    parameters.useGaps = false;
    EXPECT_THROW(JammingTest{parameters}, std::invalid_argument);
}

TEST(JammingCategories, AlignedSuperballLatticeRotatesAtFirstOrderOnly) {
    // p = 1.5 face to face: the normals pass through the centres, so every rotation is a flex;
    // whether it is blocked is a question of curvature (second order).
    const RigidityNetwork network = networkOf(readTextPacking(kData + "/sc-lattice-p1.5.txt"));
    ASSERT_TRUE(network.rotations);
    for (const JammingCategory category : {JammingCategory::Local, JammingCategory::Collective}) {
        const JammingResult result = test(network, category);
        EXPECT_EQ(result.verdict, FirstOrderVerdict::Undecided) << static_cast<int>(category);
        EXPECT_FALSE(result.opening);
        ASSERT_TRUE(result.flex);
        EXPECT_EQ(result.flex->rotation.size(), 125u);
        EXPECT_TRUE(result.freed.empty());
    }
    // Face centres of p > 1 are flat on both sides: the gaps close faster than second order
    // (docs/jamming.md §6.3).
    const JammingResult collective = test(network, JammingCategory::Collective);
    ASSERT_TRUE(collective.secondOrder);
    EXPECT_EQ(collective.secondOrder->verdict, SecondOrderVerdict::SingularCurvature);
}

TEST(JammingCategories, AnOpeningFreesASphereButLeavesASlidingSuperballUndecided) {
    // Simple cubic, particle 5 = (0, 1, 1) without its contact with 21 = (1, 1, 1): moving along
    // +x opens its -x contact while its 4 side contacts slide, and 21 likewise along -x.
    // Spheres: both freed. Aligned p = 1.5 superballs: their side contacts may close at second
    // order, so first order cannot tell.
    Packing packing = simpleCubic(4);
    const int loose = 5;
    for (const double p : {1.0, 1.5}) {
        packing.shapeSpec = sbpack::ShapeSpec::superball(p);
        const RigidityNetwork network = backboneNetwork(
            packing, withoutPlusXContacts(ContactNetwork({}).compute(packing), loose));
        const JammingResult local = test(network, JammingCategory::Local);
        ASSERT_TRUE(local.opening) << "p " << p;
        EXPECT_GT(local.opening->displacement[loose].x(), 0.5);
        if (p == 1.0) {
            EXPECT_EQ(local.verdict, FirstOrderVerdict::Unjammed);
            EXPECT_EQ(local.freed, (std::vector<int>{loose, 21}));
        } else {
            EXPECT_EQ(local.verdict, FirstOrderVerdict::Undecided);
            EXPECT_TRUE(local.freed.empty());
        }
    }
}

TEST(JammingCategories, GordansAlternativeOpensEveryContactWhereNoSelfStressExists) {
    // data/ordered-p1.2-40.h5 as sbgen left it (P = 1e12, the jam check's network): hypostatic,
    // and at the finite growth rate without any self-stress (docs/jamming.md §6.6). Gordan: then
    // a first-order motion opens every contact; the shortcut finds it, the exact self-stress
    // program (the other alternative, an independent method) finds nothing to balance.
    const Packing packing = readPacking(kData + "/ordered-p1.2-40.h5");
    const RigidityNetwork network =
        backboneNetwork(packing, checkJam(packing, *packing.reducedPressure).contacts);
    const SelfStress stress = findSelfStress(network, 1e-6, {}, SelfStressProgram::Exact);
    EXPECT_TRUE(stress.forces.size() == 0);
    for (const JammingCategory category : {JammingCategory::Collective, JammingCategory::Strict}) {
        const JammingResult result = test(network, category);
        EXPECT_TRUE(result.opensEveryContact);
        EXPECT_EQ(result.verdict, FirstOrderVerdict::Unjammed);
        EXPECT_EQ(result.freed, network.backbone);
        ASSERT_TRUE(result.opening && result.flex);
        EXPECT_GT(result.opening->gapChange.minCoeff(), 1e-6);
        EXPECT_LT(result.flex->gapChange.cwiseAbs().maxCoeff(), 1e-9);
        EXPECT_FALSE(result.secondOrder); // decided at first order
        // Without the shortcut the opening program finds an opening too (one that may slide
        // closed contacts: its verdict can stay undecided), never a jammed network.
        JammingParameters programs;
        programs.gordanShortcut = false;
        const JammingResult baseline = test(network, category, programs);
        EXPECT_FALSE(baseline.opensEveryContact);
        EXPECT_TRUE(baseline.opening);
        EXPECT_NE(baseline.verdict, FirstOrderVerdict::Jammed);
    }
    // The least-norm opening opens every contact alike (A^T dq = 1, scaled), and the flexes
    // number the Maxwell deficit, as the second order's rank-revealing QR counts them.
    const DegreesOfFreedom dof = degreesOfFreedom(network, JammingCategory::Collective);
    const Eigen::SparseMatrix<double> a = rigidityMatrix(network, JammingCategory::Collective);
    const auto motions = gordanMotions(a, dof, 0, 1);
    ASSERT_TRUE(motions);
    const Eigen::VectorXd ds = a.transpose() * motions->opening;
    EXPECT_LT(ds.maxCoeff() - ds.minCoeff(), 1e-7 * ds.maxCoeff()); // 5e-9 measured
    const SecondOrderResult rank = SecondOrderTest({}).compute(network);
    EXPECT_EQ(rank.selfStresses, 0);
    EXPECT_EQ(rank.floppyModes, test(network, JammingCategory::Collective).isostaticDeficit);
    // Strict from the collective's opening (a motion of the fixed box) answers as its own test.
    const JammingResult collective = test(network, JammingCategory::Collective);
    const JammingResult strict = JammingTest::strictFromCollective(collective, network);
    const JammingResult direct = test(network, JammingCategory::Strict);
    EXPECT_EQ(strict.category, JammingCategory::Strict);
    EXPECT_EQ(strict.verdict, direct.verdict);
    EXPECT_EQ(strict.freed, direct.freed);
    EXPECT_EQ(strict.isostaticDeficit, direct.isostaticDeficit);
    EXPECT_THROW(JammingTest::strictFromCollective(test(network, JammingCategory::Local), network),
                 std::invalid_argument);
    // More contacts than degrees of freedom (fcc): the other alternative, no shortcut.
    const RigidityNetwork fcc = networkOf(readTextPacking(kData + "/fcc-spheres.txt"));
    EXPECT_FALSE(gordanMotions(rigidityMatrix(fcc, JammingCategory::Collective),
                               degreesOfFreedom(fcc, JammingCategory::Collective), 0, 1));
}

TEST(JammingTest, RejectsInvalidParametersAndAnEmptyBackbone) {
    const auto with = [](double maxStep, double motionTolerance) {
        JammingParameters parameters;
        parameters.maxStep = maxStep;
        parameters.motionTolerance = motionTolerance;
        return parameters;
    };
    EXPECT_THROW(JammingTest(with(0.0, 1e-6)), std::invalid_argument);
    EXPECT_THROW(JammingTest(with(INFINITY, 1e-6)), std::invalid_argument);
    EXPECT_THROW(JammingTest(with(1.0, 1.0)), std::invalid_argument);
    EXPECT_THROW(JammingTest(with(1.0, 1e-8)), std::invalid_argument); // the solver's 1e-9
    EXPECT_NO_THROW(JammingTest(with(1e-9, 1e-6)));
    RigidityNetwork empty;
    empty.packingSize = 3;
    EXPECT_THROW(JammingTest({}).compute(empty, JammingCategory::Collective),
                 std::invalid_argument);
    const Packing packing = simpleCubic(3);
    ContactResult wrong = ContactNetwork({}).compute(simpleCubic(4));
    EXPECT_THROW(backboneNetwork(packing, wrong), std::invalid_argument);
}

TEST(JammingCategories, MrjSpheresAreLocallyJammedWhereTheJamChecksHemisphereTestSaysSo) {
    // The jam check's network (its tolerance at the recorded pressure, 1e-10 D: sbanalyze's
    // default). Collective and strict: bench/bench_jamming (minutes; docs/jamming.md §5).
    const Packing packing = readPacking(kData + "/mrj-spheres-5000.h5");
    const RigidityNetwork network =
        backboneNetwork(packing, checkJam(packing, *packing.reducedPressure).contacts);
    const JammingResult local = test(network, JammingCategory::Local);
    std::vector<std::vector<Vector3d>> normals(packing.size());
    for (const RigidContact& c : network.contacts) {
        normals[network.backbone[c.i]].push_back(c.normal);
        normals[network.backbone[c.j]].push_back(-c.normal);
    }
    std::vector<int> untrapped;
    for (const int k : network.backbone)
        if (!isLocallyTrapped(normals[k])) untrapped.push_back(k);
    EXPECT_EQ(untrapped.size(), 5u); // docs/design.md §3, "Jam check"
    EXPECT_EQ(local.freed, untrapped);
    EXPECT_LT(local.seconds, 30.0);
}

/// docs/mixtures.md: two kinds of sphere on `basis` (units of the lattice constant a) of cells^3
/// cubic cells, semi-axis rA on the first basis point, rB on the others.
Packing binaryLattice(double a, int cells, const std::vector<Vector3d>& basis, double rA,
                      double rB) {
    Packing packing = lattices::cubicCrystal(cells, a, basis, Vector3d::Zero());
    packing.semiAxis = std::max(rA, rB);
    for (std::size_t i = 0; i < packing.size(); ++i)
        packing.semiAxes.push_back(i % basis.size() == 0 ? rA : rB);
    return packing;
}

// Caesium chloride of two sizes whose unlike neighbours touch (a = 1.1, R_A = 0.5, R_B = a sqrt 3
// / 2 - R_A) and like ones do not: the contact network of bcc, with its normals, so its answer:
// locally but not collectively jammed. Read at one size, the small spheres' contacts are lost.
TEST(JammingCategories, CaesiumChlorideOfTwoSizesIsAsBodyCentredCubic) {
    const double a = 1.1, rB = a * std::sqrt(3.0) / 2.0 - 0.5;
    const Packing packing = binaryLattice(a, 3, lattices::kBodyCentred, 0.5, rB);
    const RigidityNetwork network = networkOf(packing);
    EXPECT_EQ(network.contacts.size(), 4u * packing.size());
    EXPECT_EQ(test(network, JammingCategory::Local).verdict, FirstOrderVerdict::Jammed);
    EXPECT_EQ(test(network, JammingCategory::Collective).verdict, FirstOrderVerdict::Unjammed);
    EXPECT_EQ(test(network, JammingCategory::Strict).verdict, FirstOrderVerdict::Unjammed);
}

/// Rock salt: fcc of unit spheres (a = sqrt 2) with spheres of semi-axis rB in its octahedral
/// holes, which touch their 6 neighbours at rB = (sqrt 2 - 1) / 2.
Packing rockSalt(double rB) {
    const double a = std::sqrt(2.0);
    std::vector<Vector3d> basis = lattices::kFaceCentred;
    for (const Vector3d& b : lattices::kFaceCentred)
        basis.push_back(b + Vector3d(0.5, 0.0, 0.0));
    Packing packing = lattices::cubicCrystal(2, a, basis, Vector3d::Zero());
    for (std::size_t i = 0; i < packing.size(); ++i)
        packing.semiAxes.push_back(i % 8 < 4 ? 0.5 : rB);
    return packing;
}

// Rock salt's small spheres in contact are strictly jammed with the fcc; 3 % smaller, they rattle
// (half the particles) and the fcc backbone alone is strictly jammed: a jammed packing whose
// rattler fraction is a property of the mixture, not of a packing still compressing.
TEST(JammingCategories, RockSaltIsStrictlyJammedWithOrWithoutItsSmallSpheres) {
    const double touching = (std::sqrt(2.0) - 1.0) / 2.0;
    for (const double rB : {touching, 0.97 * touching}) {
        const Packing packing = rockSalt(rB);
        const ContactResult contacts = ContactNetwork({}).compute(packing);
        const RigidityNetwork network = backboneNetwork(packing, contacts);
        EXPECT_EQ(network.backbone.size(), rB == touching ? packing.size() : packing.size() / 2);
        EXPECT_EQ(network.contacts.size(), (rB == touching ? 12u : 6u) * packing.size() / 2);
        for (const JammingCategory category :
             {JammingCategory::Local, JammingCategory::Collective, JammingCategory::Strict})
            EXPECT_EQ(test(network, category).verdict, FirstOrderVerdict::Jammed)
                << "R_B = " << rB << ", category " << static_cast<int>(category);
        // The jam check of a mixture counts the backbone's contacts, not its rattlers: jammed
        // at either size (a limit of 10 % rattlers would call the second not jammed).
        const JamCheck check = checkJam(packing, 1e12);
        EXPECT_TRUE(check.jammed) << check.verdict;
        EXPECT_EQ(check.backboneContacts, static_cast<int>(network.contacts.size()));
    }
}

} // namespace
} // namespace sbpack

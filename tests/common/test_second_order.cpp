// The second-order jamming test (docs/jamming.md §6): the Hessian of the contact gap against
// finite differences of the exact signed distance, and known answers: a CsCl pair of aligned
// superballs held at their body diagonals (jammed at second order for p < 1, not for p > 1, the
// smallest stiffness in closed form), fcc spheres jammed, the simple-cubic row slide not rescued;
// the least-residual self-stress of a perturbed network (docs/jamming.md §6.6): exact where the
// network is hyperstatic (fcc), linear in the perturbation where its self-stress is not generic
// (diamond).

#include "contacts/contact_network.hpp"
#include "io/text_io.hpp"
#include "jamming/gap_hessian.hpp"
#include "jamming/jamming_test.hpp"
#include "pair/pair_geometry.hpp"
#include "random/random.hpp"

#include "order_lattices.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbpack {
namespace {

using Vector12d = Eigen::Matrix<double, 12, 1>;

/// A pair of unit-diameter superballs moved by q = (dr_A, dtheta_A, dr_B, dtheta_B), the
/// rotations R = exp([dtheta]) R0 as gapHessian's.
struct MovedPair {
    Superball shape;
    Matrix3d rotationA, rotationB;
    Vector3d displacement;

    double signedDistanceAt(const Vector12d& q) const {
        const auto turned = [](const Matrix3d& r, const Vector3d& theta) {
            const double angle = theta.norm();
            return angle == 0.0 ? r : Matrix3d(Eigen::AngleAxisd(angle, theta / angle) * r);
        };
        return signedDistance(SuperballPair{shape, turned(rotationA, q.segment<3>(3)),
                                            turned(rotationB, q.segment<3>(9)),
                                            displacement + q.segment<3>(6) - q.segment<3>(0)})
            .signedDistance;
    }

    /// Central second differences with step h, Richardson-extrapolated from h and h / 2: error
    /// O(h^4) plus the distance's rounding (1e-16 D) / h^2.
    Matrix12d finiteDifferenceHessian(double h) const {
        const auto at = [&](double step) {
            Matrix12d hessian;
            const double s0 = signedDistanceAt(Vector12d::Zero());
            for (int a = 0; a < 12; ++a)
                for (int b = a; b < 12; ++b) {
                    const Vector12d ea = step * Vector12d::Unit(a), eb = step * Vector12d::Unit(b);
                    hessian(a, b) = hessian(b, a) =
                        a == b ? (signedDistanceAt(ea) - 2.0 * s0 + signedDistanceAt(-ea)) /
                                     (step * step)
                               : (signedDistanceAt(ea + eb) - signedDistanceAt(ea - eb) -
                                  signedDistanceAt(eb - ea) + signedDistanceAt(-ea - eb)) /
                                     (4.0 * step * step);
                }
            return hessian;
        };
        return (4.0 * at(0.5 * h) - at(h)) / 3.0;
    }
};

TEST(GapHessian, EqualsFiniteDifferencesOfTheExactSignedDistance) {
    // Random orientations and directions at a gap of 1e-3 D. Left out (counted): pairs whose
    // relative curvature W_A + W_B has an eigenvalue below 1 / D (two nearly flat faces of
    // near-cubes: Hess s ~ 1 / W varies on the step's scale) or a surface curvature above
    // 100 / D (contact points near an edge of p < 1, where it diverges): the finite differences,
    // not the formula, lose their accuracy there (radius of curvature < 10 steps).
    Random random(11);
    for (const double p : {0.6, 1.0, 1.5, 3.0, 10.0}) {
        const Superball shape(p, 0.5);
        int accepted = 0, excluded = 0;
        while (accepted < 10 && excluded < 100) {
            MovedPair pair{shape, random.rotation().toRotationMatrix(),
                           random.rotation().toRotationMatrix(), Vector3d::Zero()};
            const Vector3d u = random.normalVector().normalized();
            const double touching =
                1.0 /
                scaleFactor(SuperballPair{shape, pair.rotationA, pair.rotationB, u}).scaleFactor;
            pair.displacement = (touching + 1e-3) * u;
            const SignedDistanceResult s = signedDistance(
                SuperballPair{shape, pair.rotationA, pair.rotationB, pair.displacement});
            const ContactCurvature contact =
                contactCurvature(shape, pair.rotationA, pair.rotationB, pair.displacement, s.normal,
                                 s.signedDistance);
            const Eigen::Matrix<double, 3, 2> basis = tangentBasis(s.normal);
            const Eigen::Matrix2d relative =
                basis.transpose() * (contact.curvatureA + contact.curvatureB) * basis;
            const double largest = std::max(contact.curvatureA.norm(), contact.curvatureB.norm());
            if (Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(relative).eigenvalues()[0] < 1.0 ||
                largest > 100.0) {
                ++excluded;
                continue;
            }
            const Matrix12d analytic = gapHessian(contact);
            const Matrix12d numeric = pair.finiteDifferenceHessian(1e-3);
            EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(),
                      1e-6 * analytic.cwiseAbs().maxCoeff())
                << "p " << p << " pair " << accepted;
            ++accepted;
        }
        EXPECT_EQ(accepted, 10) << "p " << p << ": " << excluded << " excluded";
    }
}

TEST(GapHessian, SpheresTranslateByTheTangentialProjectionOverTheDistance) {
    // Hess s = (I - n n^T) / |d| on dr_B, and rotations change nothing.
    const Superball sphere(1.0, 0.5);
    const Vector3d d(0.3, -1.0, 0.4);
    const ContactCurvature contact = contactCurvature(
        sphere, Matrix3d::Identity(), Matrix3d::Identity(), d, d.normalized(), d.norm() - 1.0);
    const Matrix12d hessian = gapHessian(contact);
    const Matrix3d expected =
        (Matrix3d::Identity() - d.normalized() * d.normalized().transpose()) / d.norm();
    EXPECT_LT((hessian.block<3, 3>(6, 6) - expected).norm(), 1e-14);
    EXPECT_LT((hessian.block<3, 3>(0, 6) + expected).norm(), 1e-14);
    const double rotations = hessian.middleCols<3>(3).norm() + hessian.middleCols<3>(9).norm();
    EXPECT_LT(rotations, 1e-14);
}

/// Two aligned superballs of diameter 1 in a cubic box of edge a (CsCl): particle 1 at
/// (a / 2)(1, 1, 1) touches particle 0 through all 8 of its images, along the body diagonals
/// n = s / sqrt 3, s in {-1, 1}^3, at distance 2 rho, rho = (1/2) 3^{1/2 - 1/(2p)} the radius
/// along a diagonal: a = 4 rho / sqrt 3. The normals pass through the centres, so every rotation
/// is a flex, and the 8 directions hold the relative translation at first order.
RigidityNetwork diagonalPair(double p) {
    const Superball shape(p, 0.5);
    const double rho = 0.5 * std::pow(3.0, 0.5 - 0.5 / p), a = 4.0 * rho / std::sqrt(3.0);
    RigidityNetwork network;
    network.backbone = {0, 1};
    network.packingSize = 2;
    network.rotations = true;
    network.boxLength = a;
    const Vector3d inBox = 0.5 * a * Vector3d::Ones();
    for (int k = 0; k < 8; ++k) {
        const Vector3d s(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0);
        const Vector3d d = 0.5 * a * s, n = s / std::sqrt(3.0);
        const ContactCurvature c =
            contactCurvature(shape, Matrix3d::Identity(), Matrix3d::Identity(), d, n, 0.0);
        network.contacts.push_back(
            {0, 1, n, c.leverA, c.leverB, d - inBox, 0.0, c.curvatureA, c.curvatureB});
    }
    return network;
}

TEST(SecondOrder, SuperballsHeldAtTheirDiagonalsAreJammedOnlyWhereFlatterThanTheirCircle) {
    // docs/jamming.md §6.4: at a diagonal point both curvatures are kappa = (2p - 1) / rho, and
    // with f = 1 on the 8 contacts the stiffness on the rotations is
    //   (1 - kappa rho) (16/3) [(rho / 2)|dtheta_0 + dtheta_1|^2 + |dtheta_0 - dtheta_1|^2 / 2
    //   kappa]
    // (eigenvalues (16/3)(1 - kappa rho) rho on dtheta_0 = dtheta_1, (16/3)(1 - kappa rho) / kappa
    // on dtheta_0 = -dtheta_1, rho < 1 / kappa iff p < 1), so its smallest is (32/3)(1 - p) rho,
    // the two rotating alike: p < 1 (a face centre, flatter than the circle of radius rho)
    // jammed, p > 1 (a rounded corner) not.
    for (const double p : {0.85, 1.5, 10.0}) {
        const RigidityNetwork network = diagonalPair(p);
        const double rho = 0.5 * std::pow(3.0, 0.5 - 0.5 / p);
        const double expected = 32.0 / 3.0 * (1.0 - p) * rho;
        const SecondOrderResult given =
            SecondOrderTest({}).compute(network, Eigen::VectorXd::Ones(8));
        EXPECT_NEAR(given.smallestStiffness, expected, 1e-6 * std::abs(expected)) << "p " << p;
        EXPECT_LT(given.stress.balanceResidual, 1e-14);
        EXPECT_EQ(given.floppyModes, 6); // the two rotations
        EXPECT_EQ(given.testedModes, 6);
        EXPECT_EQ(given.selfStresses, 5); // 8 contacts, 3 force equations
        EXPECT_LT(given.flexResidual, 1e-6);
        const SecondOrderVerdict verdict =
            p < 1.0 ? SecondOrderVerdict::Jammed : SecondOrderVerdict::NotJammed;
        EXPECT_EQ(given.verdict, verdict) << "p " << p;
        // First order leaves the rotations; the program's self-stress loads all 8 contacts.
        const JammingResult result = JammingTest({}).compute(network, JammingCategory::Collective);
        EXPECT_EQ(result.verdict, FirstOrderVerdict::Undecided);
        ASSERT_TRUE(result.secondOrder);
        EXPECT_FALSE(result.secondOrder->forcesGiven);
        EXPECT_EQ(result.secondOrder->stress.loadedContacts, 8);
        EXPECT_EQ(result.secondOrder->verdict, verdict) << "p " << p;
        EXPECT_EQ(result.jammed(), p < 1.0);
    }
}

// Given forces on a network with no self-stress (dim ker A = 0) approximate none: the verdict is
// "no self-stress", not the stiffness under them (the reproduction's p = 1.1 packings with
// sbgen's stored forces were called "not jammed" so; bench/RESULTS.md).
TEST(SecondOrder, GivenForcesWithoutAnySelfStressTestNothing) {
    RigidityNetwork network = diagonalPair(1.5);
    network.contacts.resize(1); // one contact: A has full column rank
    const SecondOrderResult given = SecondOrderTest({}).compute(network, Eigen::VectorXd::Ones(1));
    EXPECT_EQ(given.selfStresses, 0);
    EXPECT_TRUE(given.forcesGiven);
    EXPECT_EQ(given.verdict, SecondOrderVerdict::NoSelfStress);
}

RigidityNetwork networkOf(const Packing& packing) {
    return backboneNetwork(packing, ContactNetwork({}).compute(packing));
}

TEST(SecondOrder, FaceCentredCubicSpheresStayJammed) {
    const RigidityNetwork network =
        networkOf(readTextPacking(std::string(SBPACK_DATA_DIR) + "/fcc-spheres.txt"));
    const JammingResult first = JammingTest({}).compute(network, JammingCategory::Collective);
    EXPECT_TRUE(first.jammed());
    EXPECT_FALSE(first.secondOrder); // first order decided
    const SecondOrderResult second = SecondOrderTest({}).compute(network);
    EXPECT_EQ(second.verdict, SecondOrderVerdict::Jammed);
    EXPECT_EQ(second.floppyModes, 0);
    EXPECT_EQ(second.selfStresses, 648 - 321);
    EXPECT_EQ(second.stress.loadedContacts, 648);
    EXPECT_LT(second.stress.balanceResidual, 1e-8);
}

TEST(SecondOrder, SimpleCubicRowSlideIsNotRescued) {
    // 4^3 spheres: 48 rows slide (45 floppy modes beyond the translations), each row a closed
    // loop of contacts with its own self-stress (48). Sliding a row opens its side contacts at
    // second order by |u|^2 / 2D each: the stiffness of every loaded self-stress is negative.
    const RigidityNetwork network =
        networkOf(lattices::cubicCrystal(4, 1.0, lattices::kSimpleCubic));
    const SecondOrderResult result = SecondOrderTest({}).compute(network);
    EXPECT_EQ(result.floppyModes, 45);
    EXPECT_EQ(result.selfStresses, 48);
    EXPECT_EQ(result.verdict, SecondOrderVerdict::NotJammed);
    EXPECT_LT(result.smallestStiffness, 0.0);
    EXPECT_LT(result.flexResidual, 1e-4);
    EXPECT_FALSE(JammingTest({}).compute(network, JammingCategory::Collective).jammed());
}

/// Spheres of diameter 1 on the diamond lattice (fcc and fcc + a (1, 1, 1) / 4, a = 4 / sqrt 3:
/// nearest neighbours touch), 3^3 cells, 216 spheres, each with 4 contacts along tetrahedral
/// directions, displaced uniformly in [-h, h]^3; the network at 1e-3 D, far above the
/// displacements' 2 sqrt 3 h and far below the second neighbours' gap (0.63 D).
RigidityNetwork perturbedDiamond(double h) {
    std::vector<Vector3d> basis = lattices::kFaceCentred;
    for (const Vector3d& b : lattices::kFaceCentred)
        basis.push_back(b + Vector3d::Constant(0.25));
    const Packing diamond = lattices::cubicCrystal(3, 4.0 / std::sqrt(3.0), basis);
    return backboneNetwork(lattices::displaced(diamond, h, 7),
                           ContactNetwork({1e-3}).compute(lattices::displaced(diamond, h, 7)));
}

TEST(LeastResidualSelfStress, IsLinearInThePerturbationWhereTheSelfStressIsNotGeneric) {
    // docs/jamming.md §6.6: diamond is hypostatic (2N contacts, 3N - 3 motions) yet stressed,
    // f = 1 (four tetrahedral unit vectors sum to 0); displaced by h its A has full column rank,
    // so no exact self-stress remains and the least residual is rho ~ h |dA / dh| (Eq. (L)).
    const SecondOrderParameters parameters;
    const auto rhoAt = [&](double h) {
        const RigidityNetwork network = perturbedDiamond(h);
        EXPECT_EQ(network.contacts.size(), 432u) << "h " << h;
        const SelfStress stress = findSelfStress(
            network, parameters.loadTolerance, parameters.solver, SelfStressProgram::LeastResidual);
        EXPECT_NEAR(stress.forces.mean(), 1.0, 1e-12);
        EXPECT_GE(stress.forces.minCoeff(), 0.0);
        return stress.balanceResidual;
    };
    EXPECT_LT(rhoAt(0.0), 1e-13);
    EXPECT_TRUE(findSelfStress(perturbedDiamond(1e-6), parameters.loadTolerance,
                               parameters.solver)
                    .forces.size() == 0); // the exact program: f = 0 only
    const double unit = rhoAt(1e-6) / 1e-6;
    EXPECT_GT(unit, 0.1);
    EXPECT_LT(unit, 10.0);
    for (const double h : {1e-8, 1e-4}) {
        EXPECT_GT(rhoAt(h) / h, unit / 3.0) << "h " << h;
        EXPECT_LT(rhoAt(h) / h, unit * 3.0) << "h " << h;
    }
}

TEST(LeastResidualSelfStress, StaysExactWhereTheNetworkIsHyperstatic) {
    // fcc: 648 contacts on 321 motions leave 327 self-stresses, and a perturbation of size h
    // moves the uniform one by O(h), still positive: rho stays at rounding (docs/jamming.md §6.6).
    const Packing fcc = readTextPacking(std::string(SBPACK_DATA_DIR) + "/fcc-spheres.txt");
    const SecondOrderParameters parameters;
    for (const double h : {0.0, 1e-6, 1e-4}) {
        const Packing moved = lattices::displaced(fcc, h, 3);
        const RigidityNetwork network =
            backboneNetwork(moved, ContactNetwork({1e-3}).compute(moved));
        ASSERT_EQ(network.contacts.size(), 648u);
        const SelfStress stress = findSelfStress(
            network, parameters.loadTolerance, parameters.solver, SelfStressProgram::LeastResidual);
        EXPECT_LT(stress.balanceResidual, 1e-12) << "h " << h;
        EXPECT_EQ(stress.loadedContacts, 648) << "h " << h;
    }
}

TEST(SecondOrder, TestsALeastResidualSelfStressOnlyWithinItsAcceptance) {
    // docs/jamming.md §6.6: the program's least-residual forces are tested where rho is at most
    // residualAcceptance (1e-6), else NoSelfStress. Diamond displaced by 1e-4 D (rho ~ 8e-4):
    // refused; by 1e-9 D (rho ~ 8e-9): tested, and spheres' flexes open at second order.
    SecondOrderParameters parameters;
    parameters.selfStress = SelfStressProgram::LeastResidual;
    const SecondOrderTest test(parameters);
    const SecondOrderResult far = test.compute(perturbedDiamond(1e-4));
    EXPECT_EQ(far.verdict, SecondOrderVerdict::NoSelfStress);
    EXPECT_GT(far.stress.balanceResidual, parameters.residualAcceptance);
    EXPECT_EQ(far.stress.forces.size(), 432); // reported all the same
    const SecondOrderResult near = test.compute(perturbedDiamond(1e-9));
    EXPECT_LT(near.stress.balanceResidual, parameters.residualAcceptance);
    EXPECT_EQ(near.verdict, SecondOrderVerdict::NotJammed);
    EXPECT_EQ(near.curvatureRadius, 0.0); // no positive stiffness to bound Eq. (R) with
    // fcc displaced by 1e-6 D keeps an exact self-stress: first-order rigid, jammed.
    const Packing fcc = lattices::displaced(
        readTextPacking(std::string(SBPACK_DATA_DIR) + "/fcc-spheres.txt"), 1e-6, 3);
    const SecondOrderResult rigid =
        test.compute(backboneNetwork(fcc, ContactNetwork({1e-3}).compute(fcc)));
    EXPECT_EQ(rigid.verdict, SecondOrderVerdict::Jammed);
    EXPECT_LT(rigid.stress.balanceResidual, 1e-12);
    EXPECT_LT(rigid.curvatureRadius, 1e-12);
}

TEST(SecondOrder, RejectsBadForcesAndTolerances) {
    const RigidityNetwork network = diagonalPair(1.5);
    EXPECT_THROW(SecondOrderTest({}).compute(network, Eigen::VectorXd::Ones(7)),
                 std::invalid_argument);
    EXPECT_THROW(SecondOrderTest({}).compute(network, -Eigen::VectorXd::Ones(8)),
                 std::invalid_argument);
    EXPECT_THROW(SecondOrderTest({}).compute(network, Eigen::VectorXd::Zero(8)),
                 std::invalid_argument);
    SecondOrderParameters bad;
    bad.loadTolerance = 0.0;
    EXPECT_THROW(SecondOrderTest{bad}, std::invalid_argument);
    bad = {};
    bad.residualAcceptance = 1.0;
    EXPECT_THROW(SecondOrderTest{bad}, std::invalid_argument);
    JammingParameters parameters;
    parameters.secondOrder.stiffnessTolerance = 2.0;
    EXPECT_THROW(JammingTest{parameters}, std::invalid_argument);
}

} // namespace
} // namespace sbpack

// The superball predictor's exact layer (shapes/superball/warm_distance.hpp) on its own, against
// known answers: spheres (s = |d| - D), aligned near-cubes face to face (s = the faces'
// separation), the invariance of s under rigid motions, the cubic group and the order of the
// pair, warm starts that meet the cold start and the robust solver of common/pair, witness points
// on both surfaces, every plane a lower bound, lower bounds only where asked for, and the optimal
// normal's rate against finite differences.
#include "shapes/superball/warm_distance.hpp"

#include "geometry/superball.hpp"
#include "shapes/first_contact_limits.hpp"
#include "shapes/pair_motion.hpp"
#include "superball_pairs.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace sbpack {
namespace {

using superball::atNormal;
using superball::exactSignedDistance;
using superball::PairRates;
using superball::WarmNewton;
using testing::pairNearContact;

const std::vector<double> kExponents = {0.75, 1.0, 1.2, 1.5, 3.0, 10.0};

/// s of the pair from `normal` (zero: the centre line), asked exact (no lower bound serves).
WarmNewton evaluated(const SuperballPair& pair, Vector3d normal = Vector3d::Zero(),
                     const PairRates* rates = nullptr) {
    PredictorStats stats;
    return exactSignedDistance(pair, normal, kNoContact, SuperballPredictorLimits{}, stats, rates);
}

double distanceOf(const SuperballPair& pair) {
    return evaluated(pair).result.signedDistance;
}

/// The 24 rotations of the cube (signed permutation matrices of determinant 1): each maps a
/// superball onto itself.
std::vector<Matrix3d> cubicRotations() {
    std::vector<Matrix3d> rotations;
    std::array<int, 3> axes{0, 1, 2};
    do {
        for (int signs = 0; signs < 8; ++signs) {
            Matrix3d s = Matrix3d::Zero();
            for (int row = 0; row < 3; ++row)
                s(row, axes[row]) = (signs >> row) & 1 ? -1.0 : 1.0;
            if (s.determinant() > 0.0) rotations.push_back(s);
        }
    } while (std::next_permutation(axes.begin(), axes.end()));
    return rotations;
}

TEST(WarmDistance, SpheresAreTheCentreDistanceLessOneDiameter) {
    Random random(3);
    for (int trial = 0; trial < 200; ++trial) {
        const double length = 0.99 + 1.01 * random.uniform(); // overlaps down to 0.01 D
        const Vector3d d = length * random.normalVector().normalized();
        const SuperballPair pair{Superball(1.0, 0.5), random.rotation().toRotationMatrix(),
                                 random.rotation().toRotationMatrix(), d};
        for (const Vector3d& start :
             {Vector3d(Vector3d::Zero()), Vector3d(random.normalVector().normalized())}) {
            const WarmNewton w = evaluated(pair, start);
            EXPECT_TRUE(w.exact && w.converged);
            EXPECT_NEAR(w.result.signedDistance, length - 1.0, 1e-15) << "|d| " << length;
            EXPECT_NEAR((w.result.normal - d / length).norm(), 0.0, 1e-12);
        }
    }
}

// p = 10: the normal is e_x, whose support point is the face centre, and sideways offsets of
// 0.05 D move the optimum by (0.05)^19 radians: s is the faces' separation to rounding, apart
// or overlapping, in any common orientation.
TEST(WarmDistance, AlignedNearCubesFaceToFaceAreTheFaceSeparation) {
    Random random(5);
    for (const double separation : {-1e-6, -1e-9, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.3})
        for (const double offset : {0.0, 0.05})
            for (int turn = 0; turn < 4; ++turn) {
                const Matrix3d q = turn == 0 ? Matrix3d(Matrix3d::Identity())
                                             : random.rotation().toRotationMatrix();
                const SuperballPair pair{Superball(10.0, 0.5), q, q,
                                         q * Vector3d(1.0 + separation, offset, -offset)};
                const WarmNewton w = evaluated(pair);
                EXPECT_NEAR(w.result.signedDistance, separation, 1e-14)
                    << "separation " << separation << " offset " << offset << " turn " << turn;
                EXPECT_NEAR((w.result.normal - q.col(0)).norm(), 0.0, 1e-9);
            }
}

TEST(WarmDistance, RigidMotionsSymmetriesAndTheOrderLeaveItUnchanged) {
    Random random(7);
    const std::vector<Matrix3d> cube = cubicRotations();
    ASSERT_EQ(cube.size(), 24u);
    for (const double p : kExponents)
        for (int trial = 0; trial < 40; ++trial) {
            const double stretch =
                trial % 4 == 0 ? -1e-6 : std::pow(10.0, -12.0 + 11.0 * trial / 40);
            const SuperballPair pair = pairNearContact(p, stretch, random);
            const double s = distanceOf(pair);
            const Matrix3d q = random.rotation().toRotationMatrix();
            const SuperballPair moved{pair.shape, q * pair.rotationA, q * pair.rotationB,
                                      q * pair.displacement};
            const SuperballPair symmetric{pair.shape, pair.rotationA * cube[trial % 24],
                                          pair.rotationB * cube[(7 * trial + 5) % 24],
                                          pair.displacement};
            const SuperballPair swapped{pair.shape, pair.rotationB, pair.rotationA,
                                        -pair.displacement};
            const double tolerance = 1e-13 * std::max(1.0, std::abs(s));
            EXPECT_NEAR(distanceOf(moved), s, tolerance) << "p " << p << " trial " << trial;
            EXPECT_NEAR(distanceOf(symmetric), s, tolerance) << "p " << p << " trial " << trial;
            EXPECT_NEAR(distanceOf(swapped), s, tolerance) << "p " << p << " trial " << trial;
        }
}

// The normal of a nearby configuration (moved by 1e-3 D, turned by 1e-3 rad) as the warm start,
// as the predictor's cached normal is: the same s as the cold start and the robust solver.
TEST(WarmDistance, WarmStartsMeetTheColdStartAndTheRobustSolver) {
    Random random(11);
    for (const double p : kExponents)
        for (int trial = 0; trial < 40; ++trial) {
            const double stretch = std::pow(10.0, -12.0 + 11.0 * trial / 40);
            const SuperballPair pair = pairNearContact(p, stretch, random);
            const Matrix3d turn =
                Eigen::AngleAxisd(1e-3, random.normalVector().normalized()).toRotationMatrix();
            const SuperballPair nearby{pair.shape, turn * pair.rotationA, pair.rotationB,
                                       pair.displacement + 1e-3 * random.normalVector()};
            const WarmNewton cold = evaluated(pair);
            const WarmNewton warm = evaluated(pair, evaluated(nearby).result.normal);
            const double robust = signedDistance(pair).signedDistance;
            EXPECT_NEAR(warm.result.signedDistance, cold.result.signedDistance, 1e-13)
                << "p " << p << " trial " << trial;
            EXPECT_NEAR(cold.result.signedDistance, robust, 1e-13)
                << "p " << p << " trial " << trial;
        }
}

// The answer's two support points lie on their bodies' surfaces (the gauge |x / R|_{2p} is 1),
// its normal is a unit vector and the points are s apart along it.
TEST(WarmDistance, WitnessPointsLieOnBothSurfaces) {
    Random random(13);
    for (const double p : kExponents)
        for (int trial = 0; trial < 40; ++trial) {
            const SuperballPair pair =
                pairNearContact(p, trial % 5 == 0 ? -1e-7 : 1e-3 * random.uniform(), random);
            const SignedDistanceResult r = evaluated(pair).result;
            const Superball& shape = pair.shape;
            EXPECT_NEAR(shape.gauge(pair.rotationA.transpose() * r.contactA), 1.0, 1e-12)
                << "p " << p << " trial " << trial;
            EXPECT_NEAR(shape.gauge(pair.rotationB.transpose() * (r.contactB - pair.displacement)),
                        1.0, 1e-12)
                << "p " << p << " trial " << trial;
            EXPECT_NEAR(r.normal.norm(), 1.0, 1e-15);
            EXPECT_NEAR(r.normal.dot(r.contactB - r.contactA), r.signedDistance, 1e-15);
        }
}

// s = max over unit n of the plane gap n.d - h_A(n) - h_B(n): no plane lies above it, and the
// answer's own plane is it.
TEST(WarmDistance, EveryPlaneIsALowerBound) {
    Random random(17);
    for (const double p : kExponents)
        for (int trial = 0; trial < 20; ++trial) {
            const SuperballPair pair = pairNearContact(p, 1e-2 * random.uniform(), random);
            const SignedDistanceResult r = evaluated(pair).result;
            EXPECT_NEAR(atNormal(pair, r.normal).signedDistance, r.signedDistance, 1e-15);
            for (int plane = 0; plane < 50; ++plane) {
                const Vector3d n = (r.normal + 0.1 * random.normalVector()).normalized();
                EXPECT_LE(atNormal(pair, n).signedDistance, r.signedDistance + 1e-15);
            }
        }
}

// Asked for a lower bound above `boundSuffices` only, an inexact answer is a plane above it and
// below s; near-cubes far apart take that way.
TEST(WarmDistance, ALowerBoundServesOnlyAboveTheBoundAskedFor) {
    Random random(19);
    const double bound = 1e-3;
    int lowerBounds = 0;
    for (const double p : kExponents)
        for (int trial = 0; trial < 40; ++trial) {
            const SuperballPair pair = pairNearContact(p, 0.01 + 0.3 * random.uniform(), random);
            Vector3d normal = Vector3d::Zero();
            PredictorStats stats;
            const WarmNewton w =
                exactSignedDistance(pair, normal, bound, SuperballPredictorLimits{}, stats);
            const double s = distanceOf(pair);
            if (w.exact) {
                EXPECT_NEAR(w.result.signedDistance, s, 1e-13) << "p " << p;
                continue;
            }
            ++lowerBounds;
            EXPECT_GT(w.result.signedDistance, bound) << "p " << p;
            EXPECT_LE(w.result.signedDistance, s + 1e-15) << "p " << p;
            EXPECT_EQ(normal, w.result.normal); // the cached normal is updated
        }
    EXPECT_GT(lowerBounds, 0);
}

/// The pair `tau` later along `rates` (orientations turned exactly, the size grown at the strain).
SuperballPair pairAfter(const SuperballPair& pair, const PairRates& rates, double tau) {
    auto turned = [tau](const Matrix3d& q, const Vector3d& omega) {
        return advancedOrientation(Quaterniond(q), omega, tau).toRotationMatrix();
    };
    return {Superball(pair.shape.p(), pair.shape.semiAxis() * std::exp(rates.strain * tau)),
            turned(pair.rotationA, rates.angularVelocityI),
            turned(pair.rotationB, rates.angularVelocityJ),
            pair.displacement + rates.velocity * tau};
}

TEST(WarmDistance, TheNormalRateIsTheOptimalNormalsDerivative) {
    Random random(23);
    for (const double p : {1.0, 1.2, 1.5})
        for (int trial = 0; trial < 20; ++trial) {
            const SuperballPair pair = pairNearContact(p, 1e-3, random);
            const PairRates rates{random.normalVector(), random.normalVector(),
                                  random.normalVector(), 0.01 * random.uniform()};
            const WarmNewton w = evaluated(pair, Vector3d::Zero(), &rates);
            ASSERT_TRUE(w.converged) << "p " << p << " trial " << trial;
            const double h = 1e-6;
            const Vector3d difference = (evaluated(pairAfter(pair, rates, h)).result.normal -
                                         evaluated(pairAfter(pair, rates, -h)).result.normal) /
                                        (2.0 * h);
            EXPECT_NEAR((w.normalRate - difference).norm(), 0.0,
                        1e-6 * std::max(1.0, difference.norm()))
                << "p " << p << " trial " << trial;
        }
}

} // namespace
} // namespace sbpack

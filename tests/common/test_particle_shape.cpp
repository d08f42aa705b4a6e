// The shape description (common/geometry/particle_shape, docs/architecture.md "What a new shape
// needs"): a family's identity by name, and a body of it whose geometry is the superball's.
#include "geometry/particle_shape.hpp"
#include "geometry/shape_families.hpp"
#include "jamming/gap_hessian.hpp"
#include "message_of.hpp"
#include "pair/pair_geometry.hpp"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {
namespace {

TEST(ShapeSpec, TheSuperballIsNamedWithItsExponent) {
    const ShapeSpec shape = ShapeSpec::superball(1.5);
    EXPECT_EQ(shape.info().name, "superball");
    ASSERT_EQ(shape.info().parameters.size(), 1u);
    EXPECT_EQ(shape.info().parameters[0].name, "p");
    EXPECT_EQ(shape.values(), std::vector<double>{1.5});
    EXPECT_EQ(shape.describe(), "p = 1.5");
    EXPECT_EQ(ShapeSpec::fromValues("superball", shape.values()), shape);
    EXPECT_EQ(shapeFamilies().front().name, "superball"); // a file without a family holds these
    EXPECT_EQ(findShapeFamily("superball"), &shapeFamilies().front());
    EXPECT_EQ(findShapeFamily("ellipsoid"), nullptr);
}

TEST(ShapeSpec, ParametersOutsideTheFamilyAreNamed) {
    EXPECT_FALSE(ShapeSpec::superball(0.5).problem()); // the octahedron
    EXPECT_FALSE(ShapeSpec::superball(1000.0).problem());
    EXPECT_EQ(ShapeSpec::superball(0.4).problem().value_or(""),
              "p = 0.4 (must be finite and >= 0.5)");
    EXPECT_EQ(ShapeSpec::superball(NAN).problem().value_or(""),
              "p = nan (must be finite and >= 0.5)");
    EXPECT_TRUE(ShapeSpec::superball(INFINITY).problem());
    const std::vector<double> two{1.0, 2.0};
    EXPECT_EQ(messageOf([&] { ShapeSpec::fromValues("superball", two); }),
              "the superball takes 1 parameter (p), not 2");
    EXPECT_EQ(messageOf([&] { ShapeSpec::fromValues("cube", two); }),
              "unknown shape family 'cube' (known: superball)");
}

// The exchange formats' superquadric (OVITO's implicit surface, docs/cli.md "Files") of a
// superball is paper Eq. 1 itself: the two functions agree wherever they are evaluated, and the
// formats' inverse gives the shape back; proportions or blockinesses no family has are refused.
TEST(ShapeSpec, ItsSuperquadricIsPaperEq1AndReadsBack) {
    for (const double p : {0.5, 0.8, 1.0, 1.5, 4.0, 40.0}) {
        const ShapeSpec shape = ShapeSpec::superball(p);
        const Superquadric q = shape.superquadric();
        const double phi = 2.0 / q.eastWest, theta = 2.0 / q.northSouth;
        for (const Vector3d& x :
             {Vector3d(0.3, -0.7, 0.2), Vector3d(-1.1, 0.4, 0.9), Vector3d(0.05, 0.6, -0.95)}) {
            const Vector3d r = x.cwiseQuotient(q.axes).cwiseAbs();
            const double ovito =
                std::pow(std::pow(r.x(), 2.0 / phi) + std::pow(r.y(), 2.0 / phi), phi / theta) +
                std::pow(r.z(), 2.0 / theta);
            const double eq1 = std::pow(std::abs(x.x()), 2.0 * p) +
                               std::pow(std::abs(x.y()), 2.0 * p) +
                               std::pow(std::abs(x.z()), 2.0 * p);
            EXPECT_NEAR(ovito, eq1, 1e-12 * eq1) << "p = " << p;
        }
        EXPECT_EQ(ShapeSpec::fromSuperquadric(q), shape);
    }
    EXPECT_EQ(messageOf([] {
                  ShapeSpec::fromSuperquadric({Vector3d(1.0, 1.0, 0.5), 3.0, 3.0});
              }),
              "semi-axes in proportion 1:1:0.5 with blockiness 3 (x, y) and 3 (z) are no shape "
              "sbpack knows (superball); a superball has three equal semi-axes and one blockiness "
              "2p");
    EXPECT_THROW(ShapeSpec::fromSuperquadric({Vector3d::Ones(), 3.0, 4.0}), std::invalid_argument);
}

// Only p = 1 is the sphere; the body at a size has the superball's geometry (paper Eq. 1 and
// Sec. II D), whose closed forms tests/common/test_superball.cpp checks.
TEST(ParticleShape, IsTheSuperballOfItsSpec) {
    EXPECT_TRUE(ShapeSpec::superball(1.0).isSphere());
    EXPECT_FALSE(ShapeSpec::superball(1.0 + 1e-12).isSphere());
    const ParticleShape sphere(ShapeSpec::superball(1.0), 0.5);
    EXPECT_NEAR(sphere.volume(), M_PI / 6.0, 1e-15);
    EXPECT_NEAR(sphere.meanWidth(), 1.0, 1e-14);
    for (const double p : {0.5, 0.85, 1.5, 10.0}) {
        const ParticleShape body(ShapeSpec::superball(p), 0.7);
        const Superball superball(p, 0.7);
        EXPECT_EQ(body.volume(), superball.volume()) << p;
        EXPECT_EQ(body.meanWidth(), superball.meanWidth()) << p;
        EXPECT_EQ(body.circumradius(), superball.circumradius()) << p;
        EXPECT_EQ(body.inradius(), superball.inradius()) << p;
        EXPECT_EQ(body.diameter(), 1.4) << p;
    }
    EXPECT_THROW(ParticleShape(ShapeSpec::superball(0.4), 1.0), std::invalid_argument);
}

// The questions the order metrics and the jam check's advice ask of a shape, not of p.
TEST(ParticleShape, AxesAreCubicButTheSpheresAndColumnsAreNearCubes) {
    const auto shape = [](double p) { return ParticleShape(ShapeSpec::superball(p), 0.5); };
    EXPECT_FALSE(shape(1.0).hasCubicAxes());
    EXPECT_TRUE(shape(0.5).hasCubicAxes());
    EXPECT_TRUE(shape(1.0 + 1e-9).hasCubicAxes());
    EXPECT_FALSE(shape(2.99).stacksInColumns());
    EXPECT_TRUE(shape(kNearCubeExponent).stacksInColumns());
    EXPECT_TRUE(shape(10.0).stacksInColumns());
}

// The contact types' question (docs/contact-types.md): a body that says it has the cube's
// symmetry keeps its gauge under all 48 signed permutations of the body axes.
TEST(ParticleShape, ABodyWithCubicSymmetryKeepsItsGaugeUnderTheCubesGroup) {
    const Vector3d x(0.31, -0.12, 0.54);
    for (const double p : {0.5, 0.8, 1.0, 1.5, 10.0}) {
        const ParticleShape body(ShapeSpec::superball(p), 0.7);
        ASSERT_TRUE(body.hasCubicSymmetry()) << p;
        std::array<int, 3> axes{0, 1, 2};
        do {
            for (int signs = 0; signs < 8; ++signs) {
                Vector3d y;
                for (int k = 0; k < 3; ++k)
                    y[k] = ((signs >> k) & 1 ? -1.0 : 1.0) * x[axes[k]];
                EXPECT_NEAR(body.gauge(y), body.gauge(x), 1e-14) << p;
            }
        } while (std::next_permutation(axes.begin(), axes.end()));
    }
}

// The analyses solve pairs of ParticleShape, sbgen of Superball: the one pair solver and the one
// curvature (pair/pair_geometry, jamming/gap_hessian) give both the same bits, touching pairs
// of a mixture included.
TEST(ParticleShape, ThePairSolversSeeTheSameBodyAsTheSuperballs) {
    for (const double p : {0.5, 1.0, 0.85, 1.5, 10.0}) {
        const Superball superball(p, 0.5);
        const ParticleShape shape(ShapeSpec::superball(p), 0.5);
        const Matrix3d a = Eigen::Quaterniond(0.9, 0.1, -0.3, 0.2).normalized().toRotationMatrix();
        const Matrix3d b = Eigen::Quaterniond(0.4, -0.5, 0.6, 0.1).normalized().toRotationMatrix();
        for (const double sizeB : {1.0, 1.4})
            for (const double distance : {0.9, 1.1, 1.6}) {
                const Vector3d d = distance * Vector3d(0.6, -0.48, 0.64);
                const SignedDistanceResult x =
                    signedDistance(SuperballPair{superball, a, b, d, sizeB});
                const SignedDistanceResult y =
                    signedDistance(BodyPair<ParticleShape>{shape, a, b, d, sizeB});
                EXPECT_EQ(x.signedDistance, y.signedDistance) << p;
                EXPECT_EQ(x.scaleFactor, y.scaleFactor) << p;
                EXPECT_EQ(x.normal, y.normal) << p;
                EXPECT_EQ(x.contactA, y.contactA) << p;
                if (p == 0.5) continue; // the octahedron's curvature is not finite
                const ContactCurvature cx =
                    contactCurvature(superball, a, b, d, x.normal, x.signedDistance, sizeB);
                const ContactCurvature cy =
                    contactCurvature(shape, a, b, d, y.normal, y.signedDistance, sizeB);
                EXPECT_EQ(cx.curvatureA, cy.curvatureA) << p;
                EXPECT_EQ(cx.curvatureB, cy.curvatureB) << p;
                EXPECT_EQ(cx.leverA, cy.leverA) << p;
            }
    }
}

// The build's own list: the superball first (a file without a family name holds superballs), and
// a ShapeSpec is its family's index with the family's values; the default is the first family at
// its parameters' fallbacks.
TEST(ShapeFamilyList, TheBuildsFamiliesStartWithTheSuperball) {
    static_assert(ShapeFamilies::indexOf<SuperballFamily> == 0);
    EXPECT_EQ(ShapeSpec(), ShapeSpec::superball(1.0));
    EXPECT_EQ(ShapeSpec::superball(1.5).familyIndex(), 0u);
    EXPECT_FALSE(ShapeSpec::superball(1.5).writtenFamily());
    EXPECT_EQ(ShapeSpec::superball(1.5).superballExponent(), 1.5);
    const ParticleShape body(ShapeSpec::superball(1.5), 0.5);
    EXPECT_EQ(body.familyName(), "superball");
    EXPECT_EQ(body.visitBody([](const auto& b) { return b.semiAxis(); }), 0.5);
    EXPECT_EQ(body.superball().p(), 1.5);
}

} // namespace
} // namespace sbpack

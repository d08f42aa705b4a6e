// ShapeSpec and ParticleShape (common/geometry/particle_shape) over two families: the superball
// and the ball of tests/families/two_families.hpp, built into this program alone (tests/
// CMakeLists.txt: SBPACK_SHAPE_FAMILIES_HEADER). Each question goes to the family the shape
// names; the ball's answers are closed forms, the superball's those of the one-family build.
#include "geometry/particle_shape.hpp"
#include "message_of.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {
namespace {

const std::vector<double> kNone;

TEST(TwoFamilies, AShapeIsItsFamilyByNameWithThatFamilysParameters) {
    static_assert(ShapeFamilies::indexOf<SuperballFamily> == 0);
    static_assert(ShapeFamilies::indexOf<TestBallFamily> == 1);
    static_assert(std::is_same_v<ShapeFamilies::AnyBody, std::variant<Superball, TestBall>>);
    EXPECT_EQ(shapeFamilyNames(), "superball, ball");
    EXPECT_EQ(findShapeFamily("ball"), &shapeFamilies()[1]);
    const ShapeSpec ball = ShapeSpec::fromValues("ball", kNone);
    EXPECT_EQ(ball.familyIndex(), 1u);
    EXPECT_EQ(ball.info().name, "ball");
    EXPECT_TRUE(ball.values().empty());
    EXPECT_EQ(ball.describe(), "ball");
    EXPECT_EQ(ball.writtenFamily(), "ball");
    EXPECT_FALSE(ball.superballExponent());
    EXPECT_TRUE(ball.isSphere());
    EXPECT_FALSE(ball.problem());
    EXPECT_NE(ball, ShapeSpec::superball(1.0)); // a sphere of another family is another shape
    EXPECT_EQ(messageOf([] { ShapeSpec::fromValues("ball", std::vector<double>{1.0}); }),
              "the ball takes 0 parameters (), not 1");
    const ShapeSpec superball = ShapeSpec::fromValues("superball", std::vector<double>{1.5});
    EXPECT_EQ(superball, ShapeSpec::superball(1.5));
    EXPECT_EQ(superball.describe(), "p = 1.5");
    EXPECT_FALSE(superball.writtenFamily());
}

// A file names the family (nothing: the superball) and each of its parameters: the ball's file
// has none to read, and the superball's p becomes optional in the schemas.
TEST(TwoFamilies, FilesReadTheFamilyTheyNameAndItsParametersOnly) {
    std::vector<std::string> asked;
    const auto value = [&](std::string_view name) {
        asked.emplace_back(name);
        return 1.5;
    };
    EXPECT_EQ(ShapeSpec::read(std::string("ball"), value), ShapeSpec::fromValues("ball", kNone));
    EXPECT_TRUE(asked.empty());
    EXPECT_EQ(ShapeSpec::read(std::nullopt, value), ShapeSpec::superball(1.5));
    EXPECT_EQ(asked, std::vector<std::string>{"p"});
    EXPECT_EQ(ShapeSpec::readOrFallback(std::nullopt,
                                        [](std::string_view) { return std::optional<double>(); }),
              ShapeSpec::superball(1.0));
    EXPECT_THROW(ShapeSpec::read(std::string("cube"), value), std::invalid_argument);
    const std::vector<ShapeField> fields = shapeFields();
    ASSERT_EQ(fields.size(), 2u); // the family's name, then p
    EXPECT_EQ(fields[1].name, "p");
    EXPECT_TRUE(fields[1].optional);
}

// The superquadric goes to the first family that has it; one that none has is refused with what
// each family needs.
TEST(TwoFamilies, ASuperquadricIsTheFirstFamilysThatHasIt) {
    EXPECT_EQ(ShapeSpec::fromSuperquadric({}), ShapeSpec::superball(1.0));
    EXPECT_EQ(messageOf([] {
                  ShapeSpec::fromSuperquadric({Vector3d(1.0, 1.0, 0.5), 2.0, 2.0});
              }),
              "semi-axes in proportion 1:1:0.5 with blockiness 2 (x, y) and 2 (z) are no shape "
              "sbpack knows (superball, ball); a superball has three equal semi-axes and one "
              "blockiness 2p; a ball is the superball of p = 1");
}

TEST(TwoFamilies, ABodyAnswersAsItsFamilysBody) {
    const ParticleShape ball(ShapeSpec::fromValues("ball", kNone), 0.5);
    EXPECT_EQ(ball.familyName(), "ball");
    EXPECT_DOUBLE_EQ(ball.volume(), std::numbers::pi / 6.0);
    EXPECT_EQ(ball.meanWidth(), 1.0);
    EXPECT_EQ(ball.circumradius(), 0.5);
    EXPECT_EQ(ball.diameter(), 1.0);
    EXPECT_TRUE(ball.isSphere());
    EXPECT_FALSE(ball.isOctahedron()); // the ball has no such question: false
    EXPECT_FALSE(ball.hasCubicAxes());
    EXPECT_EQ(ball.support(Vector3d(0.0, 3.0, 4.0)), 2.5);
    EXPECT_EQ(ball.scaled(2.0).semiAxis(), 1.0);
    const ParticleShape::InsideTest inside = ball.insideTest();
    EXPECT_TRUE(inside(Vector3d(0.49, 0.0, 0.0)));
    EXPECT_FALSE(inside(Vector3d(0.3, 0.3, 0.3))); // inside the superballs of p > 1.2
    EXPECT_EQ(ball.gaugePower(Vector3d(0.0, 1.0, 0.0)), 4.0);
    EXPECT_EQ(ball.closestPoint(Vector3d(0.0, 0.0, 2.0)), Vector3d(0.0, 0.0, 0.5));
    EXPECT_EQ(ball.visitBody([](const auto& body) { return body.semiAxis(); }), 0.5);
    EXPECT_EQ(messageOf([&] { (void)ball.superball(); }),
              "the particles are balls: this quantity is defined for superballs only");

    const ParticleShape cube(ShapeSpec::superball(10.0), 0.5);
    EXPECT_EQ(cube.familyName(), "superball");
    EXPECT_EQ(cube.volume(), Superball(10.0, 0.5).volume());
    EXPECT_TRUE(cube.insideTest()(Vector3d(0.3, 0.3, 0.3)));
    EXPECT_TRUE(cube.hasCubicAxes());
    EXPECT_EQ(cube.superball().p(), 10.0);
}

} // namespace
} // namespace sbpack

// The list of shape families (common/geometry/shape_family.hpp, docs/architecture.md "What a
// new shape needs"): a family is a ShapeFamilyTraits in its own files and one entry of the list,
// from which ShapeSpec and ParticleShape dispatch. Checked here with a second family made for the
// test (a ball of radius r), so that the dispatch is seen to pick the family by its index.
#include "geometry/particle_shape.hpp"
#include "geometry/shape_families.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sbpack {
namespace {

/// A body of the test family: a ball, its gauge |x| / r.
struct TestBall {
    double r;
    bool operator()(const Vector3d& x) const { return x.norm() < r; }
};
bool hasCubicAxes(const TestBall&) {
    return false;
}
bool hasCubicSymmetry(const TestBall&) {
    return true;
}
bool stacksInColumns(const TestBall&) {
    return false;
}
TestBall insideTest(const TestBall& ball) {
    return ball;
}
double gaugePower(const TestBall& ball, const Vector3d& x) {
    return x.squaredNorm() / (ball.r * ball.r);
}
Vector3d closestPoint(const TestBall& ball, const Vector3d& x) {
    return x.norm() <= ball.r ? x : Vector3d(ball.r * x.normalized());
}

struct TestBallFamily {
    using Body = TestBall;
    static constexpr std::string_view name = "ball";
    static constexpr std::array<ShapeParameter, 1> parameters = {
        ShapeParameter{"stretch", "1", "for the test", 2.0}};
    static constexpr std::string_view superquadricForm = "a ball is n = 2";
    static std::optional<std::string> problem(std::span<const double>) { return std::nullopt; }
    static bool isSphere(std::span<const double>) { return true; }
    static TestBall body(std::span<const double> values, double semiAxis) {
        return {values[0] * semiAxis};
    }
    static Superquadric superquadric(std::span<const double>) { return {}; }
    static std::optional<std::vector<double>> fromSuperquadric(const Superquadric&) {
        return std::nullopt;
    }
};

using TwoFamilies = ShapeFamilyList<SuperballFamily, TestBallFamily>;

TEST(ShapeFamilyList, NumbersItsFamiliesInOrderAndDispatchesByThatNumber) {
    static_assert(ShapeFamilyTraits<TestBallFamily>);
    static_assert(TwoFamilies::size == 2);
    static_assert(TwoFamilies::indexOf<SuperballFamily> == 0);
    static_assert(TwoFamilies::indexOf<TestBallFamily> == 1);
    static_assert(std::is_same_v<TwoFamilies::AnyBody, std::variant<Superball, TestBall>>);
    EXPECT_EQ(TwoFamilies::info[0].name, "superball");
    EXPECT_EQ(TwoFamilies::info[1].name, "ball");
    EXPECT_EQ(TwoFamilies::info[1].parameters[0].name, "stretch");
    EXPECT_EQ(TwoFamilies::info[1].parameters[0].fallback, 2.0);
    const std::vector<double> values{1.5};
    for (std::size_t index : {0u, 1u}) {
        const std::string name = TwoFamilies::visit(
            index, []<class F>(std::type_identity<F>) { return std::string(F::name); });
        EXPECT_EQ(name, TwoFamilies::info[index].name);
        const TwoFamilies::AnyBody body =
            TwoFamilies::visit(index, [&]<class F>(std::type_identity<F>) {
                return TwoFamilies::AnyBody(F::body(values, 0.5));
            });
        EXPECT_EQ(body.index(), index);
    }
    EXPECT_EQ(std::get<TestBall>(TwoFamilies::visit(1,
                                                    [&]<class F>(std::type_identity<F>) {
                                                        return TwoFamilies::AnyBody(
                                                            F::body(values, 0.5));
                                                    }))
                  .r,
              0.75);
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

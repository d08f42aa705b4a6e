#pragma once
// The family list of tests/families/test_two_families.cpp: the superball and a second family made
// for the test, the ball (no parameters), so that ShapeSpec and ParticleShape
// (common/geometry/particle_shape) are seen to dispatch to the family a shape names.

#include "geometry/superball_family.hpp"

#include <numbers>

namespace sbpack {

/// The ball of radius r: every ConvexBody quantity in closed form.
struct TestBall {
    double r;
    double semiAxis() const { return r; }
    double gauge(const Vector3d& x) const { return x.norm() / r; }
    double support(const Vector3d& n) const { return r * n.norm(); }
    Vector3d supportPoint(const Vector3d& n) const { return r * n.normalized(); }
    Matrix3d supportHessian(const Vector3d& n) const {
        const Vector3d u = n.normalized();
        return r / n.norm() * (Matrix3d::Identity() - u * u.transpose());
    }
    Matrix3d surfaceCurvature(const Vector3d&) const { return Matrix3d::Identity() / r; }
    TestBall scaled(double factor) const { return {r * factor}; }
    bool isSphere() const { return true; }
    double volume() const { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }
    double meanWidth() const { return 2.0 * r; }
    double circumradius() const { return r; }
    double inradius() const { return r; }
    bool operator()(const Vector3d& x) const { return gauge(x) < 1.0; }
};
inline bool hasCubicAxes(const TestBall&) {
    return false;
}
inline bool hasCubicSymmetry(const TestBall&) {
    return true;
}
inline bool stacksInColumns(const TestBall&) {
    return false;
}
inline TestBall insideTest(const TestBall& ball) {
    return ball;
}
inline double gaugePower(const TestBall& ball, const Vector3d& x) {
    return x.squaredNorm() / (ball.r * ball.r);
}
inline Vector3d closestPoint(const TestBall& ball, const Vector3d& x) {
    return x.norm() <= ball.r ? x : Vector3d(ball.r * x.normalized());
}

struct TestBallFamily {
    using Body = TestBall;
    static constexpr std::string_view name = "ball";
    static constexpr std::array<ShapeParameter, 0> parameters = {};
    static constexpr std::string_view superquadricForm = "a ball is the superball of p = 1";
    static std::optional<std::string> problem(std::span<const double>) { return std::nullopt; }
    static bool isSphere(std::span<const double>) { return true; }
    static TestBall body(std::span<const double>, double semiAxis) { return {semiAxis}; }
    static Superquadric superquadric(std::span<const double>) { return {}; }
    static std::optional<std::vector<double>> fromSuperquadric(const Superquadric& q) {
        if (q.axes == Vector3d::Ones() && q.eastWest == 2.0 && q.northSouth == 2.0)
            return std::vector<double>{};
        return std::nullopt;
    }
};

using ShapeFamilies = ShapeFamilyList<SuperballFamily, TestBallFamily>;

} // namespace sbpack

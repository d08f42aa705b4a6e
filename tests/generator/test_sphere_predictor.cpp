#include "random/random.hpp"
#include "shapes/sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sbpack {
namespace {

PairMotion pair(Vector3d d, Vector3d w, double diameter, double gamma) {
    PairMotion m;
    m.displacement = d;
    m.relativeVelocity = w;
    m.diameter = diameter;
    m.growthRate = gamma;
    return m;
}

TEST(SpherePredictor, HeadOnWithGrowthIsExact) {
    // Gap 2 - 1 = 1 closes at speed 0.5 + gamma 0.25: tau = 1 / 0.75.
    const SphereShape sphere;
    EXPECT_NEAR(sphere.collisionTime(pair({2, 0, 0}, {-0.5, 0, 0}, 1.0, 0.25)), 4.0 / 3.0, 1e-15);
    // Growth alone closes any gap: |d| = D + gamma tau.
    EXPECT_NEAR(sphere.collisionTime(pair({0, 3, 0}, {0, 0, 0}, 1.0, 0.5)), 4.0, 1e-15);
    // Receding faster than growing never meets.
    EXPECT_EQ(sphere.collisionTime(pair({2, 0, 0}, {1, 0, 0}, 1.0, 0.5)),
              std::numeric_limits<double>::infinity());
}

TEST(SpherePredictor, RandomPairsTouchExactlyAtThePredictedTime) {
    const SphereShape sphere;
    Random random(3);
    int hits = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Vector3d d = random.normalVector().normalized() * (1.0 + 3.0 * random.uniform());
        const Vector3d w = random.normalVector();
        const double gamma = trial % 2 == 0 ? 0.0 : 0.1 * random.uniform();
        const double tau = sphere.collisionTime(pair(d, w, 1.0, gamma));
        // Brute force: the first sign change of |d + w t| - (D + gamma t) on a fine grid.
        double first = std::numeric_limits<double>::infinity();
        const double step = 1e-3;
        for (double t = 0.0; t < 20.0; t += step)
            if ((d + w * (t + step)).norm() - (1.0 + gamma * (t + step)) <= 0.0) {
                first = t + step;
                break;
            }
        if (std::isinf(first)) {
            EXPECT_TRUE(std::isinf(tau) || tau > 20.0) << trial;
            continue;
        }
        ++hits;
        ASSERT_LE(tau, first) << trial;
        ASSERT_GE(tau, first - step) << trial;
        EXPECT_NEAR((d + w * tau).norm(), 1.0 + gamma * tau, 1e-12) << trial;
    }
    EXPECT_GT(hits, 200);
}

TEST(SpherePredictor, OverlapByRoundingCollidesNowOnlyWhenApproaching) {
    const SphereShape sphere;
    EXPECT_EQ(sphere.collisionTime(pair({1.0 - 1e-15, 0, 0}, {-1, 0, 0}, 1.0, 0.0)), 0.0);
    EXPECT_TRUE(std::isinf(sphere.collisionTime(pair({1.0 - 1e-15, 0, 0}, {1, 0, 0}, 1.0, 0.0))));
}

} // namespace
} // namespace sbpack

// The engine against analytic truths: exact collision times, conservation laws and the
// Carnahan-Starling equation of state of the equilibrium hard-sphere fluid.
#include "engine/event_driven_md.hpp"
#include "geometry/superball.hpp"
#include "initial/random_start.hpp"
#include "neighbours/neighbour_lists.hpp"
#include "shapes/sphere.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sbpack {
namespace {

using Engine = EventDrivenMd<SphereShape>;

Engine randomFluid(int n, double phi, double gamma, std::uint64_t seed) {
    Random random(seed);
    const double box = boxLengthFor(n, Superball(1.0, 0.5).volume(), phi);
    const auto placement = randomPlacement(SphereShape{}, n, box, random);
    const auto velocities = maxwellVelocities(n, random);
    std::vector<ParticleState> state(n);
    for (int i = 0; i < n; ++i)
        state[i] = {placement.positions[i], velocities[i]};
    return Engine(SphereShape{}, box, std::move(state), GrowthClock{1.0, 0.0, gamma});
}

Vector3d totalMomentum(const Engine& engine) {
    Vector3d sum = Vector3d::Zero();
    for (const ParticleState& s : engine.particles())
        sum += s.velocity;
    return sum;
}

double smallestGap(const Engine& engine) {
    double gap = INFINITY;
    const auto& s = engine.particles();
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j)
            gap = std::min(gap,
                           minimumImage(s[j].position - s[i].position, engine.boxLength()).norm() -
                               engine.diameter());
    return gap / engine.diameter();
}

// The skin is five Carnahan-Starling mean free paths, D / (6 sqrt(2) phi g), g = (1 - phi/2) /
// (1 - phi)^3, within [0.1, 0.5] D: wide in the dilute start, the old fixed 0.1 near jamming.
TEST(NeighbourSkin, FiveMeanFreePathsWithinItsBounds) {
    for (const double phi : {0.25, 0.3, 0.4, 0.5}) {
        const double g = (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3);
        const double expected = std::clamp(5.0 / (6.0 * std::sqrt(2.0) * phi * g), 0.1, 0.5);
        EXPECT_NEAR(neighbourSkin(phi), expected, 1e-15) << "phi " << phi;
    }
    EXPECT_EQ(neighbourSkin(0.05), 0.5);
    EXPECT_EQ(neighbourSkin(0.2), 0.5);
    EXPECT_EQ(neighbourSkin(0.6), 0.1);
    EXPECT_EQ(neighbourSkin(0.74), 0.1);
    for (double phi = 0.01; phi < 0.9; phi += 0.01)
        EXPECT_GE(neighbourSkin(phi), neighbourSkin(phi + 0.01)) << "not monotone at " << phi;
}

TEST(EventDrivenMd, TwoGrowingSpheresCollideAtTheExactTimeAndSwapNormalVelocity) {
    // Head on: gap 3 - 1 = 2 closes at 0.5 + 0.5 + gamma 0.5, so tau = 4 / 3.
    std::vector<ParticleState> state = {{{2, 5, 5}, {0.5, 0, 0}}, {{5, 5, 5}, {-0.5, 0, 0}}};
    Engine engine(SphereShape{}, 10.0, state, GrowthClock{1.0, 0.0, 0.5});
    const RunReport report = engine.run(1);
    ASSERT_EQ(report.collisions, 1u);
    EXPECT_NEAR(report.duration, 4.0 / 3.0, 1e-14);
    EXPECT_NEAR(engine.diameter(), 1.0 + 0.5 * 4.0 / 3.0, 1e-14);
    // Surface normal velocity u = -1 - 0.5 reversed: v_n' = 2 gamma - v_n = 2.
    EXPECT_NEAR(engine.particles()[1].velocity.x() - engine.particles()[0].velocity.x(), 2.0,
                1e-14);
    // Collision virial r_ij . Delta p_j = D J with J = gamma - v_n = 1.5.
    EXPECT_NEAR(report.virial, engine.diameter() * 1.5, 1e-13);
}

TEST(EventDrivenMd, CollisionsAcrossThePeriodicBoundary) {
    // Through the face x = 0: centre distance 0.2 + (6 - 4.7) = 1.5, gap 0.5 closing at speed 1.
    std::vector<ParticleState> state = {{{0.2, 2, 2}, {-1, 0, 0}}, {{4.7, 2, 2}, {0, 0, 0}}};
    Engine engine(SphereShape{}, 6.0, state, GrowthClock{1.0, 0.0, 0.0});
    const RunReport report = engine.run(1);
    ASSERT_EQ(report.collisions, 1u);
    EXPECT_NEAR(report.duration, 0.5, 1e-14);
    EXPECT_NEAR(engine.particles()[1].velocity.x(), -1.0, 1e-14); // equal masses swap
}

TEST(EventDrivenMd, MomentumIsConservedWhileGrowing) {
    Engine engine = randomFluid(300, 0.3, 0.02, 11);
    ASSERT_LT(totalMomentum(engine).norm(), 1e-12);
    engine.run(20000);
    EXPECT_LT(totalMomentum(engine).norm(), 1e-11);
    EXPECT_GT(smallestGap(engine), -1e-12);
}

TEST(EventDrivenMd, EnergyIsConservedWithoutGrowth) {
    Engine engine = randomFluid(300, 0.35, 0.0, 12);
    const double before = engine.kineticTemperature();
    for (int k = 0; k < 5; ++k)
        engine.run(10000);
    EXPECT_NEAR(engine.kineticTemperature(), before, 1e-12 * before);
    EXPECT_GT(smallestGap(engine), -1e-12);
}

TEST(EventDrivenMd, EquilibriumPressureAtPhi03MatchesCarnahanStarling) {
    const double phi = 0.3;
    Engine engine = randomFluid(500, phi, 0.0, 13);
    engine.run(50 * 500); // equilibrate
    double virial = 0.0, duration = 0.0;
    for (int k = 0; k < 8; ++k) {
        const RunReport report = engine.run(50 * 500);
        virial += report.virial;
        duration += report.duration;
    }
    const double pressure = 1.0 + virial / (3.0 * 500 * engine.kineticTemperature() * duration);
    const double carnahanStarling =
        (1.0 + phi + phi * phi - phi * phi * phi) / std::pow(1.0 - phi, 3);
    EXPECT_NEAR(pressure / carnahanStarling, 1.0, 0.03) << pressure << " vs " << carnahanStarling;
}

TEST(EventDrivenMd, NoOverlapAfterShortGrowingRunsForSeveralSeeds) {
    for (const std::uint64_t seed : {1, 2, 3, 4, 5}) {
        Engine engine = randomFluid(200, 0.2, 0.05, seed);
        for (int k = 0; k < 10; ++k) {
            engine.run(2000);
            engine.scaleVelocities(1.0 / std::sqrt(engine.kineticTemperature()));
        }
        EXPECT_GT(smallestGap(engine), -1e-12) << "seed " << seed;
        EXPECT_GT(engine.diameter(), 1.0);
    }
}

} // namespace
} // namespace sbpack

// The residuals, the virial and the distribution of contact forces (common/packing/contact_forces;
// issue 62), on contacts whose answers are worked by hand or drawn from a known distribution.
#include "packing/contact_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace sbpack {
namespace {

/// Two spheres of diameter 1 in a box of 4, touching across its x faces: r_1 - r_0 is
/// (-1, 0, 0) by the minimum image.
Packing twoAcrossTheBox() {
    Packing packing;
    packing.semiAxis = 0.5;
    packing.boxLength = 4.0;
    packing.positions = {Vector3d(0.25, 2, 2), Vector3d(3.25, 2, 2)};
    packing.orientations.assign(2, Quaterniond::Identity());
    return packing;
}

TEST(ContactForces, ABalancedPairHasOppositeNetForcesAndTheVirialOfItsSeparation) {
    const Packing packing = twoAcrossTheBox();
    // 0 pushes 1 along n = -x with f = 6 (kT / D), at the midpoint across the face.
    const ContactForces forces{
        {{0, 1, Vector3d(3.75, 2, 2), Vector3d(-1, 0, 0), 6.0}}, 1, 1.0, 0.0};
    const ForceBalance balance = forceBalance(packing, forces);
    EXPECT_EQ(balance.netForces[0], Vector3d(6, 0, 0)); // 1 pushes back on 0 along +x
    EXPECT_EQ(balance.netForces[1], Vector3d(-6, 0, 0));
    EXPECT_EQ(balance.netTorques[0], Vector3d::Zero()); // lever along the force: no torque
    EXPECT_EQ(balance.netTorques[1], Vector3d::Zero());
    // P = 1 + f (r_01 . n) / (3 N D) = 1 + 6 * 1 / 6.
    EXPECT_DOUBLE_EQ(virialPressure(packing, forces), 2.0);
}

TEST(ContactForces, AnOffCentreContactTurnsBothParticles) {
    const Packing packing = twoAcrossTheBox();
    // The same force at a point 0.25 above the centre line: lever of 0 (-0.5, 0.25, 0) by the
    // minimum image, of 1 (+0.5, 0.25, 0); torques (lever / D) x force.
    const ContactForces forces{
        {{0, 1, Vector3d(3.75, 2.25, 2), Vector3d(-1, 0, 0), 6.0}}, 1, 1.0, 0.0};
    const ForceBalance balance = forceBalance(packing, forces);
    EXPECT_TRUE(balance.netTorques[0].isApprox(Vector3d(-0.5, 0.25, 0).cross(Vector3d(6, 0, 0))));
    EXPECT_TRUE(balance.netTorques[1].isApprox(Vector3d(0.5, 0.25, 0).cross(Vector3d(-6, 0, 0))));
    EXPECT_DOUBLE_EQ(balance.netTorques[0].z(), -1.5);
}

TEST(ContactForces, AContactOutsideThePackingIsRefused) {
    const ContactForces forces{{{0, 2, Vector3d::Zero(), Vector3d(1, 0, 0), 1.0}}, 1, 1.0, 0.0};
    EXPECT_THROW(forceBalance(twoAcrossTheBox(), forces), std::invalid_argument);
    EXPECT_THROW(virialPressure(twoAcrossTheBox(), forces), std::invalid_argument);
}

/// Stored forces of the given magnitudes (the pair and geometry do not enter the distribution).
ContactForces forcesOf(const std::vector<double>& magnitudes) {
    ContactForces forces;
    for (const double f : magnitudes)
        forces.contacts.push_back({0, 1, Vector3d::Zero(), Vector3d::UnitX(), f});
    return forces;
}

double integral(const ForceDistribution& d) {
    double sum = d.tailFraction;
    for (std::size_t k = 0; k < d.density.size(); ++k)
        sum += d.density[k] * (d.edges[k + 1] - d.edges[k]);
    return sum;
}

TEST(ForceDistribution, EqualForcesAreOneSpikeAtTheMean) {
    const ForceDistribution d = forceDistribution(forcesOf(std::vector<double>(7, 3.0)));
    EXPECT_EQ(d.count, 7);
    EXPECT_DOUBLE_EQ(d.mean, 3.0);
    EXPECT_DOUBLE_EQ(d.secondMoment, 1.0);
    EXPECT_EQ(d.tailFraction, 0.0);
    ASSERT_EQ(d.edges.size(), ForceDistribution::kBins + 1u);
    const double width = d.edges[1] - d.edges[0];
    for (std::size_t k = 0; k < d.density.size(); ++k) // x = 1 opens bin [1, 1 + width)
        EXPECT_DOUBLE_EQ(d.density[k], d.edges[k] == 1.0 ? 1.0 / width : 0.0) << k;
}

TEST(ForceDistribution, ForcesBeyondTheLastEdgeAreTheTail) {
    // mean 2: x = 0, 0, 0 and 4, the last edge, which belongs to the tail
    const ForceDistribution d = forceDistribution(forcesOf({0.0, 0.0, 0.0, 8.0}));
    EXPECT_DOUBLE_EQ(d.tailFraction, 0.25);
    EXPECT_DOUBLE_EQ(d.density.front(), 0.75 / (d.edges[1] - d.edges[0]));
    EXPECT_DOUBLE_EQ(integral(d), 1.0);
    EXPECT_DOUBLE_EQ(d.secondMoment, 4.0);
}

// Exponential forces, P(x) = e^-x (the tail of jammed packings' distributions): each bin within 5
// standard deviations of its probability, <x^2> = 2 and the tail e^-4 within theirs.
TEST(ForceDistribution, ExponentialForcesGiveTheExponentialDensity) {
    std::mt19937_64 random(62);
    std::exponential_distribution<double> exponential(0.25); // mean 4 kT / D
    std::vector<double> magnitudes(200000);
    for (double& f : magnitudes)
        f = exponential(random);
    const ForceDistribution d = forceDistribution(forcesOf(magnitudes));
    const double n = static_cast<double>(magnitudes.size());
    EXPECT_NEAR(d.mean, 4.0, 5.0 * 4.0 / std::sqrt(n));
    EXPECT_NEAR(d.secondMoment, 2.0, 5.0 * std::sqrt(20.0 / n)); // var x^2 = 24 - 4
    const double tail = std::exp(-ForceDistribution::kLargest);
    EXPECT_NEAR(d.tailFraction, tail, 5.0 * std::sqrt(tail / n));
    EXPECT_NEAR(integral(d), 1.0, 1e-12);
    for (std::size_t k = 0; k < d.density.size(); ++k) {
        const double a = d.edges[k], b = d.edges[k + 1];
        const double probability = std::exp(-a) - std::exp(-b);
        EXPECT_NEAR(d.density[k] * (b - a), probability, 5.0 * std::sqrt(probability / n)) << k;
    }
}

TEST(ForceDistribution, NoForcesIsUndefinedNotZero) {
    const ForceDistribution d = forceDistribution(ContactForces{});
    EXPECT_EQ(d.count, 0);
    EXPECT_TRUE(std::isnan(d.mean));
    EXPECT_TRUE(std::isnan(d.secondMoment));
    EXPECT_TRUE(std::isnan(d.density.front()));
}

} // namespace
} // namespace sbpack

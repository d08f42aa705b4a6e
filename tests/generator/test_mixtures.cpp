// sbgen's binary mixtures of spheres (docs/mixtures.md): the exact collision of two sizes, the
// random start, and a protocol run that jams without overlap, unordered, and resumes bit for bit.
#include "contacts/contact_network.hpp"
#include "engine/event_driven_md.hpp"
#include "geometry/superball.hpp"
#include "initial/random_start.hpp"
#include "io/packing_io.hpp"
#include "order/order_metrics.hpp"
#include "protocol/jamming_protocol.hpp"
#include "shapes/sphere.hpp"
#include "shapes/superball_shape.hpp"
#include "small_runs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

namespace sbpack {
namespace {

ProtocolParameters smallMixture(std::uint64_t seed) {
    ProtocolParameters p = testing::smallRun(seed);
    p.particles = 80;
    p.sizeRatio = 1.4;
    p.largeFraction = 0.25;
    return p;
}

/// The smallest gap over all pairs (brute force, minimum image), over the pair's R_i + R_j.
double smallestRelativeGap(const Packing& packing) {
    double gap = INFINITY;
    for (std::size_t i = 0; i < packing.size(); ++i)
        for (std::size_t j = i + 1; j < packing.size(); ++j) {
            const double contact = packing.semiAxisOf(i) + packing.semiAxisOf(j);
            const Vector3d d =
                minimumImage(packing.positions[j] - packing.positions[i], packing.boxLength);
            gap = std::min(gap, (d.norm() - contact) / contact);
        }
    return gap;
}

TEST(Mixtures, TwoGrowingSpheresOfTwoSizesCollideAtTheSumOfTheirRadii) {
    // D(t) = 1 + 0.5 t; sizes 1 and 0.5: contact at (D / 2)(1 + 0.5) = 0.75 D(t). The gap
    // 3 - 0.75 closes at 1 + 0.75 * 0.5, so tau = 2.25 / 1.375.
    std::vector<ParticleState> state = {{{2, 5, 5}, {0.5, 0, 0}}, {{5, 5, 5}, {-0.5, 0, 0}}};
    EventDrivenMd<SphereShape> engine(SphereShape{}, 10.0, state, GrowthClock{1.0, 0.0, 0.5},
                                      {1.0, 0.5});
    const RunReport report = engine.run(1);
    ASSERT_EQ(report.collisions, 1U);
    const double tau = 2.25 / 1.375;
    EXPECT_NEAR(report.duration, tau, 1e-14);
    const Vector3d d = engine.particles()[1].position - engine.particles()[0].position;
    EXPECT_NEAR(d.norm(), 0.75 * engine.diameter(), 1e-13);
    // The surfaces' normal velocity -1 - 0.375 reversed: v_n' = 2 * 0.375 + 1 = 1.75.
    EXPECT_NEAR(engine.particles()[1].velocity.x() - engine.particles()[0].velocity.x(), 1.75,
                1e-14);
}

// Two aligned superballs (p = 1.5) of diameters D and D / 2, not turning, meet face to face along
// x where their semi-axes add up, 0.75 D(t): the time of the spheres above.
TEST(Mixtures, TwoAlignedSuperballsOfTwoSizesMeetFaceToFace) {
    std::vector<ParticleState> state = {{{2, 5, 5}, {0.5, 0, 0}}, {{5, 5, 5}, {-0.5, 0, 0}}};
    EventDrivenMd<SuperballShape> engine(SuperballShape(1.5), 10.0, state,
                                         GrowthClock{1.0, 0.0, 0.5}, {1.0, 0.5});
    const RunReport report = engine.run(1);
    ASSERT_EQ(report.collisions, 1U);
    EXPECT_NEAR(report.duration, 2.25 / 1.375, 1e-12);
    const Vector3d d = engine.particles()[1].position - engine.particles()[0].position;
    EXPECT_NEAR(d.norm(), 0.75 * engine.diameter(), 1e-12);
    // A central collision: no torque, the normal velocity reversed as for the spheres.
    EXPECT_NEAR(engine.particles()[1].velocity.x() - engine.particles()[0].velocity.x(), 1.75,
                1e-12);
    EXPECT_LT(engine.particles()[0].angularVelocity.norm(), 1e-12);
}

// docs/mixtures.md: a binary superball mixture (p = 1.5, ratio 1.4) jams without overlap by the
// contact network (common/pair's pair geometry of two sizes, not the predictor's) and is not
// ordered.
TEST(Mixtures, ABinarySuperballRunJamsWithoutOverlap) {
    ProtocolParameters p = smallMixture(5);
    p.shape = sbpack::ShapeSpec::superball(1.5);
    JammingProtocol run(p);
    ASSERT_TRUE(run.run([](const ProtocolStatus&) {}));
    const Packing packing = run.checkpoint();
    EXPECT_EQ(packing.semiAxes.size(), 80U);
    EXPECT_GE(run.status().reducedPressure, 1e7);
    const ContactResult c = ContactNetwork({.tolerance = 1e-4}).compute(packing);
    EXPECT_EQ(c.overlappingPairs, 0);
    EXPECT_GT(c.worstGap, -1e-12);
    EXPECT_GT(c.meanContactNumber, 6.0);
    EXPECT_FALSE(orderVerdict(measureOrder(packing)).ordered);
}

TEST(Mixtures, TheRandomStartPlacesEachPairAtItsOwnDistance) {
    Random random(3);
    const int n = 300;
    std::vector<double> sizes(n, 1.0 / 1.4);
    std::fill(sizes.begin(), sizes.begin() + n / 2, 1.0);
    double volume = 0.0;
    for (const double s : sizes)
        volume += std::numbers::pi / 6.0 * s * s * s;
    const double box = std::cbrt(volume / 0.3);
    const RandomPlacement placement = randomPlacement(SphereShape{}, n, box, random, {}, sizes);
    Packing packing;
    packing.boxLength = box;
    packing.positions = placement.positions;
    packing.orientations = placement.orientations;
    packing.semiAxis = 0.5;
    for (const double s : sizes)
        packing.semiAxes.push_back(0.5 * s);
    EXPECT_GT(smallestRelativeGap(packing), 0.0);
    EXPECT_NEAR(packing.packingFraction(), 0.3, 1e-12);
}

TEST(Mixtures, ABinaryRunJamsWithoutOverlapAndKeepsItsSizes) {
    JammingProtocol run(smallMixture(4));
    ASSERT_TRUE(run.run([](const ProtocolStatus&) {}));
    const Packing packing = run.checkpoint();
    ASSERT_EQ(packing.semiAxes.size(), 80U);
    EXPECT_EQ(std::count(packing.semiAxes.begin(), packing.semiAxes.end(), packing.semiAxis), 20);
    for (std::size_t i = 20; i < 80; ++i)
        EXPECT_NEAR(packing.semiAxes[i], packing.semiAxis / 1.4, 1e-15 * packing.semiAxis) << i;
    EXPECT_GE(run.status().reducedPressure, 1e7);
    // No overlap by the brute-force check, and the load-bearing gaps closed: at P = 1e7 a jammed
    // network has its gaps near D / P.
    EXPECT_GT(smallestRelativeGap(packing), -1e-12);
    const ContactResult c = ContactNetwork({.tolerance = 1e-4}).compute(packing);
    EXPECT_EQ(c.overlappingPairs, 0);
    EXPECT_GT(c.meanContactNumber, 5.5);
    EXPECT_NEAR(run.status().packingFraction, packing.packingFraction(), 1e-12);
    EXPECT_EQ(std::get<double>(packing.provenance.at("size_ratio")), 1.4);
    // docs/order-metrics.md §1: every pair's contact at r_ij / sigma_ij = 1 w, so the main peak
    // of the reduced g2 is the bin [1, 1.02) (the small spheres' contacts at 0.71 w would be
    // the highest without the pair's size), and the packing has not ordered.
    const OrderMetrics order = measureOrder(packing);
    const auto& g = order.pairCorrelation;
    const auto peak = std::max_element(g.g2.begin(), g.g2.end()) - g.g2.begin();
    EXPECT_NEAR(g.r[peak], 1.01, 1e-9);
    EXPECT_FALSE(orderVerdict(order).ordered) << orderVerdict(order).reason;
}

TEST(Mixtures, ABinaryRunResumesFromItsFileBitForBit) {
    JammingProtocol uninterrupted(smallMixture(7));
    std::optional<Packing> saved;
    ASSERT_TRUE(uninterrupted.run([&](const ProtocolStatus& s) {
        if (s.windows == 30) saved = uninterrupted.checkpoint();
    }));
    ASSERT_TRUE(saved.has_value());
    const auto file = std::filesystem::temp_directory_path() / "sbgen-test-mixture-resume.h5";
    writePacking(*saved, file);
    JammingProtocol resumed(readPacking(file), file.string());
    std::filesystem::remove(file);
    ASSERT_TRUE(resumed.run([](const ProtocolStatus&) {}));
    const Packing a = uninterrupted.checkpoint(), b = resumed.checkpoint();
    EXPECT_EQ(a.semiAxes, b.semiAxes);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(*a.reducedPressure, *b.reducedPressure);
}

// docs/mixtures.md: the diameters are the quantiles of the uniform distribution of mean 1 (over
// the largest: 1 / (1 + a - a / N), a = sqrt(3) s), so their mean and deviation are known exactly.
TEST(Mixtures, APolydisperseRunHasTheDiametersOfItsDistributionAndJams) {
    ProtocolParameters p = smallMixture(3);
    p.sizeRatio = 1.0;
    p.polydispersity = 0.15;
    const std::vector<double> sizes = p.relativeSizes();
    ASSERT_EQ(sizes.size(), 80U);
    EXPECT_EQ(sizes.front(), 1.0);
    const double n = 80.0, a = std::sqrt(3.0) * 0.15, largest = 1.0 + a - a / n;
    double mean = 0.0, square = 0.0;
    for (const double s : sizes) {
        mean += s * largest / n;
        square += s * s * largest * largest / n;
    }
    EXPECT_NEAR(mean, 1.0, 1e-14);
    EXPECT_NEAR(std::sqrt(square - mean * mean), 0.15 * std::sqrt(1.0 - 1.0 / (n * n)), 1e-12);
    JammingProtocol run(p);
    ASSERT_TRUE(run.run([](const ProtocolStatus&) {}));
    const Packing packing = run.checkpoint();
    EXPECT_GT(smallestRelativeGap(packing), -1e-12);
    EXPECT_EQ(std::get<double>(packing.provenance.at("polydispersity")), 0.15);
    EXPECT_NEAR(packing.semiAxes.back() / packing.semiAxis, sizes.back(), 1e-15);
}

TEST(Mixtures, OneSizedMixturesAreRefused) {
    ProtocolParameters allLarge = smallMixture(1);
    allLarge.largeFraction = 1.0;
    EXPECT_THROW(allLarge.validate(), ProtocolParameterError);
    ProtocolParameters ratio = smallMixture(1);
    ratio.sizeRatio = 0.7;
    EXPECT_THROW(ratio.validate(), ProtocolParameterError);
    ProtocolParameters both = smallMixture(1);
    both.polydispersity = 0.1;
    EXPECT_THROW(both.validate(), ProtocolParameterError);
    ProtocolParameters wide = smallMixture(1);
    wide.sizeRatio = 1.0;
    wide.polydispersity = 0.4;
    EXPECT_THROW(wide.validate(), ProtocolParameterError);
    EXPECT_NO_THROW(smallMixture(1).validate());
}

} // namespace
} // namespace sbpack

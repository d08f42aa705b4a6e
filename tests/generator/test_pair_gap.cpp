// The superball pair's gap function (shapes/superball/pair_gap.hpp) on its own, against known
// answers: the circumscribed spheres' window of a head-on approach, plane gaps that are the
// support planes' with their exact rates, the rate and curvature bounds over the whole window,
// samples of s along the motion (warm-started) against cold evaluations and the robust solver,
// their rates where the envelope theorem makes them exact, and the warm start a given contact
// leaves.
#include "shapes/superball/pair_gap.hpp"

#include "free_flight.hpp"
#include "geometry/superball.hpp"
#include "superball_pairs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace sbpack {
namespace {

using superball::circumscribedWindow;
using superball::SphereWindow;
using superball::SuperballPairGap;

const std::vector<double> kExponents = {0.75, 1.0, 1.5, 3.0, 10.0};

/// The shape's figures the gap function takes: c (circumradius over semi-axis) and the lever.
struct ShapeFigures {
    double c, lever;
};
ShapeFigures figuresOf(double p) {
    const Superball unit(p, 1.0);
    const double c = unit.circumradius(), cIn = unit.inradius();
    return {c, std::sqrt(c * c - cIn * cIn)};
}

/// The pair of motion m after tau, as common/pair sees it.
SuperballPair pairAt(const PairMotion& m, double p, double tau) {
    const PairMotion a = advancedPair(m, tau);
    return {Superball(p, 0.5 * a.diameter), a.orientationI.toRotationMatrix(),
            a.orientationJ.toRotationMatrix(), a.displacement};
}

/// A pair near contact (about `stretch` D apart) that drifts at up to `speed` D and turns at up to
/// `speed` rad per unit time, and grows at `growth` D per unit time.
PairMotion motionNearContact(double p, double stretch, double speed, double growth,
                             Random& random) {
    const SuperballPair pair = testing::pairNearContact(p, stretch, random);
    auto upTo = [&random](double size) {
        return Vector3d(random.normalVector().normalized() * (size * random.uniform()));
    };
    return {.displacement = pair.displacement,
            .relativeVelocity = upTo(speed),
            .orientationI = Quaterniond(pair.rotationA),
            .orientationJ = Quaterniond(pair.rotationB),
            .angularVelocityI = upTo(speed),
            .angularVelocityJ = upTo(speed),
            .diameter = 1.0,
            .growthRate = growth};
}

/// Everything a SuperballPairGap refers to, kept alive beside it.
struct GapUnderTest {
    PairMotion motion;
    double p, end;
    Vector3d normal = Vector3d::Zero();
    SuperballPredictorLimits limits{};
    PredictorStats stats{};
    SuperballPairGap gap() {
        const ShapeFigures f = figuresOf(p);
        return SuperballPairGap(motion, p, f.c, f.lever, end, normal, limits, stats);
    }
};

TEST(PairGap, CircumscribedWindowOfAHeadOnApproach) {
    const double c = figuresOf(3.0).c;
    // Closing at unit speed from 3 D: the spheres of diameter c D meet at 3 - c, part at 3 + c.
    const PairMotion m{.displacement = {3.0, 0.0, 0.0}, .relativeVelocity = {-1.0, 0.0, 0.0}};
    const std::optional<SphereWindow> window = circumscribedWindow(m, c, 10.0);
    ASSERT_TRUE(window);
    EXPECT_NEAR(window->enter, 3.0 - c, 1e-15);
    EXPECT_NEAR(window->end, 3.0 + c, 1e-14);
    EXPECT_EQ(circumscribedWindow(m, c, 4.0)->end, 4.0);     // the horizon first
    EXPECT_FALSE(circumscribedWindow(m, c, 3.0 - c - 1e-9)); // they do not meet before it
    PairMotion inside = m;
    inside.displacement = {0.5 * c, 0.0, 0.0};
    EXPECT_EQ(circumscribedWindow(inside, c, 10.0)->enter, 0.0);
    // Growing faster than they part (c gamma >= |v|): they never part for good.
    PairMotion growing = inside;
    growing.relativeVelocity = {0.1, 0.0, 0.0};
    growing.growthRate = 0.2;
    EXPECT_EQ(circumscribedWindow(growing, c, 7.0)->end, 7.0);
}

// g_n(0) = n.d - h_i(n) - h_j(n), and its rate is the derivative of g_n(tau) along the motion.
TEST(PairGap, PlaneGapIsTheSupportPlanesWithItsExactRate) {
    Random random(29);
    for (const double p : kExponents)
        for (int trial = 0; trial < 20; ++trial) {
            GapUnderTest t{motionNearContact(p, 1e-2, 1.0, 0.01 * trial / 20, random), p, 1.0};
            const SuperballPairGap gap = t.gap();
            const Vector3d n = random.normalVector().normalized();
            const SuperballPair pair = pairAt(t.motion, p, 0.0);
            EXPECT_NEAR(gap.planeGap(n, 0.0).gap, superball::atNormal(pair, n).signedDistance,
                        1e-15);
            const double tau = 0.5 * random.uniform(), h = 1e-6;
            const double difference =
                (gap.planeGap(n, tau + h).gap - gap.planeGap(n, tau - h).gap) / (2.0 * h);
            EXPECT_NEAR(gap.planeGap(n, tau).rate, difference, 1e-7)
                << "p " << p << " trial " << trial;
        }
}

// planeRate(n) bounds the rate from below and planeCurvature(n) the second derivative from above
// everywhere in [0, end].
TEST(PairGap, PlaneBoundsHoldOverTheWholeWindow) {
    Random random(31);
    for (const double p : kExponents)
        for (int trial = 0; trial < 10; ++trial) {
            GapUnderTest t{motionNearContact(p, 0.1, 1.0, 0.02, random), p, 0.5};
            const SuperballPairGap gap = t.gap();
            for (int plane = 0; plane < 10; ++plane) {
                const Vector3d n = random.normalVector().normalized();
                const double rate = gap.planeRate(n), curvature = gap.planeCurvature(n);
                const double h = 1e-4;
                for (double tau = h; tau <= t.end - h; tau += 0.01) {
                    EXPECT_GE(gap.planeGap(n, tau).rate, rate - 1e-12) << "p " << p;
                    const double second =
                        (gap.planeGap(n, tau + h).gap - 2.0 * gap.planeGap(n, tau).gap +
                         gap.planeGap(n, tau - h).gap) /
                        (h * h);
                    EXPECT_LE(second, curvature + 1e-6) << "p " << p << " tau " << tau;
                }
            }
        }
}

/// A sample of s after tau is exact (the robust solver's value) or, above the contact gap, a lower
/// bound that proves the pair apart.
void expectSampleOf(const Sample& sample, const SuperballPair& pair, const GapUnderTest& t) {
    const double robust = signedDistance(pair).signedDistance;
    if (sample.exact) {
        EXPECT_NEAR(sample.gap, robust, 1e-13) << "p " << t.p << " tau " << sample.tau;
    } else {
        EXPECT_GT(sample.gap, t.limits.contactGap * pair.shape.diameter());
        EXPECT_LE(sample.gap, robust + 1e-15) << "p " << t.p << " tau " << sample.tau;
    }
}

// Each sample is s of the pair after tau, warm-started along the motion from the last sample's
// normal carried at its rate. The pair stays apart (s from about 3e-4 to 2e-3 D).
TEST(PairGap, SamplesAreTheDistanceAlongTheMotion) {
    Random random(37);
    for (const double p : kExponents) {
        int exact = 0;
        for (int trial = 0; trial < 10; ++trial) {
            GapUnderTest t{motionNearContact(p, 1e-3, 1e-3, 1e-3, random), p, 0.2};
            SuperballPairGap gap = t.gap();
            for (int step = 0; step <= 20; ++step) {
                const double tau = 0.01 * step;
                const Sample sample = gap.at(tau);
                EXPECT_EQ(sample.tau, tau);
                expectSampleOf(sample, pairAt(t.motion, p, tau), t);
                EXPECT_EQ(sample.normal, t.normal); // the warm start moves on
                exact += sample.exact ? 1 : 0;
            }
            EXPECT_EQ(t.stats.evaluations, 21);
        }
        EXPECT_GT(exact, 0) << "p " << p; // not only lower bounds
    }
}

// Where no support point moves about its centre (pure translation), an exact sample's rate is
// ds/dtau = n.v; for spheres touching, whatever their spin and growth, ds/dtau = n.v - gamma.
TEST(PairGap, SampleRatesAreTheEnvelopeTheoremsWhereItIsExact) {
    Random random(41);
    for (const double p : kExponents)
        for (int trial = 0; trial < 10; ++trial) {
            GapUnderTest t{motionNearContact(p, 1e-3, 1.0, 0.0, random), p, 0.1};
            t.motion.angularVelocityI = t.motion.angularVelocityJ = Vector3d::Zero();
            SuperballPairGap gap = t.gap();
            const double h = 1e-6;
            const double difference = (signedDistance(pairAt(t.motion, p, h)).signedDistance -
                                       signedDistance(pairAt(t.motion, p, -h)).signedDistance) /
                                      (2.0 * h);
            const Sample sample = gap.given(signedDistance(pairAt(t.motion, p, 0.0)));
            EXPECT_NEAR(sample.rate, sample.normal.dot(t.motion.relativeVelocity), 1e-15);
            EXPECT_NEAR(sample.rate, difference, 1e-6) << "p " << p << " trial " << trial;
        }
    for (int trial = 0; trial < 10; ++trial) {
        GapUnderTest t{motionNearContact(1.0, 1e-12, 1.0, 0.01, random), 1.0, 0.1};
        SuperballPairGap gap = t.gap();
        const Sample sample = gap.at(0.0);
        ASSERT_TRUE(sample.exact);
        EXPECT_NEAR(sample.rate, sample.normal.dot(t.motion.relativeVelocity) - t.motion.growthRate,
                    1e-13);
    }
}

// A contact evaluated elsewhere is the sample at tau = 0 and the warm start of the next.
TEST(PairGap, AGivenContactIsTheFirstSampleAndTheWarmStart) {
    Random random(43);
    for (const double p : kExponents) {
        GapUnderTest t{motionNearContact(p, 1e-3, 1e-2, 0.0, random), p, 0.1};
        SuperballPairGap gap = t.gap();
        const SignedDistanceResult contact = signedDistance(pairAt(t.motion, p, 0.0));
        const Sample given = gap.given(contact);
        EXPECT_EQ(given.tau, 0.0);
        EXPECT_EQ(given.gap, contact.signedDistance);
        EXPECT_EQ(given.normal, contact.normal);
        EXPECT_EQ(t.normal, contact.normal);
        EXPECT_EQ(t.stats.evaluations, 0); // nothing evaluated
        expectSampleOf(gap.at(1e-3), pairAt(t.motion, p, 1e-3), t);
    }
}

} // namespace
} // namespace sbpack

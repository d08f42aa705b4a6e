// The superball predictor (SuperballShape::collisionTime, docs/design.md §3) against truths that do
// not depend on it: a brute-force first contact from the sign of mu(tau) - 1 (docs/design.md §2) on
// a fine grid, the exact sphere quadratic at p = 1, and the conservation laws of an elastic
// collision of two rotating bodies in the engine.
#include "engine/event_driven_md.hpp"
#include "free_flight.hpp"
#include "geometry/superball.hpp"
#include "initial/random_start.hpp"
#include "pair/pair_geometry.hpp"
#include "random/random.hpp"
#include "shapes/sphere.hpp"
#include "shapes/superball_shape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace sbpack {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// ---- The pair along its free flight ---------------------------------------------------------

/// The geometry of the pair after tau, for the pair solvers of common/pair (a mixture's pair: A
/// of diameter sizeI D, B scaled by sizeJ / sizeI).
SuperballPair pairAt(double p, const PairMotion& m, double tau) {
    const PairMotion a = advancedPair(m, tau);
    return {Superball(p, 0.5 * a.diameter * a.sizeI), a.orientationI.toRotationMatrix(),
            a.orientationJ.toRotationMatrix(), a.displacement, a.sizeJ / a.sizeI};
}

/// Signed distance after tau in units of the diameter then, from a cold start.
double relativeGapAt(double p, const PairMotion& m, double tau) {
    const SuperballPair pair = pairAt(p, m, tau);
    return signedDistance(pair).signedDistance / pair.shape.diameter();
}

/// First tau >= 0 at which balls of diameter ratio (D + gamma tau) about the two centres meet:
/// |d + w tau| = ratio (D + gamma tau), a tau^2 + 2 b tau + c = 0 (the exact sphere case).
double ballsMeet(const PairMotion& m, double ratio) {
    const double a = m.relativeVelocity.squaredNorm() - std::pow(ratio * m.growthRate, 2);
    const double b =
        m.displacement.dot(m.relativeVelocity) - ratio * ratio * m.diameter * m.growthRate;
    const double c = m.displacement.squaredNorm() - std::pow(ratio * m.diameter, 2);
    if (c <= 0.0) return 0.0;
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0 || (a >= 0.0 && b >= 0.0)) return kNever;
    return c / (-b + std::sqrt(discriminant));
}

// ---- Brute force, independent of the predictor -----------------------------------------------

/// The first contact of a pair from mu(tau) - 1 of cold scaleFactor() calls (its sign is that of
/// the signed distance): sampled on a grid fine against the pair's translation and rotation, each
/// sampled local minimum near 0 searched by golden section for a dip below 0 (thin grazing
/// contacts), the first sign change bisected to 1e-13. Sampling starts where the circumscribed
/// spheres meet (no contact before) and ends where the inscribed spheres meet (contact by then).
class BruteForce {
  public:
    BruteForce(double p, const PairMotion& m) : p_(p), m_(m) {}

    /// +inf if the grid sees no contact in [0, horizon]. `alsoAt`: a time added to the grid.
    double firstContact(double horizon, double alsoAt = -1.0) {
        const Superball unit(p_, 1.0);
        const double begin = ballsMeet(m_, unit.circumradius());
        const double end = std::min(horizon, ballsMeet(m_, unit.inradius()));
        if (!(begin <= end)) return kNever;
        const double spin = std::max(m_.angularVelocityI.norm(), m_.angularVelocityJ.norm());
        // 0.03 rad of rotation and 0.01 D of translation or growth per step at most.
        const double step = std::min({0.01, 0.03 / std::max(spin, 1e-9),
                                      0.01 * m_.diameter / (m_.relativeVelocity.norm() + 1e-9),
                                      0.01 * m_.diameter / (m_.growthRate + 1e-9)});
        std::vector<double> grid;
        for (double t = begin; t < end; t += step)
            grid.push_back(t);
        grid.push_back(end);
        if (alsoAt > begin && alsoAt < end) {
            grid.push_back(alsoAt);
            std::sort(grid.begin(), grid.end());
        }
        std::vector<double> excess;
        for (std::size_t k = 0; k < grid.size(); ++k) {
            excess.push_back(excessAt(grid[k]));
            if (excess[k] <= 0.0) return k == 0 ? grid[0] : bisect(grid[k - 1], grid[k]);
            // A sampled local minimum near touching at k - 1: search [k - 2, k] for a dip.
            if (k >= 2 && excess[k - 1] < excess[k - 2] && excess[k - 1] <= excess[k] &&
                excess[k - 1] < 0.05) {
                const double dip = lowestPoint(grid[k - 2], grid[k]);
                if (excessAt(dip) <= 0.0) return bisect(grid[k - 2], dip);
            }
        }
        return kNever;
    }

    long evaluations = 0;

  private:
    double excessAt(double tau) {
        ++evaluations;
        return scaleFactor(pairAt(p_, m_, tau)).scaleFactor - 1.0;
    }
    /// The last tau with mu > 1 before the sign change in (lo, hi].
    double bisect(double lo, double hi) {
        while (hi - lo > 1e-13 * (1.0 + hi)) {
            const double mid = 0.5 * (lo + hi);
            (excessAt(mid) > 0.0 ? lo : hi) = mid;
        }
        return lo;
    }
    /// Golden-section minimum of mu on [lo, hi] (unimodal there on a fine grid).
    double lowestPoint(double lo, double hi) {
        const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
        double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
        double f1 = excessAt(x1), f2 = excessAt(x2);
        while (hi - lo > 1e-9 && f1 > 0.0 && f2 > 0.0) {
            if (f1 <= f2) {
                hi = x2, x2 = x1, f2 = f1;
                x1 = hi - ratio * (hi - lo), f1 = excessAt(x1);
            } else {
                lo = x1, x1 = x2, f1 = f2;
                x2 = lo + ratio * (hi - lo), f2 = excessAt(x2);
            }
        }
        return f1 <= f2 ? x1 : x2;
    }

    double p_;
    const PairMotion& m_;
};

// ---- The predictor as the engine uses it -------------------------------------------------------

/// The engine's loop over one pair: predict; at a safe recheck time (contact == false) predict
/// again from there with the pair's memory moved on; until a contact or none up to the horizon.
/// With `pieces` > 1 each prediction is asked only up to the next of `pieces` equal parts of the
/// horizon (as the engine asks up to the pair's next event) and the next one starts there.
struct EnginePrediction {
    double time = kNever;             ///< the contact, +inf if none
    std::vector<double> recheckTimes; ///< the safe times on the way
    bool finished = false;            ///< within the bounded number of rounds
};

EnginePrediction predictLikeTheEngine(SuperballShape& shape, const PairMotion& m, double horizon,
                                      PairMemory& memory, int pieces = 1) {
    EnginePrediction result;
    double now = 0.0;
    for (int round = 0; round < 10000; ++round) {
        const double limit =
            horizon * std::min(1.0, std::floor(now / horizon * pieces + 1.0) / pieces);
        const Prediction next = shape.collisionTime(advancedPair(m, now), limit - now, memory);
        const bool none = std::isinf(next.time);
        if ((next.contact && !none) || (none && limit == horizon)) {
            result.time = now + next.time;
            result.finished = true;
            return result;
        }
        const double step = none ? limit - now : next.time;
        if (!(step > 0.0)) return result; // a recheck that makes no progress
        memory = memory.after(step);
        now += step;
        if (!none) result.recheckTimes.push_back(now);
    }
    return result;
}

// ---- Random pairs ------------------------------------------------------------------------------

/// Spins of the three families: none, slow (|omega| < 2) and fast (5 < |omega| < 20), D = 1.
Vector3d randomSpin(Random& random, int family) {
    const double size = family == 0   ? 0.0
                        : family == 1 ? 2.0 * random.uniform()
                                      : 5.0 + 15.0 * random.uniform();
    return size * random.normalVector().normalized();
}

/// Two bodies of diameter 1 at a random separation, aimed at each other with a random impact
/// parameter up to 1.2 D: hits and misses; s(0) > 0 as in the engine.
PairMotion randomApproach(double p, Random& random, int spinFamily, double gamma) {
    const Superball unit(p, 0.5);
    for (;;) {
        PairMotion m;
        const Vector3d direction = random.normalVector().normalized();
        m.displacement = direction * (2.0 * unit.inradius() +
                                      (2.0 * unit.circumradius() + 0.6) * random.uniform());
        Vector3d side = random.normalVector();
        side = (side - side.dot(direction) * direction).normalized();
        m.relativeVelocity =
            (0.3 + 1.2 * random.uniform()) * (-direction + 1.2 * random.uniform() * side);
        m.orientationI = random.rotation();
        m.orientationJ = random.rotation();
        m.angularVelocityI = randomSpin(random, spinFamily);
        m.angularVelocityJ = randomSpin(random, spinFamily);
        m.diameter = 1.0;
        m.growthRate = gamma;
        if (relativeGapAt(p, m, 0.0) > 0.0) return m;
    }
}

/// A grazing pass: at tau = closest the bodies are `gap` (in D) apart along their contact normal
/// n and the gap is stationary there (n . w cancels the normal speed that the spins and growth
/// give the two support points, by the envelope theorem); w has a random tangential part. The
/// pair is returned at tau = 0, with s(0) > 0.
PairMotion grazingPass(double p, Random& random, int spinFamily, double gamma, double gap,
                       double& closest) {
    for (;;) {
        closest = 0.3 + 1.7 * random.uniform();
        PairMotion m;
        m.diameter = 1.0 + gamma * closest; // at the closest approach
        m.growthRate = gamma;
        m.orientationI = random.rotation();
        m.orientationJ = random.rotation();
        m.angularVelocityI = randomSpin(random, spinFamily);
        m.angularVelocityJ = randomSpin(random, spinFamily);
        const Vector3d u = random.normalVector().normalized();
        const Superball body(p, 0.5 * m.diameter);
        SuperballPair pair{body, m.orientationI.toRotationMatrix(),
                           m.orientationJ.toRotationMatrix(), u};
        pair.displacement = u / scaleFactor(pair).scaleFactor; // touching
        const SignedDistanceResult touching = signedDistance(pair);
        const Vector3d& n = touching.normal;
        m.displacement = pair.displacement + gap * m.diameter * n;
        const Vector3d xI = touching.contactA, xJ = touching.contactB - pair.displacement;
        const double strain = gamma / m.diameter;
        const Vector3d surfaceI = m.angularVelocityI.cross(xI) + strain * xI;
        const Vector3d surfaceJ = m.angularVelocityJ.cross(xJ) + strain * xJ;
        Vector3d tangential = random.normalVector();
        tangential -= tangential.dot(n) * n;
        m.relativeVelocity = (0.3 + 1.2 * random.uniform()) * tangential.normalized() -
                             n.dot(surfaceJ - surfaceI) * n;
        const PairMotion start = advancedPair(m, -closest);
        if (relativeGapAt(p, start, 0.0) > 0.0) return start;
    }
}

// ---- Never misses, agrees with brute force -----------------------------------------------------

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", x);
    return text;
}

void printStats(double p, const PredictorStats& s) {
    std::printf("p %5.2f predictor: %ld calls, %ld sphere + %ld bound + %ld witness + %ld plane "
                "rejections, "
                "%ld evaluations (%ld robust), %ld plane steps (%ld chord), %ld Newton brackets "
                "(%ld uncertified), "
                "%ld refinement steps, %ld rechecks, %ld limit hits, %ld pair-solver fallbacks, "
                "%ld start overlaps\n",
                p, s.calls, s.sphereRejections, s.boundRejections, s.witnessRejections,
                s.planeRejections, s.evaluations, s.robustEvaluations, s.planeSteps, s.chordSteps,
                s.newtonBrackets, s.uncertifiedRoots, s.refinementSteps, s.rechecks, s.limitHits,
                s.distanceFallbacks, s.startOverlaps);
}

/// One ctest case: `pairs` pairs of exponent p from the shard's own seed.
struct Shard {
    double p;
    int index;
    int pairs;
    /// A mixture's pairs (docs/mixtures.md): the small body's diameter over the large one's, each
    /// pair's bodies in either order; 1: identical bodies.
    double sizeRatio = 1.0;
};

std::string shardName(const ::testing::TestParamInfo<Shard>& info) {
    char name[64];
    std::snprintf(name, sizeof name,
                  info.param.sizeRatio == 1.0 ? "p%g_shard%d" : "p%g_shard%d_mix", info.param.p,
                  info.param.index);
    std::string result = name;
    std::replace(result.begin(), result.end(), '.', '_');
    return result;
}

void PrintTo(const Shard& shard, std::ostream* out) {
    *out << "p " << shard.p << ", shard " << shard.index << ", " << shard.pairs << " pairs";
    if (shard.sizeRatio != 1.0) *out << " of size ratio " << shard.sizeRatio;
}

/// randomApproach with the bodies of diameters 2 r / (1 + r) and 2 / (1 + r) about their mean D
/// = 1 (the small one first where `smallFirst`), again until s(0) > 0.
PairMotion mixtureApproach(double p, Random& random, int spinFamily, double gamma, double r,
                           bool smallFirst) {
    for (;;) {
        PairMotion m = randomApproach(p, random, spinFamily, gamma);
        m.sizeI = (smallFirst ? 2.0 * r : 2.0) / (1.0 + r);
        m.sizeJ = 2.0 - m.sizeI;
        if (relativeGapAt(p, m, 0.0) > 0.0) return m;
    }
}

class SuperballPredictorByP : public ::testing::TestWithParam<Shard> {};

// 10^4 pairs per p in shards, half aimed at random, half grazing passes with a gap of
// 1e-9 .. 1e-6 D at the closest approach on either side of zero; no, slow and fast spins; growth
// 0 and > 0. Each pair is predicted from a cold normal, then again warm from the normal that
// call left behind and in eight pieces, so that the gap bound each piece leaves rejects later
// ones unevaluated, each time in the engine's loop over safe recheck times.
TEST_P(SuperballPredictorByP, NeverMissesAndAgreesWithBruteForce) {
    const double p = GetParam().p;
    const int pairs = GetParam().pairs;
    const double horizon = 3.0;
    SuperballShape shape{p};
    Random random(1000 + static_cast<std::uint64_t>(100 * p) + 7919 * GetParam().index);
    long bruteEvaluations = 0;
    int bruteContacts = 0, agreed = 0, thinContacts = 0, grazes = 0, grazesTouching = 0;
    int recheckRounds = 0, shallow = 0, flat = 0;
    // Touching for the engine is s <= contactGap D as the predictor evaluates s: a lower bound
    // certified to within the supporting planes' mismatch tolerance (near-cube faces), and up to
    // 1e-15 D of rounding between its warm and the test's cold evaluation.
    const double touchingGap = shape.limits.contactGap + PairTolerances{}.mismatchTolerance + 1e-15;
    for (int trial = 0; trial < pairs; ++trial) {
        const int spinFamily = (trial / 2) % 3;
        const double gamma = (trial / 6) % 2 == 0 ? 0.0 : 0.01 + 0.09 * random.uniform();
        const double ratio = GetParam().sizeRatio;
        const bool grazing = trial % 2 == 1 && ratio == 1.0; // grazing passes of one size
        double closest = -1.0;
        double gap = 0.0;
        PairMotion m;
        if (ratio != 1.0) {
            m = mixtureApproach(p, random, spinFamily, gamma, ratio, trial % 2 == 1);
        } else if (grazing) {
            gap = std::pow(10.0, -9.0 + 3.0 * random.uniform()) * ((trial / 12) % 2 ? 1.0 : -1.0);
            m = grazingPass(p, random, spinFamily, gamma, gap, closest);
            ++grazes;
        } else {
            m = randomApproach(p, random, spinFamily, gamma);
        }
        BruteForce brute(p, m);
        const double first = brute.firstContact(horizon, closest);
        bruteEvaluations += brute.evaluations;
        if (grazing && gap < 0.0) {
            // By construction s(closest) = gap < 0: the grid, which holds closest, sees it.
            ASSERT_LE(first, closest) << "p " << p << " #" << trial;
            ++grazesTouching;
        }
        if (!std::isinf(first)) ++bruteContacts;

        PairMemory memory;
        for (const char* start : {"cold", "warm"}) {
            memory = PairMemory{memory.normal}; // the warm start alone, no record of a future
            const EnginePrediction predicted =
                predictLikeTheEngine(shape, m, horizon, memory, start[0] == 'c' ? 1 : 8);
            const std::string where = "p " + number(p) + " #" + std::to_string(trial) + " (" +
                                      start + " normal), brute " + number(first) + ", predicted " +
                                      number(predicted.time);
            ASSERT_TRUE(predicted.finished) << where;
            recheckRounds += static_cast<int>(predicted.recheckTimes.size());
            // A safe recheck time is never later than the first contact.
            for (const double safe : predicted.recheckTimes)
                ASSERT_LE(safe, first + 1e-9) << where << ", recheck at " << safe;
            // No missed collision: a contact the brute force sees is predicted, never later.
            if (!std::isinf(first)) {
                ASSERT_FALSE(std::isinf(predicted.time)) << "missed: " << where;
            }
            if (std::isinf(predicted.time)) continue;
            // Touching at the predicted time, never overlapping.
            const double touching = relativeGapAt(p, m, predicted.time);
            EXPECT_GE(touching, -1e-12) << where;
            EXPECT_LE(touching, 1e-9) << where;
            if (predicted.time > first + 1e-9) {
                // Later than the brute force only where s stays within rounding of 0 from the
                // brute contact to the predicted one (a flat crossing, |s'| ~ 1e-7 D per unit
                // time: which sign flip of the rounding noise is "first" is arbitrary).
                for (int k = 0; k <= 10; ++k)
                    ASSERT_GE(relativeGapAt(p, m, first + 0.1 * k * (predicted.time - first)),
                              -shape.limits.contactGap)
                        << "later than the brute force: " << where;
                ASSERT_LE(touching, touchingGap) << where;
                ASSERT_LE(predicted.time, first + 1e-6) << where;
                flat += start[0] == 'c';
                continue;
            }
            if (predicted.time >= first - 1e-9) {
                agreed += start[0] == 'c';
                continue;
            }
            // Earlier by more than 1e-9 but already touching by the engine's criterion: a
            // crossing so shallow (|s'| < contactGap D / 1e-9) that the engine's touching gap is
            // worth more than 1e-9 in time.
            if (touching <= touchingGap) {
                shallow += start[0] == 'c';
                continue;
            }
            // Otherwise only a real contact thinner than the grid. The witness: mu <= 1 just
            // after the predicted time, well before the brute contact.
            bool witnessed = false;
            for (double delta = 1e-12; delta <= 1e-7 && !witnessed; delta *= 10.0) {
                const double tau = predicted.time + delta * (1.0 + predicted.time);
                witnessed = tau < first - 1e-9 && scaleFactor(pairAt(p, m, tau)).scaleFactor <= 1.0;
            }
            EXPECT_TRUE(witnessed) << "a contact the brute force does not see: " << where << ", s "
                                   << touching << " D";
            thinContacts += start[0] == 'c';
        }
    }
    std::printf(
        "p %5.2f: %d pairs (%d grazing, %d of them touching), %d brute-force contacts, "
        "%d agree to 1e-9, %d within the touching gap (shallow), %d flat, %d thinner than the "
        "grid, %d recheck rounds; brute force %ld evaluations\n",
        p, pairs, grazes, grazesTouching, bruteContacts, agreed, shallow, flat, thinContacts,
        recheckRounds, bruteEvaluations);
    printStats(p, shape.stats);
    EXPECT_GT(bruteContacts, pairs / 4);
    EXPECT_GT(shape.stats.boundRejections, 0); // the pieces' bounds were used
    if (GetParam().sizeRatio == 1.0) {         // and their witness records, on the grazing passes
        EXPECT_GT(shape.stats.witnessRejections, 0);
    }
    EXPECT_GE(agreed + shallow + flat, bruteContacts - thinContacts);
}

/// `total` pairs of exponent p in shards of `each` (of a mixture's size ratio where given).
std::vector<Shard> shards(double p, int total, int each, double sizeRatio = 1.0) {
    std::vector<Shard> result;
    for (int k = 0; k * each < total; ++k)
        result.push_back({p, k, std::min(each, total - k * each), sizeRatio});
    return result;
}

// Shards of <= ~40 s on one core in Release (measured with both cores busy: 10^4 pairs take ~60 s
// at p 0.55, 18 s at 0.85, 32 s at 1.5, 80 s at 3 and 400 s at 10, where the pair solvers'
// cutting-plane finishes and the rechecks of pairs that slide face on face dominate).
INSTANTIATE_TEST_SUITE_P(Exponents055, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(0.55, 10000, 5000)), shardName);
INSTANTIATE_TEST_SUITE_P(Exponents085, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(0.85, 10000, 10000)), shardName);
INSTANTIATE_TEST_SUITE_P(Exponents15, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(1.5, 10000, 10000)), shardName);
INSTANTIATE_TEST_SUITE_P(Exponents3, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(3.0, 10000, 2500)), shardName);
INSTANTIATE_TEST_SUITE_P(Exponents10, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(10.0, 10000, 150)), shardName);
// A mixture's pairs (docs/mixtures.md): bodies of two sizes, ratio 0.6, aimed at random.
INSTANTIATE_TEST_SUITE_P(Mixtures085, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(0.85, 2000, 2000, 0.6)), shardName);
INSTANTIATE_TEST_SUITE_P(Mixtures15, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(1.5, 2000, 2000, 0.6)), shardName);
INSTANTIATE_TEST_SUITE_P(Mixtures3, SuperballPredictorByP,
                         ::testing::ValuesIn(shards(3.0, 1000, 1000, 0.6)), shardName);

// ---- A stale cached normal -------------------------------------------------------------------

// The engine warm-starts every exact evaluation from the pair's cached normal, which can be far
// off (the pair rotated since). The worst start, the normal from j back to i, where f is at its
// lowest and Newton cannot ascend, must give the same first contact as a cold start: the face
// restart, the lower bound far from contact and the robust solver between them recover.
TEST(SuperballPredictor, AStaleNormalFromTheWrongSideGivesTheSameContact) {
    for (const double p : {0.55, 1.5, 3.0, 10.0}) {
        SuperballShape shape{p};
        Random random(13 + static_cast<std::uint64_t>(10 * p));
        int hits = 0;
        for (int trial = 0; trial < 60; ++trial) {
            const double gamma = trial % 2 == 0 ? 0.0 : 0.01 + 0.09 * random.uniform();
            const PairMotion m = randomApproach(p, random, trial % 3, gamma);
            PairMemory cold;
            PairMemory wrong{-m.displacement.normalized()};
            const EnginePrediction fresh = predictLikeTheEngine(shape, m, 3.0, cold);
            const EnginePrediction stale = predictLikeTheEngine(shape, m, 3.0, wrong);
            const std::string where = "p " + number(p) + " trial " + std::to_string(trial);
            ASSERT_TRUE(fresh.finished && stale.finished) << where;
            if (std::isinf(fresh.time)) {
                EXPECT_TRUE(std::isinf(stale.time)) << where << ": " << stale.time;
                continue;
            }
            ++hits;
            EXPECT_NEAR(stale.time, fresh.time, 1e-9) << where;
        }
        EXPECT_GT(hits, 20) << "p " << number(p);
    }
}

/// Two bodies of diameter 1 in random orientations touching (s = 0 to rounding) along a random
/// direction, then `gap` further apart along it (s in (0, gap]: s is 1-Lipschitz in d); returns
/// the pair's contact normal.
Vector3d touchingPair(double p, Random& random, double gap, PairMotion& m) {
    m.diameter = 1.0;
    m.orientationI = random.rotation();
    m.orientationJ = random.rotation();
    const Vector3d u = random.normalVector().normalized();
    SuperballPair pair{Superball(p, 0.5), m.orientationI.toRotationMatrix(),
                       m.orientationJ.toRotationMatrix(), u};
    m.displacement = u / scaleFactor(pair).scaleFactor + gap * u;
    pair.displacement = m.displacement;
    return signedDistance(pair).normal;
}

// Right after a collision the engine re-predicts the pair at the same state; the resolver left it
// separating at its contact point, so touching now is no contact then (near-cube faces: another
// evaluation may pick another point of the face and see it closing, and zero impulses repeated at
// one instant). A pair that is closing still gets its contact, a moment later and not overlapping.
TEST(SuperballPredictor, AJustResolvedPairIsNotAContactAtThatInstant) {
    for (const double p : {1.5, 10.0}) {
        Random random(29 + static_cast<std::uint64_t>(p));
        for (int trial = 0; trial < 50; ++trial) {
            PairMotion m;
            const Vector3d n = touchingPair(p, random, 0.0, m);
            const std::string where = "p " + number(p) + " #" + std::to_string(trial);
            SuperballShape shape{p};
            m.relativeVelocity = -0.5 * n; // closing
            PairMemory memory;
            EXPECT_EQ(shape.collisionTime(m, 1.0, memory).time, 0.0) << where;
            memory = {};
            const PairMemory::Resolved resolved{m.displacement, std::nullopt};
            const Prediction later = shape.collisionTime(m, 1.0, memory, &resolved);
            ASSERT_TRUE(later.contact) << where;
            EXPECT_GT(later.time, 0.0) << where;
            EXPECT_LE(later.time, 1e-9) << where;
            EXPECT_GE(relativeGapAt(p, m, later.time), -1e-12) << where;
            m.relativeVelocity = 0.5 * n; // separating
            memory = {};
            EXPECT_TRUE(std::isinf(shape.collisionTime(m, 1.0, memory, &resolved).time)) << where;
        }
    }
}

// The same at a gap just above zero (within the contact gap 1e-14 D) with spins that can bend
// s(tau) down: Newton's step in time from the touching sample then overshoots, and the refined
// bracket used to end on that sample, a contact at the resolved instant again (a p = 10,
// N = 1000 run repeated 10^4 zero impulses at one instant and stopped).
TEST(SuperballPredictor, AJustResolvedPairJustApartIsNotAContactAtThatInstantEither) {
    for (const double p : {1.5, 3.0, 10.0}) {
        Random random(31 + static_cast<std::uint64_t>(p));
        for (int trial = 0; trial < 50; ++trial) {
            PairMotion m;
            const Vector3d n = touchingPair(p, random, 5e-15, m);
            m.relativeVelocity = -0.5 * n;
            m.angularVelocityI = random.normalVector();
            m.angularVelocityJ = random.normalVector();
            SuperballShape shape{p};
            PairMemory memory;
            const PairMemory::Resolved resolved{m.displacement, std::nullopt};
            const Prediction later = shape.collisionTime(m, 1.0, memory, &resolved);
            const std::string where = "p " + number(p) + " #" + std::to_string(trial);
            EXPECT_FALSE(later.contact && later.time == 0.0) << where;
            if (later.contact && std::isfinite(later.time)) {
                EXPECT_GE(relativeGapAt(p, m, later.time), -1e-12) << where;
            }
        }
    }
}

/// The pair seen from j: displacement and velocity negated, the bodies swapped.
PairMotion seenFromJ(const PairMotion& m) {
    PairMotion r = m;
    r.displacement = -m.displacement;
    r.relativeVelocity = -m.relativeVelocity;
    std::swap(r.orientationI, r.orientationJ);
    std::swap(r.angularVelocityI, r.angularVelocityJ);
    std::swap(r.turnedI, r.turnedJ);
    return r;
}

/// The plane gap of unit n for the pair of m, in units of D.
double planeGapOf(double p, const PairMotion& m, const Vector3d& n) {
    const SuperballPair pair = pairAt(p, m, 0.0);
    const double h = pair.shape.support(pair.rotationA.transpose() * n) +
                     pair.shape.support(pair.rotationB.transpose() * n);
    return (n.dot(m.displacement) - h) / m.diameter;
}

// The engine's contact starts from the normal the pair's prediction found at the root:
// that normal's plane is the optimal one there, within rounding of the exact contact computed
// afresh (the independent check: a cold pair solver from the centre line).
TEST(SuperballPredictor, TheContactAtAPredictedRootTakesThePredictedNormal) {
    for (const double p : {1.5, 3.0, 10.0}) {
        Random random(37 + static_cast<std::uint64_t>(p));
        int hits = 0;
        for (int trial = 0; trial < 60; ++trial) {
            const PairMotion m = randomApproach(p, random, trial % 3, trial % 2 ? 0.05 : 0.0);
            SuperballShape shape{p};
            PairMemory memory;
            const Prediction next = shape.collisionTime(m, 3.0, memory);
            if (!next.contact || std::isinf(next.time)) continue;
            ++hits;
            const std::string where = "p " + number(p) + " #" + std::to_string(trial);
            ASSERT_TRUE(memory.atContact) << where;
            const Vector3d predicted = memory.normal;
            const PairMotion atRoot = advancedPair(m, next.time);
            const double s = relativeGapAt(p, atRoot, 0.0);
            PairMemory::Resolved resolved;
            const PairContact taken = shape.contact(atRoot, memory, resolved);
            EXPECT_EQ(shape.stats.predictedContacts, 1) << where;
            EXPECT_EQ(taken.normal, predicted) << where;
            // The predicted plane is optimal to rounding: its gap is s (a plane's gap never
            // exceeds s), and the contact is within the contact gap.
            EXPECT_NEAR(planeGapOf(p, atRoot, taken.normal), s, 1e-14) << where;
            EXPECT_LE(std::abs(s), 2e-14) << where;
        }
        EXPECT_GT(hits, 20) << "p " << number(p);
    }
}

/// The engine's predictions of a pair it has just resolved: the first with `resolved`, then on
/// from each safe recheck time (predictLikeTheEngine); the contact, +inf if none to the horizon.
double resolvedThenLikeTheEngine(SuperballShape& shape, const PairMotion& m, double horizon,
                                 PairMemory& memory, const PairMemory::Resolved& resolved) {
    const Prediction first = shape.collisionTime(m, horizon, memory, &resolved);
    if (first.contact || std::isinf(first.time)) return first.time;
    memory = memory.after(first.time);
    const EnginePrediction rest =
        predictLikeTheEngine(shape, advancedPair(m, first.time), horizon - first.time, memory);
    EXPECT_TRUE(rest.finished);
    return first.time + rest.time;
}

// Right after contact() the engine predicts the resolved pair again at that state, from i and
// from j: the contact stands in for the first evaluation. The predictions must be those of a
// shape that evaluates it afresh.
TEST(SuperballPredictor, TheResolvedPairStartsFromItsContactAsFromAnEvaluation) {
    for (const double p : {1.5, 3.0, 10.0}) {
        Random random(41 + static_cast<std::uint64_t>(p));
        long saved = 0;
        for (int trial = 0; trial < 60; ++trial) {
            const PairMotion m = randomApproach(p, random, trial % 3, 0.0);
            SuperballShape shape{p};
            PairMemory memory;
            const Prediction next = shape.collisionTime(m, 3.0, memory);
            if (!next.contact || std::isinf(next.time)) continue;
            PairMotion after = advancedPair(m, next.time);
            PairMemory::Resolved resolved;
            const PairContact contact = shape.contact(after, memory, resolved);
            ParticleState i{Vector3d::Zero(), Vector3d::Zero(), {}, after.angularVelocityI};
            ParticleState j{after.displacement, after.relativeVelocity, {}, after.angularVelocityJ};
            shape.resolve(after, contact, i, j);
            after.relativeVelocity = j.velocity - i.velocity;
            after.angularVelocityI = i.angularVelocity;
            after.angularVelocityJ = j.angularVelocity;
            for (const bool fromI : {true, false}) {
                const PairMotion side = fromI ? after : seenFromJ(after);
                const std::string where = "p " + number(p) + " #" + std::to_string(trial);
                SuperballShape fresh{p};
                PairMemory mine{(fromI ? 1.0 : -1.0) * contact.normal};
                PairMemory theirs = mine;
                const long before = shape.stats.evaluations;
                const double reused = resolvedThenLikeTheEngine(
                    shape, side, 3.0, mine, fromI ? resolved : resolved.seenFromOther());
                const double evaluated = resolvedThenLikeTheEngine(
                    fresh, side, 3.0, theirs, {side.displacement, std::nullopt});
                saved += fresh.stats.evaluations - (shape.stats.evaluations - before);
                if (std::isinf(evaluated)) {
                    EXPECT_TRUE(std::isinf(reused)) << where << ": " << reused;
                } else {
                    EXPECT_NEAR(reused, evaluated, 1e-9) << where;
                    EXPECT_GT(reused, 0.0) << where;
                }
            }
        }
        EXPECT_GT(saved, 20) << "p " << number(p) << ": evaluations spared";
    }
}

// ---- p = 1: the general path against the exact sphere quadratic --------------------------------

// Spheres are the p = 1 superballs: SuperballShape's general path (advancement on s, Newton,
// refinement) must give the exact quadratic's time; spins are invisible to spheres.
TEST(SuperballPredictor, SphereCaseAgreesWithTheExactQuadratic) {
    SuperballShape ball{1.0};
    const SphereShape sphere;
    const double horizon = 3.0;
    Random random(11);
    int hits = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const double gamma = trial % 2 == 0 ? 0.0 : 0.01 + 0.09 * random.uniform();
        const PairMotion m = randomApproach(1.0, random, trial % 3, gamma);
        const double exact = sphere.collisionTime(m);
        PairMemory memory;
        const double tau = predictLikeTheEngine(ball, m, horizon, memory).time;
        if (exact > horizon) {
            EXPECT_TRUE(std::isinf(tau)) << trial << ": " << tau;
            continue;
        }
        ++hits;
        EXPECT_NEAR(tau, exact, 1e-9) << trial;
    }
    EXPECT_GT(hits, 200);
}

// ---- The engine: one elastic collision of two rotating bodies ---------------------------------

/// Linear and angular momentum (about the origin) and kinetic energy of unit-mass bodies with
/// isotropic inertia I: sum v, sum r x v + I omega, sum (v^2 + I omega^2) / 2.
struct Invariants {
    Vector3d momentum = Vector3d::Zero();
    Vector3d angularMomentum = Vector3d::Zero();
    double energy = 0.0;
};

Invariants invariants(const std::vector<ParticleState>& particles, double inertia) {
    Invariants sum;
    for (const ParticleState& s : particles) {
        sum.momentum += s.velocity;
        sum.angularMomentum += s.position.cross(s.velocity) + inertia * s.angularVelocity;
        sum.energy += 0.5 * (s.velocity.squaredNorm() + inertia * s.angularVelocity.squaredNorm());
    }
    return sum;
}

/// Signed distance of bodies i and j of the engine's synchronised state, in units of D.
double pairGap(const EventDrivenMd<SuperballShape>& engine, int i, int j) {
    const auto& s = engine.particles();
    const SuperballPair pair{Superball(engine.shape().p(), 0.5 * engine.diameter()),
                             s[i].orientation.toRotationMatrix(),
                             s[j].orientation.toRotationMatrix(),
                             minimumImage(s[j].position - s[i].position, engine.boxLength())};
    return signedDistance(pair).signedDistance / engine.diameter();
}

// A free collision (gamma = 0) in a big box: the impulse acts at one common point, so linear and
// angular momentum are conserved exactly, and the elastic impulse conserves kinetic energy,
// translational plus rotational.
TEST(SuperballEngine, FreeCollisionConservesMomentumAngularMomentumAndEnergy) {
    for (const double p : {0.55, 0.85, 1.5, 3.0})
        for (const std::uint64_t seed : {1, 2, 3, 4}) {
            Random random(seed + static_cast<std::uint64_t>(100 * p));
            SuperballShape shape{p};
            const double inertia = shape.inertiaPerMass(1.0);
            // Centres 2.5 D apart on x, closing at ~1 with an impact parameter < 0.2 D.
            std::vector<ParticleState> state(2);
            state[0].position = Vector3d(3.75, 5.0, 5.0);
            state[1].position = Vector3d(6.25, 5.0, 5.0) + 0.1 * random.normalVector();
            state[0].velocity = Vector3d(0.5, 0.0, 0.0) + 0.05 * random.normalVector();
            state[1].velocity = Vector3d(-0.5, 0.0, 0.0) + 0.05 * random.normalVector();
            for (ParticleState& s : state) {
                s.orientation = random.rotation();
                s.angularVelocity = 3.0 * random.normalVector();
            }
            const Invariants before = invariants(state, inertia);
            EventDrivenMd<SuperballShape> engine(shape, 10.0, state, GrowthClock{1.0, 0.0, 0.0});
            const RunReport report = engine.run(1);
            const std::string where = "p " + number(p) + " seed " + std::to_string(seed);
            ASSERT_EQ(report.collisions, 1u) << where;
            const Invariants after = invariants(engine.particles(), inertia);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(after.momentum[k], before.momentum[k], 1e-12) << where;
                EXPECT_NEAR(after.angularMomentum[k], before.angularMomentum[k], 1e-12) << where;
            }
            EXPECT_NEAR(after.energy, before.energy, 1e-12) << where;
            // The velocities changed (a real impulse), and the bodies touch without overlap.
            EXPECT_GT((engine.particles()[0].velocity - state[0].velocity).norm(), 1e-3) << where;
            const double gap = pairGap(engine, 0, 1);
            EXPECT_GE(gap, -1e-12) << where;
            EXPECT_LE(gap, 1e-9) << where;
        }
}

// A dense growing fluid of superballs (phi 0.3 -> ~0.45, kT rescaled to 1 as the protocol does):
// after thousands of collisions no pair overlaps (docs/design.md §3: the predictor never misses).
TEST(SuperballEngine, NoOverlapAfterDenseGrowingRuns) {
    for (const double p : {1.5, 0.85}) {
        const int n = 64;
        Random random(7 + static_cast<std::uint64_t>(100 * p));
        SuperballShape shape{p};
        const double box = boxLengthFor(n, Superball(p, 0.5).volume(), 0.3);
        const RandomPlacement placement = randomPlacement(shape, n, box, random);
        const auto velocities = maxwellVelocities(n, random);
        const auto spins = maxwellAngularVelocities(n, shape.inertiaPerMass(1.0), random);
        std::vector<ParticleState> state(n);
        for (int i = 0; i < n; ++i)
            state[i] = {placement.positions[i], velocities[i], placement.orientations[i], spins[i]};
        EventDrivenMd<SuperballShape> engine(shape, box, state, GrowthClock{1.0, 0.0, 0.05});
        std::uint64_t collisions = 0;
        for (int k = 0; k < 8; ++k) {
            collisions += engine.run(500).collisions;
            engine.scaleVelocities(1.0 / std::sqrt(engine.kineticTemperature()));
            engine.scaleAngularVelocities(1.0 / std::sqrt(engine.rotationalTemperature()));
        }
        const double phi = n * Superball(p, 0.5 * engine.diameter()).volume() / std::pow(box, 3);
        double smallest = kNever;
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j)
                smallest = std::min(smallest, pairGap(engine, i, j));
        std::printf("p %.2f: N %d, %llu collisions, phi 0.3 -> %.3f, smallest gap %.3e D\n", p, n,
                    static_cast<unsigned long long>(collisions), phi, smallest);
        EXPECT_EQ(collisions, 4000u);
        EXPECT_GT(phi, 0.4);
        EXPECT_GE(smallest, -1e-10) << "p " << p;
        // The pairs' remembered gap bounds did the work of plane gaps along the way.
        EXPECT_GT(engine.shape().stats.boundRejections, 0) << "p " << p;
    }
}

} // namespace
} // namespace sbpack

// The shape-independent first-contact search (shapes/first_contact_search.hpp) on an analytic gap
// function: two eccentric spheres, each a ball whose centre sits at an offset e_k from its
// particle's centre and turns with the particle's spin, the particles translating apart at a
// constant velocity. Its signed distance, plane gaps and their bounds are closed forms, so the
// search is checked against roots known exactly (head-on approach, a spin-driven dip) and
// against a certified brute force (s is Lipschitz: a grid proves where no root lies), in
// milliseconds, without any superball.
#include "shapes/first_contact_search.hpp"

#include "random/random.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <optional>

namespace sbpack {
namespace {

/// Two balls of radii summing to `reach`, ball k centred at Q_k(tau) e_k about particle k
/// (Q_k the rotation by omega_k tau), particle j at d + w tau from particle i. Every vector is
/// given: `{}` would leave an Eigen vector uninitialised (the CI once found a receding pair
/// touching so).
struct EccentricSpheres {
    Vector3d d, w, omegaI, omegaJ, offsetI, offsetJ;
    double reach = 1.0;

    static Vector3d turned(const Vector3d& omega, const Vector3d& e, double tau) {
        const double angle = omega.norm() * tau;
        return angle == 0.0 ? e : Eigen::AngleAxisd(angle, omega.normalized()) * e;
    }
    /// The vector between the balls' centres after tau, and its rate.
    Vector3d between(double tau) const {
        return d + w * tau + turned(omegaJ, offsetJ, tau) - turned(omegaI, offsetI, tau);
    }
    Vector3d betweenRate(double tau) const {
        return w + omegaJ.cross(turned(omegaJ, offsetJ, tau)) -
               omegaI.cross(turned(omegaI, offsetI, tau));
    }
    double s(double tau) const { return between(tau).norm() - reach; }
    /// Lipschitz constant of s: |ds/dtau| <= |w| + |omega_i| e_i + |omega_j| e_j.
    double lipschitz() const {
        return w.norm() + omegaI.norm() * offsetI.norm() + omegaJ.norm() * offsetJ.norm();
    }
};

/// The balls as a GapFunction: g_n = n . between - reach, whose rate is bounded by the lever
/// |n x omega_k| e_k and whose second derivative n . (omega x (omega x c)) by
/// |n x omega_k| |omega_k| e_k; s is exact (the plane of the centre line).
class EccentricGap {
  public:
    explicit EccentricGap(const EccentricSpheres& balls) : b_(balls) {}

    PlaneGap planeGap(const Vector3d& n, double tau) const {
        return {n.dot(b_.between(tau)) - b_.reach, n.dot(b_.betweenRate(tau))};
    }
    double planeRate(const Vector3d& n) const {
        return n.dot(b_.w) - n.cross(b_.omegaI).norm() * b_.offsetI.norm() -
               n.cross(b_.omegaJ).norm() * b_.offsetJ.norm();
    }
    double planeCurvature(const Vector3d& n) const {
        return n.cross(b_.omegaI).norm() * b_.omegaI.norm() * b_.offsetI.norm() +
               n.cross(b_.omegaJ).norm() * b_.omegaJ.norm() * b_.offsetJ.norm();
    }
    Sample at(double tau) {
        ++samples;
        const Vector3d n = b_.between(tau).normalized();
        const double rate = n.dot(b_.betweenRate(tau));
        return {tau, b_.s(tau), rate, n, rate, true};
    }
    Sample given(const SignedDistanceResult& r) {
        const double rate = r.normal.dot(b_.betweenRate(0.0));
        return {0.0, r.signedDistance, rate, r.normal, rate, true};
    }
    int samples = 0;

  private:
    const EccentricSpheres& b_;
};
static_assert(GapFunction<EccentricGap>);

const Vector3d kZero = Vector3d::Zero(); ///< no velocity, spin or offset

/// The search from tau = 0 over [0, end], starting from the centre line's plane.
Found search(const EccentricSpheres& balls, double end, int* samples = nullptr) {
    EccentricGap gap(balls);
    const FirstContactLimits limits{};
    PredictorStats stats;
    FirstContactSearch<EccentricGap> first(gap, end, balls.reach, limits, stats);
    const Vector3d n = balls.between(0.0).normalized();
    const Found found = first.advance(0.0, n, gap.planeGap(n, 0.0), false, std::nullopt);
    if (samples) *samples = gap.samples;
    return found;
}

/// The search's contact is the first root's: touching there (within the contact gap, either
/// side), and within the contact gap's worth of time of `root`.
void expectTheRoot(const EccentricSpheres& balls, const Found& found, double root) {
    ASSERT_TRUE(found.contact);
    const double touching = FirstContactLimits{}.contactGap * balls.reach;
    const Vector3d n = balls.between(root).normalized();
    const double slope = std::abs(n.dot(balls.betweenRate(root)));
    EXPECT_LE(std::abs(balls.s(found.time)), touching);
    EXPECT_NEAR(found.time, root, 1.01 * touching / slope + 1e-15 * (1.0 + root));
}

TEST(FirstContactSearch, HeadOnSpheresTouchAtTheClosedFormRoot) {
    // |d| - reach = 0.5 closed at speed 2: the root is 0.25 exactly.
    const EccentricSpheres balls{{1.5, 0, 0}, {-2, 0, 0}, kZero, kZero, kZero, kZero, 1.0};
    const Found found = search(balls, 10.0);
    expectTheRoot(balls, found, 0.25);
    EXPECT_NEAR(found.normal.x(), 1.0, 1e-15);
}

TEST(FirstContactSearch, ARecedingOrGrazingPairIsNeverAContact) {
    const EccentricSpheres receding{{1.5, 0, 0}, {2, 0, 0}, kZero, kZero, kZero, kZero, 1.0};
    EXPECT_EQ(search(receding, 10.0).time, kNoContact);
    // Passing at 1 + 1e-9 from centre to centre: s falls to 1e-9 and rises again.
    const EccentricSpheres grazing{{-3, 1 + 1e-9, 0}, {1, 0, 0}, kZero, kZero, kZero, kZero, 1.0};
    const Found missed = search(grazing, 10.0);
    EXPECT_FALSE(missed.contact && missed.time < 10.0) << missed.time;
    // And 1e-9 closer: a root exists, at sqrt(reach^2 - b^2) before the closest approach.
    const EccentricSpheres clipping{{-3, 1 - 1e-9, 0}, {1, 0, 0}, kZero, kZero, kZero, kZero, 1.0};
    expectTheRoot(clipping, search(clipping, 10.0), 3.0 - std::sqrt(1.0 - std::pow(1 - 1e-9, 2)));
}

TEST(FirstContactSearch, ASpinDrivenDipIsCaughtAtItsFirstRoot) {
    // Particles at rest, 1.05 apart; ball i's centre turns at radius 0.1 towards j: the centres'
    // distance^2 is 1.1125 - 0.21 sin(omega tau), which reaches 1 where sin(omega tau) =
    // 0.1125 / 0.21. The rate bound is spin alone, so the first-order steps are long against
    // the dip: the curvature (chord) bound has to certify them.
    const double omega = 40.0;
    const EccentricSpheres balls{{1.05, 0, 0}, kZero, {0, 0, -omega}, kZero, {0, 0.1, 0},
                                 kZero,        1.0};
    expectTheRoot(balls, search(balls, 10.0), std::asin(0.1125 / 0.21) / omega);
}

TEST(FirstContactSearch, AShallowDipBeforeThePairRecedesIsNotSteppedOver) {
    // The same spinning ball with the particles receding at 1e-3: only the first swing reaches
    // (by 6e-5 of the reach, for about 2e-3 of the time), every later one falls short.
    const double omega = 40.0;
    const EccentricSpheres balls{
        {1.1 - 1e-4, 0, 0}, {1e-3, 0, 0}, {0, 0, -omega}, kZero, {0, 0.1, 0}, kZero, 1.0};
    double left = 0.0, right = 0.5 * M_PI / omega; // s(left) > 0 > s(right): bisect
    ASSERT_LT(balls.s(right), 0.0);
    while (right - left > 1e-16)
        (balls.s(0.5 * (left + right)) > 0.0 ? left : right) = 0.5 * (left + right);
    expectTheRoot(balls, search(balls, 10.0), left);
}

/// The first root of s in (a, b] (s(a) = sa > 0, s(b) = sb), by subdivision certified by the
/// semiconvexity of s: s'' = (|c'|^2 - (n . c')^2) / |c| + n . c'' >= -|c''| >= -K,
/// K = sum_k |omega_k|^2 e_k (c the centres' vector), so over [a, b] s >= min(sa, sb) -
/// K (b - a)^2 / 8. kNoContact where it proves there is none; none where 60 halvings cannot
/// decide (a graze within rounding).
std::optional<double> firstRoot(const EccentricSpheres& balls, double a, double sa, double b,
                                double sb, int depth = 0) {
    const double curvature = balls.omegaI.squaredNorm() * balls.offsetI.norm() +
                             balls.omegaJ.squaredNorm() * balls.offsetJ.norm();
    if (sb > 0.0 && std::min(sa, sb) > 0.125 * curvature * (b - a) * (b - a)) return kNoContact;
    const double m = 0.5 * (a + b);
    if (!(m > a && m < b)) return sb <= 0.0 ? std::optional(a) : std::nullopt;
    if (depth == 60) return std::nullopt;
    const double sm = balls.s(m);
    const std::optional<double> left = firstRoot(balls, a, sa, m, sm, depth + 1);
    if (!left || *left != kNoContact) return left;
    return firstRoot(balls, m, sm, b, sb, depth + 1);
}

/// The first root of s on [0, end] from a grid of step h, each step certified as above.
std::optional<double> certifiedFirstRoot(const EccentricSpheres& balls, double end, double h) {
    double sLeft = balls.s(0.0);
    for (double left = 0.0; left < end; left += h) {
        const double sRight = balls.s(left + h);
        const std::optional<double> root = firstRoot(balls, left, sLeft, left + h, sRight);
        if (!root || *root != kNoContact) return root;
        sLeft = sRight;
    }
    return kNoContact;
}

TEST(FirstContactSearch, RandomSpinningPairsAgreeWithACertifiedBruteForce) {
    // 1000 pairs over decades: gaps 1e-6 to 0.5, approach 1e-3 to 2 (and up to half that
    // across), spins 0.1 to 1000, offsets 1e-3 to 0.3 (the balls apart at the start).
    Random random(20261127);
    const auto logUniform = [&](double low, double high) {
        return low * std::pow(high / low, random.uniform());
    };
    const auto unit = [&] { return Vector3d(random.rotation() * Vector3d::UnitX()); };
    const double end = 1.0;
    int decided = 0, contacts = 0, rechecks = 0;
    for (int k = 0; k < 1000; ++k) {
        const Vector3d axis = unit();
        const double offsetI = logUniform(1e-3, 0.3), offsetJ = logUniform(1e-3, 0.3);
        const double speed = logUniform(1e-3, 2.0);
        const EccentricSpheres balls{(1.0 + offsetI + offsetJ + logUniform(1e-6, 0.5)) * axis,
                                     -speed * axis + 0.5 * speed * unit(),
                                     logUniform(0.1, 1000.0) * unit(),
                                     logUniform(0.1, 1000.0) * unit(),
                                     offsetI * unit(),
                                     offsetJ * unit(),
                                     1.0};
        if (balls.s(0.0) <= 0.0) continue;
        const std::optional<double> root = certifiedFirstRoot(balls, end, 1e-3);
        const Found found = search(balls, end);
        if (!root) continue;
        ++decided;
        if (found.time == kNoContact) {
            EXPECT_EQ(*root, kNoContact) << k << ": missed the root at " << *root;
        } else if (found.contact) {
            SCOPED_TRACE(k);
            expectTheRoot(balls, found, *root);
            ++contacts;
        } else { // a safe recheck time (the step limit): before any root
            EXPECT_LE(found.time, *root) << k;
            ++rechecks;
        }
    }
    std::printf("%d pairs decided by the grid: %d contacts, %d rechecks\n", decided, contacts,
                rechecks);
    EXPECT_GT(decided, 900); // the grid decides most pairs
    EXPECT_GT(contacts, 300);
}

} // namespace
} // namespace sbpack

// The hyperuniformity chain against analytic truths (docs/hyperuniformity.md): Parseval's sum
// rule of the discrete spreadability, the Debye medium's normalisation and t^{-3/2} tail, the
// superball form factor against the sphere's closed form, the cube bound and its own quadrature,
// the exact spectral density of spheres by two independent paths, alpha of a perturbed lattice
// (2 in the limit) and of random sequential addition (0), and the small-Q fit on exact data.

#include "hyperuniformity/debye_medium.hpp"
#include "hyperuniformity/discrete_spectrum.hpp"
#include "hyperuniformity/hyperuniformity.hpp"
#include "hyperuniformity/small_q_fit.hpp"
#include "hyperuniformity/spreadability_curve.hpp"
#include "hyperuniformity/spreadability_exponent.hpp"
#include "numerics/tanh_sinh.hpp"
#include "spectral/exact_spectral_density.hpp"
#include "spectral/spectral_density.hpp"
#include "spectral/superball_form_factor.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "voxels/voxelization.hpp"

#include "test_packings.hpp"
#include "test_spectra.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>

namespace sbpack {
namespace {

const Progress quiet;
constexpr double kPi = std::numbers::pi;

TEST(Spreadability, DiscreteSumRuleIsParsevalsIdentity) {
    // Without the cube form factor the grid's discrete transform sums to
    // phi_voxel (1 - phi_voxel) V over k != 0: E(0) = 1 - phi_voxel exactly.
    const Packing packing = testing::latticePacking(1.5, 3, 1.35, 0.05, 3);
    const Voxelization voxels = Voxelizer({40}).compute(packing, quiet);
    const VoxelFourierTransform transform(voxels, {FftPlanning::Estimate, {}}, quiet);
    const double w = packing.shape().meanWidth();
    VoxelSpectrumOptions plain;
    plain.cubeFormFactor = false;
    const DiscreteSpectrum s = voxelSpectrum(transform, voxels, w, plain, quiet);
    const SpreadabilityCurve curve(std::span(&s, 1));
    EXPECT_NEAR(curve.excess(0.0), 1.0 - voxels.phiVoxel(), 1e-12);
    EXPECT_EQ(curve.truncationBound(0.0), 0.0);
    // With the cube form factor weight moves beyond the grid; E(0) plus the reported missing
    // weight restores the sum rule, and the bound covers it at t = 0.
    const DiscreteSpectrum cube = voxelSpectrum(transform, voxels, w, {}, quiet);
    const SpreadabilityCurve cubes(std::span(&cube, 1));
    EXPECT_LT(cubes.excess(0.0), 1.0 - voxels.phiVoxel());
    EXPECT_NEAR(cubes.excess(0.0) + cubes.truncationBound(0.0), 1.0 - voxels.phiVoxel(), 1e-12);
    // nu = -t <(Q w)^2> against a centred difference of ln E.
    const double t = 0.05, h = 1e-4;
    const double nu = (std::log(curve.excess(t * (1 + h))) - std::log(curve.excess(t * (1 - h)))) /
                      (std::log1p(h) - std::log1p(-h));
    EXPECT_NEAR(curve.at(t).exponent, nu, 1e-6);
}

TEST(Debye, ClosedFormMatchesQuadratureAndIsNormalised) {
    const double phi = 0.35, a = 1.0;
    // Inverse transform at r = 0: int d^3k / (2 pi)^3 chi(k) = phi (1 - phi).
    const double variance = tanhSinh(
        [&](double u) { // k = u / (1 - u)
            const double k = u / (1 - u);
            return k * k * debyeSpectralDensity(k, phi, a) / (2 * kPi * kPi) / ((1 - u) * (1 - u));
        },
        0.0, 1.0, 1e-14);
    EXPECT_NEAR(variance, phi * (1 - phi), 1e-12);
    EXPECT_NEAR(debyeExcessSpreadability(0.0, phi), 1 - phi, 1e-15);
    for (const double s : {1e-3, 0.1, 1.0, 10.0, 49.0, 51.0, 300.0, 1e4}) {
        const double quadrature = tanhSinh(
            [&](double u) {
                const double k = u / (1 - u);
                return k * k * debyeSpectralDensity(k, phi, a) * std::exp(-k * k * s) /
                       (2 * kPi * kPi * phi) / ((1 - u) * (1 - u));
            },
            0.0, 1.0, 1e-15);
        EXPECT_NEAR(debyeExcessSpreadability(s, phi) / quadrature, 1.0, 1e-9) << s;
    }
    // The t^{-3/2} tail: alpha = 0 through the window exponent, once past the transient.
    const auto logE = [&](double s) { return std::log(debyeExcessSpreadability(s, phi)); };
    EXPECT_NEAR(windowExponent(logE, {1e2, 1e4}), 0.0, 0.02);
    EXPECT_NEAR(debyeExcessSpreadability(1e6, phi) * std::pow(1e6, 1.5), (1 - phi) / std::sqrt(kPi),
                1e-5);
}

TEST(Debye, NoAlphaWindowInABoxOfTwentyA) {
    // A box of 20 a: t_c / 4 = (20 / 2 pi)^2 / 4 = 2.5 a^2 / D_diff, before the tail (the weight
    // Q^2 chi_V peaks at Q a = 1, whose transient lasts to t = 10).
    const double phi = 0.3, a = 1.0, box = 20.0;
    const DiscreteSpectrum s = testing::debyeBoxSpectrum(phi, a, box, 60);
    const SpreadabilityCurve curve(std::span(&s, 1));
    EXPECT_NEAR(curve.cutoffTime(), std::pow(box / (2 * kPi), 2), 1e-12);
    EXPECT_THROW(findExponentWindow(curve, 1.0), std::domain_error);
    // Where the omitted |n| > 60 have decayed, the lattice sum is the continuum's, less the
    // Q = 0 term chi_V(0) / (phi V) (Poisson summation: the images of the autocovariance at
    // distance 20 a weigh e^{-20}).
    const double zero = debyeSpectralDensity(0.0, phi, a) / (phi * std::pow(box, 3));
    for (const double t : {0.05, 0.5, 2.0})
        EXPECT_NEAR((curve.excess(t) + zero) / debyeExcessSpreadability(t, phi), 1.0, 1e-5) << t;
}

TEST(FormFactor, SphereClosedFormAndSeriesAgainstQuadrature) {
    std::mt19937_64 random(5);
    std::normal_distribution<double> normal;
    for (const double p : {1.0, 0.75, 1.5, 3.0}) {
        const SuperballFormFactor m(Superball(p, 0.5));
        const double w = Superball(p, 0.5).meanWidth();
        for (int i = 0; i < 12; ++i) {
            const Eigen::Vector3d dir =
                Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
            const double kw = 10.0 * (i + 0.5) / 12.0;
            const Eigen::Vector3d k = dir * kw / w;
            if (p == 1.0) {
                EXPECT_NEAR(m(k) / m.volume(), sphereFormFactor(k.norm(), 0.5) / m.volume(), 1e-10)
                    << kw;
            }
            if (k.norm() * Superball(p, 0.5).circumradius() <= SuperballFormFactor::kSeriesLimit) {
                EXPECT_NEAR(m.series(k) / m.volume(), m.quadrature(k) / m.volume(), 1e-10)
                    << "p " << p << " k w " << kw;
            }
            // The 48-fold symmetry: signs and permutations of the components.
            const Eigen::Vector3d swapped(-k.z(), k.x(), -k.y());
            EXPECT_NEAR(m(swapped), m(k), 1e-12 * m.volume());
        }
        EXPECT_DOUBLE_EQ(m(Eigen::Vector3d::Zero()), m.volume());
    }
}

TEST(FormFactor, NearCubeWithinItsVolumeDefectOfTheCube) {
    // |m_superball - m_cube| <= v_cube - v_superball: the two indicators differ only there.
    for (const double p : {20.0, 200.0}) {
        const Superball shape(p, 0.5);
        const SuperballFormFactor m(shape);
        const double defect = 1.0 - shape.volume();
        for (const Eigen::Vector3d& k :
             {Eigen::Vector3d(3.0, 0.0, 0.0), Eigen::Vector3d(2.0, 4.0, 1.0),
              Eigen::Vector3d(7.0, 6.0, 5.0), Eigen::Vector3d(12.0, 1.0, 9.0)}) {
            const double cube = cubeFormFactor(k, 1.0);
            EXPECT_LE(std::abs(m(k) - cube), defect + 1e-10) << p << " " << k.transpose();
        }
    }
}

TEST(ExactSpectralDensity, SuperballPathOfSpheresEqualsTheSpherePath) {
    const Packing spheres = testing::latticePacking(1.0, 4, 1.2, 0.1, 11);
    const std::int64_t maxN2 = 30;
    const WaveVectorSpectrum a = sphereWaveVectors(spheres, maxN2, quiet);
    const WaveVectorSpectrum b = formFactorWaveVectors(spheres, maxN2, quiet);
    ASSERT_EQ(a.size(), b.size());
    double peak = 0.0;
    for (const double c : a.chi)
        peak = std::max(peak, c);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.n[i], b.n[i]);
        EXPECT_NEAR(a.chi[i], b.chi[i], 1e-10 * peak);
    }
}

/// `packing` with five sizes, semi-axes 0.5 down to 0.38 (docs/mixtures.md).
Packing polydisperse(Packing packing) {
    for (std::size_t i = 0; i < packing.size(); ++i)
        packing.semiAxes.push_back(0.5 - 0.03 * static_cast<double>(i % 5));
    return packing;
}

// docs/mixtures.md: a mixture's chi_V sums each particle's own form factor. Against the direct
// sum of the sphere's closed form m(Q; R_j) (the series path computes it from s_j^3 m(s_j Q R)).
TEST(ExactSpectralDensity, EachParticleOfAMixtureScattersWithItsOwnFormFactor) {
    const Packing spheres = polydisperse(testing::latticePacking(1.0, 3, 1.2, 0.1, 19));
    ExactSpectralDensityParameters parameters;
    parameters.maxQw = 6.0;
    const ExactSpectralDensityResult exact =
        ExactSpectralDensity(parameters).compute(spheres, quiet);
    ASSERT_GT(exact.modes.size(), 50u);
    EXPECT_DOUBLE_EQ(exact.phi, spheres.packingFraction());
    const double l = spheres.boxLength, volume = l * l * l;
    for (std::size_t i = 0; i < exact.modes.size(); i += 7) {
        const auto& n = exact.modes.n[i];
        const Vector3d q = 2.0 * kPi / l * Vector3d(n[0], n[1], n[2]);
        std::complex<double> sum = 0.0;
        for (std::size_t j = 0; j < spheres.size(); ++j)
            sum += sphereFormFactor(q.norm(), spheres.semiAxes[j]) *
                   std::exp(std::complex<double>(0.0, -q.dot(spheres.positions[j])));
        EXPECT_NEAR(exact.modes.chi[i], std::norm(sum) / volume, 1e-12 * std::norm(sum) / volume)
            << "n = " << n[0] << " " << n[1] << " " << n[2];
    }
    EXPECT_THROW(sphereWaveVectors(spheres, 10, quiet), std::invalid_argument);
}

TEST(ExactSpectralDensity, ShellsEndWhereNoWaveVectorLies) {
    // Shell 12 ends at |n|^2 = 12 * 13 = 156 = 4 * 39, not a sum of three squares: the largest
    // listed |n|^2 is 155, and the shell average must still be made.
    const Packing spheres = testing::latticePacking(1.0, 3, 1.2, 0.1, 13);
    const WaveVectorSpectrum a = sphereWaveVectors(spheres, maxSquaredIndex(12), quiet);
    EXPECT_EQ(a.n2(a.size() - 1), 155);
    EXPECT_EQ(shellAverage(a, 12).size(), 12u);
    EXPECT_THROW(shellAverage(a, 13), std::invalid_argument);
}

/// chi at the smallest wave vectors (|n| <= 2), voxels against exact: the worst error falls by
/// more than half from M = 24 to 48.
void expectVoxelsConverge(const Packing& packing) {
    const double w = packing.shape().meanWidth();
    ExactSpectralDensityParameters parameters;
    parameters.maxQw = 2.0 * kPi * w * 2.0 / packing.boxLength; // |n| <= 2
    const ExactSpectralDensityResult exact =
        ExactSpectralDensity(parameters).compute(packing, quiet);
    double error[2];
    for (const int m : {24, 48}) {
        const Voxelization voxels = Voxelizer({m}).compute(packing, quiet);
        const VoxelFourierTransform transform(voxels, {FftPlanning::Estimate, {}}, quiet);
        const DiscreteSpectrum s = voxelSpectrum(transform, voxels, w, {}, quiet);
        double worst = 0.0;
        for (std::size_t i = 0; i < exact.modes.size(); ++i)
            worst = std::max(worst, std::abs(s.modes.chi[i] - exact.modes.chi[i]));
        error[m / 48] = worst;
    }
    EXPECT_LT(error[1], 0.5 * error[0]);
}

TEST(ExactSpectralDensity, VoxelsConvergeToIt) {
    // chi at the smallest wave vectors, voxels against exact, for p = 1.5, identical and of five
    // sizes (docs/mixtures.md): the error falls as the grid is refined (M = 24 -> 48).
    for (const bool mixture : {false, true}) {
        const Packing packing = testing::latticePacking(1.5, 3, 1.35, 0.05, 21);
        expectVoxelsConverge(mixture ? polydisperse(packing) : packing);
    }
}

/// alpha of an exact spectrum through the whole chain (the window found from the chi peak, or
/// `window` where given).
HyperuniformityResult exactChain(const Packing& packing, double maxQw,
                                 std::optional<ExponentWindow> window = std::nullopt) {
    ExactSpectralDensityParameters parameters;
    parameters.maxQw = maxQw;
    const ExactSpectralDensityResult exact =
        ExactSpectralDensity(parameters).compute(packing, quiet);
    const DiscreteSpectrum s = exactSpectrum(exact);
    HyperuniformityParameters hp;
    hp.replicas = 40;
    hp.window = window;
    return Hyperuniformity(hp).compute(std::span(&s, 1), principalPeak(s));
}

TEST(Hyperuniformity, PerturbedLatticeHasAlphaNearTwo) {
    // 16^3 spheres of diameter 0.3 on a unit lattice, each displaced uniformly within its cell:
    // S(Q) ~ Q^2 at small Q (alpha = 2 in the limit; the form factor bends it at reachable times).
    Packing packing = testing::latticePacking(1.0, 16, 1.0, 0.5, 31, true);
    packing.semiAxis = 0.15;
    const HyperuniformityResult r = exactChain(packing, 3.0);
    std::printf("perturbed lattice: alpha %.3f +- %.3f in t = [%.3g, %.3g]\n", r.alpha.alpha,
                r.alpha.standardError, r.window.tMin, r.window.tMax);
    // alpha (extrapolated in 1/t) covers the truth within two standard errors; the window's
    // mean lies below it, by the finite times (bench/RESULTS.md, "alpha on fixtures with known
    // exponents": 20 of 20 such lattices covered).
    EXPECT_GT(r.alpha.standardError, 0.0);
    EXPECT_NEAR(r.alpha.alpha, 2.0, 2.0 * r.alpha.standardError);
    EXPECT_LT(r.alpha.windowMean, r.alpha.alpha);
    EXPECT_LE(r.alpha.endLow, r.alpha.alpha);
    EXPECT_GE(r.alpha.endHigh, r.alpha.alpha);
    EXPECT_LT(r.window.tMin, r.window.tMax);
    // The points kept with the fit are the ones it fitted: in the window, and fitting them again
    // gives the same a0 and a1.
    ASSERT_EQ(r.fitted.qw.size(), static_cast<std::size_t>(r.fit.points));
    for (double qw : r.fitted.qw) {
        EXPECT_GT(qw, 0.0);
        EXPECT_LE(qw, r.parameters.fitQmaxW);
    }
    const PowerLawFit again = fitFixedExponent(r.fitted, r.alpha.alpha);
    EXPECT_EQ(again.a0, r.fit.a0);
    EXPECT_EQ(again.a1, r.fit.a1);
}

TEST(Hyperuniformity, AWindowPastTheCutoffTimeIsRefused) {
    // The perturbed lattice's box of 16: t_c = (L / (2 pi w))^2 with w = 0.3. A window ending
    // there is taken; one ending past it is refused, not fitted to the smallest wave vectors'
    // decay (issue 42: alpha_window=(1, 5.8) on N = 200, t_c = 0.68, returned 5.02).
    Packing packing = testing::latticePacking(1.0, 16, 1.0, 0.5, 31, true);
    packing.semiAxis = 0.15;
    const double cutoff = std::pow(16.0 / (2 * kPi * 0.3), 2);
    const HyperuniformityResult r = exactChain(packing, 3.0, ExponentWindow{1.0, 0.999 * cutoff});
    EXPECT_NEAR(r.cutoffTime, cutoff, 1e-9 * cutoff);
    try {
        exactChain(packing, 3.0, ExponentWindow{1.0, 1.001 * cutoff});
        ADD_FAILURE() << "a window past the cutoff time was fitted";
    } catch (const std::domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("past the box's cutoff time"), std::string::npos);
    }
}

TEST(Hyperuniformity, RandomSequentialAdditionIsNotHyperuniform) {
    // Random sequential addition of spheres to phi = 0.3: S(0) > 0, alpha = 0.
    const Packing packing = testing::randomSequentialAddition(1500, 0.3, 41);
    const HyperuniformityResult r = exactChain(packing, 12.0);
    std::printf("RSA: alpha %.3f +- %.3f in t = [%.3g, %.3g], a0 %.3g +- %.2g, H %.3g\n",
                r.alpha.alpha, r.alpha.standardError, r.window.tMin, r.window.tMax, r.fit.a0,
                r.fit.a0Error, r.h);
    EXPECT_NEAR(r.alpha.alpha, 0.0, 0.3);
    EXPECT_NEAR(r.alpha.alpha, 0.0, 2.0 * r.alpha.standardError);
}

TEST(Hyperuniformity, ExtrapolationRemovesTheDebyeMediumsFiniteTimeBias) {
    // The Debye medium's chi_V on the wave vectors of a box of 200 a, no noise: its local alpha
    // tends to 0 as c / t. In t = 10 ... t_c / 4 the window's mean is -0.13, the line in 1/t at
    // 1/t = 0 within 0.02 of 0.
    // Q a <= 1.26 at |n_i| <= 40: weight exp(-(Q a)^2 t) below e^{-15} at t = 10.
    const DiscreteSpectrum s = testing::debyeBoxSpectrum(0.3, 1.0, 200.0, 40);
    const SpreadabilityCurve curve(std::span(&s, 1));
    const ExponentWindow window{10.0, curve.cutoffTime() / kCutoffFraction};
    const ExponentEstimate e = estimateExponent(curve, std::span(&s, 1), window, 0);
    EXPECT_LT(e.windowMean, -0.1);
    EXPECT_NEAR(e.alpha, 0.0, 0.02);
    // The line runs through the local alpha it was fitted to (within 0.06: the local alpha
    // bends in 1/t at the window's start and crosses 0 near its end, the box's finite sum).
    for (const double t : {window.tMin, std::sqrt(window.tMin * window.tMax), window.tMax})
        EXPECT_NEAR(e.alpha + e.slope / t, -3.0 - 2.0 * curve.at(t).exponent, 0.06) << t;
    // The ensemble path's estimate from E sampled on a time grid agrees with the exact one.
    std::vector<double> t, excess;
    for (double time = 1.0; time <= 300.0; time *= std::pow(10.0, 1.0 / 40))
        t.push_back(time), excess.push_back(curve.excess(time));
    EXPECT_NEAR(sampledExponent(t, excess, window).alpha, e.alpha, 0.01);
}

/// A spectrum of every wave vector up to Q w = 10 in a box of box wave number 2 pi w / L = 0.4
/// (w = 1), chi_V(Q) / w^3 = 0.02 exp(-(Q w - 7.6)^2 / (2 0.25^2)) + 0.002 at the peak, each wave
/// vector's value times `noise()` (1: none).
template <class Noise> DiscreteSpectrum peakedSpectrum(Noise noise) {
    DiscreteSpectrum s;
    s.meanWidth = 1.0;
    s.boxLength = 2.0 * kPi / 0.4;
    s.modes.boxLength = s.boxLength;
    s.modes.maxN2 = 625;
    s.modes.n = halfSpaceWaveVectors(625);
    for (std::size_t i = 0; i < s.modes.n.size(); ++i) {
        const double qw = 0.4 * std::sqrt(static_cast<double>(s.modes.n2(i)));
        const double x = (qw - 7.6) / 0.25;
        s.modes.chi.push_back((0.02 * std::exp(-0.5 * x * x) + 0.002) * noise());
    }
    return s;
}

// The peak H is divided by: on a smooth peak it is the peak; under the scatter of single wave
// vectors' chi_V (exponential, as a packing's) the parabola is not biased upward as the largest
// fine bin is (docs/hyperuniformity.md, "Fit and H").
TEST(PrincipalPeak, FindsASmoothPeakAndIsNotBiasedByTheScatter) {
    const SpectralPeak smooth = principalPeak(peakedSpectrum([] { return 1.0; }));
    EXPECT_NEAR(smooth.qw, 7.6, 0.02);
    EXPECT_NEAR(smooth.chi, 0.022, 0.022 * 0.02);
    std::mt19937_64 random(5);
    std::exponential_distribution<double> exponential(1.0);
    double fitted = 0.0, largest = 0.0;
    const int trials = 20;
    for (int t = 0; t < trials; ++t) {
        const DiscreteSpectrum s = peakedSpectrum([&] { return exponential(random); });
        fitted += principalPeak(s).chi / trials;
        largest += largestBin(binnedChi(modePoints(s), kPeakBinQw)).chi / trials;
    }
    std::printf("peak 0.022: smooth %.5f, scattered: fitted %.5f, largest fine bin %.5f\n",
                smooth.chi, fitted, largest);
    EXPECT_NEAR(fitted, 0.022, 0.022 * 0.02);
    EXPECT_GT(largest, 0.022 * 1.025); // the maximum of noisy bins
}

TEST(SmallQFit, RecoversAnExactPowerLaw) {
    SmallQPoints points;
    for (int i = 1; i <= 40; ++i) {
        points.qw.push_back(0.05 * i);
        points.chi.push_back(2e-4 + 1e-3 * std::pow(0.05 * i, 0.55));
    }
    const PowerLawFit fixed = fitFixedExponent(points, 0.55);
    EXPECT_NEAR(fixed.a0, 2e-4, 1e-15);
    EXPECT_NEAR(fixed.a1, 1e-3, 1e-15);
    const FreeFit free = fitFreeExponent(points);
    EXPECT_NEAR(free.best.alpha, 0.55, 1e-9);
    EXPECT_FALSE(free.degenerate);
    const IndexSpread spread = indexSpread(points, 1.4, 0.55, 0.02);
    EXPECT_NEAR(spread.hMin, 0.01, 1e-10);
    EXPECT_NEAR(spread.hMax, 0.01, 1e-10);
    EXPECT_THROW(fitFixedExponent(points.upTo(0.1), 0.5), std::domain_error);
}

TEST(SmallQFit, TheSpreadLeavesOutWindowsThroughOneShell) {
    // A box whose first shell lies at Q w = 0.79 and second at 1.12 (p = 0.55, N = 1000): the
    // windows ending at 0.8 and 0.9 times 1.4 hold the first shell alone, and the spread is that
    // of the windows through two shells or more (before, the narrowest refused the whole
    // analysis: "hyperuniformity skipped").
    SmallQPoints points;
    for (const double q : {0.7926, 1.1209, 1.3728, 1.5852, 1.7723})
        for (int k = 0; k < 3; ++k) {
            points.qw.push_back(q);
            points.chi.push_back(2e-4 + 1e-3 * std::pow(q, 0.55));
        }
    const IndexSpread spread = indexSpread(points, 1.4, 0.55, 0.02);
    EXPECT_NEAR(spread.hMin, 0.01, 1e-10);
    EXPECT_NEAR(spread.hMax, 0.01, 1e-10);
    EXPECT_THROW(fitFixedExponent(points.upTo(0.8 * 1.4), 0.55), std::domain_error);
}

TEST(SmallQFit, OneDistinctMagnitudeIsRefused) {
    // Three members' wave vectors at one shell (their boxes 3e-4 apart): a0 + a1 Q^alpha through
    // one |Q| is not determined, however many wave vectors (issue 42: N = 300 printed
    // H = 0 +- 1.5e6); a second shell determines it exactly.
    SmallQPoints points;
    const auto add = [&](double q) {
        for (const double member : {1.0, 1.0003, 0.9997})
            for (int k = 0; k < 3; ++k) {
                points.qw.push_back(q * member);
                points.chi.push_back(2e-4 + 1e-3 * std::pow(q * member, 0.55));
            }
    };
    add(1.0);
    try {
        fitFixedExponent(points, 0.55);
        ADD_FAILURE() << "one shell was fitted";
    } catch (const std::domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("1 distinct |Q|"), std::string::npos) << e.what();
    }
    add(std::sqrt(2.0));
    const PowerLawFit fit = fitFixedExponent(points, 0.55);
    EXPECT_NEAR(fit.a0, 2e-4, 1e-14);
    EXPECT_NEAR(fit.a1, 1e-3, 1e-14);
}

} // namespace
} // namespace sbpack

// bench_alpha_coverage: does alpha's stated uncertainty cover the truth? (issue 42, item 1;
// bench/RESULTS.md, "alpha on fixtures with known exponents"). For COUNT independent fixtures of
// each family with a known exponent, the exact chi_V (no voxels) goes through the hyper chain
// (the window from the chi_V peak, the Poisson bootstrap over the wave vectors), and each
// estimator's alpha +- its bootstrap error is compared with the truth:
//   perturbed lattice: 16^3 spheres of diameter 0.3 on a unit simple-cubic lattice, each
//     displaced uniformly within its cell (S(Q) ~ Q^2: alpha = 2);
//   RSA: random sequential addition of 1500 unit spheres to phi = 0.3 (S(0) > 0: alpha = 0);
// and, without noise, the Debye random medium's chi_V summed over the wave vectors of a box of
// 200 a (alpha = 0), in the window from t = 10 a^2 / D_diff to the box's t_c / 4.
//
//   bench_alpha_coverage [COUNT] [REPLICAS] [THREADS]      (default 20, 100 and 2)

#include "hyperuniformity/hyperuniformity.hpp"
#include "parallel/parallel.hpp"
#include "spectral/exact_spectral_density.hpp"
#include "test_packings.hpp"
#include "test_spectra.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

using namespace sbpack;

namespace {

struct Family {
    const char* name;
    double truth;
    double maxQw; ///< exact chi_V up to this Q w (the fit's reach and beyond the peak)
    std::function<Packing(int seed)> make;
};

Packing perturbedLattice(int seed) {
    Packing packing = testing::latticePacking(1.0, 16, 1.0, 0.5, 1000 + seed, true);
    packing.semiAxis = 0.15;
    return packing;
}

/// The hyper chain on the exact spectrum of one fixture.
HyperuniformityResult exactChain(const Packing& packing, double maxQw, int replicas) {
    const Progress quiet;
    ExactSpectralDensityParameters parameters;
    parameters.maxQw = maxQw;
    const DiscreteSpectrum s =
        exactSpectrum(ExactSpectralDensity(parameters).compute(packing, quiet));
    HyperuniformityParameters hp;
    hp.replicas = replicas;
    return Hyperuniformity(hp).compute(std::span(&s, 1), principalPeak(s));
}

/// Prints one row per fixture and the coverage of each estimator's 2-sigma interval.
void runFamily(const Family& family, int count, int replicas) {
    std::printf("\n%s (alpha = %g)\n\n| seed | window t | window alpha | +- | extrapolated alpha "
                "| +- |\n|---|---|---|---|---|---|\n",
                family.name, family.truth);
    int windowCovered = 0, extrapolatedCovered = 0;
    double windowMean = 0.0, extrapolatedMean = 0.0;
    for (int seed = 1; seed <= count; ++seed) {
        const HyperuniformityResult r = exactChain(family.make(seed), family.maxQw, replicas);
        const ExponentEstimate& a = r.alpha;
        windowCovered += std::abs(a.windowMean - family.truth) <= 2.0 * a.windowMeanError;
        extrapolatedCovered += std::abs(a.alpha - family.truth) <= 2.0 * a.standardError;
        windowMean += a.windowMean / count;
        extrapolatedMean += a.alpha / count;
        std::printf("| %d | %.3g ... %.3g | %.3f | %.3f | %.3f | %.3f |\n", seed, r.window.tMin,
                    r.window.tMax, a.windowMean, a.windowMeanError, a.alpha, a.standardError);
        std::fflush(stdout);
    }
    std::printf("\nmean over %d: window %.3f, extrapolated %.3f; truth within 2 sigma: window %d "
                "of %d, extrapolated %d of %d\n",
                count, windowMean, extrapolatedMean, windowCovered, count, extrapolatedCovered,
                count);
}

/// The Debye medium (phi = 0.3, a = 1 = w) on the wave vectors |n| <= 40 of a box of 200 a.
void debyeRow() {
    const DiscreteSpectrum s = testing::debyeBoxSpectrum(0.3, 1.0, 200.0, 40);
    const SpreadabilityCurve curve(std::span(&s, 1));
    const ExponentWindow window{10.0, curve.cutoffTime() / kCutoffFraction};
    const ExponentEstimate e = estimateExponent(curve, std::span(&s, 1), window, 0);
    std::printf("\nDebye medium, box 200 a (alpha = 0), t = %.3g ... %.3g: window mean %.3f, "
                "extrapolated %.3f\n",
                window.tMin, window.tMax, e.windowMean, e.alpha);
}

} // namespace

int main(int argc, char** argv) {
    const int count = argc > 1 ? std::stoi(argv[1]) : 20;
    const int replicas = argc > 2 ? std::stoi(argv[2]) : 100;
    const ThreadBudget budget(argc > 3 ? std::stoi(argv[3]) : 2);
    const Family families[] = {
        {"perturbed simple-cubic lattice, 16^3", 2.0, 3.0, perturbedLattice},
        {"RSA spheres, phi = 0.3, N = 1500", 0.0, 12.0,
         [](int seed) { return testing::randomSequentialAddition(1500, 0.3, 2000 + seed); }}};
    for (const Family& family : families)
        runFamily(family, count, replicas);
    debyeRow();
    return 0;
}

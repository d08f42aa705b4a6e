// bench_hyperuniformity: error against run time of the hyperuniformity chain (issue 24), results
// in bench/RESULTS.md. For one packing file and each grid M:
//  - the voxel chi_V (cube form factor, as sbanalyze) at the wave vectors with Q w <= 3 against
//    the exact chi_V there: the root-mean-square and largest error over chi_peak;
//  - alpha (spreadability) and H from the voxel data alone and with the exact small-Q values;
//  - wall-clock seconds of the voxelization + FFT, of the exact path, of the spreadability + fits
//    alone and with the bootstrap of alpha.
//
//   bench_hyperuniformity FILE.h5 [M1,M2,...] [THREADS]     (default 100,200,300,500 and 2)

#include "hyperuniformity/discrete_spectrum.hpp"
#include "hyperuniformity/hyperuniformity.hpp"
#include "io/packing_io.hpp"
#include "parallel/parallel.hpp"
#include "progress/progress.hpp"
#include "spectral/exact_spectral_density.hpp"
#include "spectral/spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "voxel_spectrum_run.hpp"
#include "voxels/voxelization.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace sbpack;

/// RMS and largest |voxel - exact| over the exact wave vectors, in units of `peak`.
std::pair<double, double> chiErrors(const DiscreteSpectrum& voxel,
                                    const ExactSpectralDensityResult& exact, double peak) {
    double sum = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < exact.modes.size(); ++i) {
        const double e = std::abs(voxel.modes.chi[i] - exact.modes.chi[i]) / peak;
        sum += e * e;
        worst = std::max(worst, e);
    }
    return {std::sqrt(sum / static_cast<double>(exact.modes.size())), worst};
}

/// alpha, a0 and H; `seconds` with the bootstrap, `plain` without (replicas = 0).
std::string summary(const DiscreteSpectrum& s, const SpectralPeak& peak, double& seconds,
                    double& plain) {
    HyperuniformityParameters noBootstrap;
    noBootstrap.replicas = 0;
    try {
        const Stopwatch plainClock;
        static_cast<void>(Hyperuniformity(noBootstrap).compute(std::span(&s, 1), peak));
        plain = plainClock.seconds();
    } catch (const std::exception&) {
        plain = 0.0;
    }
    const Stopwatch clock;
    try {
        const HyperuniformityResult h = Hyperuniformity({}).compute(std::span(&s, 1), peak);
        seconds = clock.seconds();
        char text[160];
        std::snprintf(text, sizeof text, "%.3f +- %.3f | %.2e +- %.1e | %.2e", h.alpha.alpha,
                      h.alpha.standardError, h.fit.a0, h.fit.a0Error, h.h);
        return text;
    } catch (const std::exception& e) {
        seconds = clock.seconds();
        return std::string("- (") + e.what() + ") | - | -";
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_hyperuniformity FILE.h5 [M1,M2,...] [THREADS]\n");
        return 1;
    }
    const Packing packing = readPacking(argv[1]);
    const std::vector<int> grids = bench::parseGrids(argc > 2 ? argv[2] : "100,200,300,500");
    const ThreadBudget budget(argc > 3 ? std::stoi(argv[3]) : 2);
    const Progress quiet;
    const double w = packing.shape().meanWidth();
    const ExactSpectralDensityResult exact = ExactSpectralDensity({}).compute(packing, quiet);
    std::printf("%s: N = %zu, %s, exact chi at %zu wave vectors (Q w <= 3) in %.3f s\n\n", argv[1],
                packing.size(), packing.shapeSpec.describe().c_str(), 2 * exact.modes.size(),
                exact.runtimeSeconds);
    std::printf(
        "| M | voxels + FFT s | chi error / peak, RMS | max | alpha, voxel | a0 / w^3, voxel "
        "| H, voxel | alpha, exact+voxel | a0 / w^3, exact+voxel | H, exact+voxel | "
        "spreadability + fits s | with the bootstrap (200) s |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const int m : grids) {
        const bench::VoxelSpectrumRun run = bench::voxelSpectrumRun(packing, m, quiet);
        const DiscreteSpectrum& voxel = run.spectrum;
        const double gridSeconds = run.seconds;
        const SpectralPeak peak = principalPeak(voxel);
        const auto [rms, worst] = chiErrors(voxel, exact, peak.chi * w * w * w);
        double voxelSeconds = 0.0, exactSeconds = 0.0, plain = 0.0;
        const std::string byVoxel = summary(voxel, peak, voxelSeconds, plain);
        const std::string byExact =
            summary(withExactSmallQ(voxel, exact), peak, exactSeconds, plain);
        std::printf("| %d | %.2f | %.2e | %.2e | %s | %s | %.3f | %.2f |\n", m, gridSeconds, rms,
                    worst, byVoxel.c_str(), byExact.c_str(), plain, exactSeconds);
    }
    return 0;
}

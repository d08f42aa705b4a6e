// bench_chi_peak: chi_V's principal peak, the denominator of H = a0 / chi_peak (paper Eq. HX),
// against the binning that takes it (issue 42, item 2; bench/RESULTS.md, "The peak of chi_V").
// For one packing and each grid M: the largest shell average (shells one box wave number
// 2 pi / L wide, sbanalyze's spectral_density) and the largest mean over the individual wave
// vectors in bins of Q w of several widths, each with its Q w and its count of wave vectors.
//
//   bench_chi_peak FILE.h5 [M1,M2,...] [THREADS]     (default 200,300 and 2)

#include "hyperuniformity/hyperuniformity.hpp"
#include "io/packing_io.hpp"
#include "parallel/parallel.hpp"
#include "voxel_spectrum_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

using namespace sbpack;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_chi_peak FILE.h5 [M1,M2,...] [THREADS]\n");
        return 1;
    }
    const Packing packing = readPacking(argv[1]);
    const ThreadBudget budget(argc > 3 ? std::stoi(argv[3]) : 2);
    const Progress quiet;
    const double w = packing.shape().meanWidth();
    const double shellQw = 2.0 * std::numbers::pi / packing.boxLength * w;
    std::printf("%s: N = %zu, %s, box wave number 2 pi w / L = %.4f\n\n", argv[1], packing.size(),
                packing.shapeSpec.describe().c_str(), shellQw);
    std::printf("| M | binning | Q_peak w | chi_peak / w^3 |\n|---|---|---|---|\n");
    for (const int m : bench::parseGrids(argc > 2 ? argv[2] : "200,300")) {
        const bench::VoxelSpectrumRun run = bench::voxelSpectrumRun(packing, m, quiet);
        const SpectralDensityResult& chi = run.chi;
        const auto shell = std::max_element(chi.shells.value.begin(), chi.shells.value.end());
        const auto i = static_cast<std::size_t>(shell - chi.shells.value.begin());
        std::printf("| %d | largest shell average (shells 2 pi / L wide) | %.4f | %.5f |\n", m,
                    chi.shells.q[i] * w, *shell / (w * w * w));
        const DiscreteSpectrum& s = run.spectrum;
        const SpectralPeak chosen = principalPeak(s);
        std::printf("| %d | principalPeak (sbanalyze's H) | %.4f | %.5f |\n", m, chosen.qw,
                    chosen.chi);
        for (const double width : {0.4, 0.2, 0.1, 0.05}) {
            const std::vector<ChiBin> bins = binnedChi(modePoints(s), width);
            const ChiBin& top = largestBin(bins);
            std::printf("| %d | largest bin of Q w %.3f (%d wave vectors) | %.4f | %.5f |\n", m,
                        width, top.modes, top.qw, top.chi);
            for (const double half : {0.4, 0.6, 0.8, 1.0}) {
                const SpectralPeak fit = fittedPeak(bins, half);
                std::printf(
                    "| %d | Gaussian through the bins of %.3f within +-%.1f | %.4f | %.5f |\n", m,
                    width, half, fit.qw, fit.chi);
            }
        }
    }
    return 0;
}

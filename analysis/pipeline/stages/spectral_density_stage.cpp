// chi: the spectral density chi_V(Q) of the kept spectral-grid voxelization.
#include "hyperuniformity/discrete_spectrum.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "spectral/spectral_density_fields.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "voxels/voxelization.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sbpack::stages {

StageMemory spectralDensityMemory(const Packing& packing, const RunSettings& settings) {
    const int m = settings.voxelization.voxels;
    double bytes = SpectralDensity::memoryEstimateBytes(m);
    if (packing.shape().isSphere()) {
        const int shell = SpectralDensity::maxShellFor(
            settings.structureFactor.maxQw, packing.boxLength, packing.shape().meanWidth(), m);
        bytes += collectiveDensityBytes(packing, std::max(shell, 1));
    }
    return {bytes, fmt::format("FFT grid {}^3", m), "--voxels"};
}

namespace {

void report(const Progress& progress, const SpectralDensityResult& chi) {
    std::string detail =
        fmt::format("{} shells, FFT plan {} s", chi.maxShell, describe(chi.planSeconds, 3));
    if (chi.exactSphere)
        detail += ", exact sphere path: max error / peak " +
                  describe(chi.exactSphere->maxErrorOverPeak, 3);
    progress.stageDone("spectral density", chi.runtimeSeconds, detail);
}

/// " (measuring predicted P s, budget B s)" when measured planning is limited
/// (--fft-planning-budget) and the wisdom had no plan.
std::string budgetNote(const FftSettings& fft, int voxels, FftPlanSource source) {
    if (source != FftPlanSource::OverBudget && source != FftPlanSource::MeasuredBudget) return "";
    return fmt::format(" (measuring predicted {} s, budget {} s)",
                       describe(predictedPlanningSeconds(voxels, fft.planning), 2),
                       describe(fft.planningBudget, 3));
}

/// The plan's line: "FFT plan  0.2 s  300^3, measure: wisdom" (whole grids and slabs alike).
void reportPlan(const Progress& progress, const FftSettings& fft, int voxels, double seconds,
                FftPlanSource source) {
    progress.stageDone("FFT plan", seconds,
                       fmt::format("{}^3, {}: {}{}", voxels, fftPlanningName(fft.planning),
                                   fftPlanSourceName(source), budgetNote(fft, voxels, source)));
}

/// chi of the kept whole voxelization; the voxel spectrum kept for hyper.
SpectralDensityResult wholeGrid(FileContext& context, const SpectralDensityParameters& parameters) {
    const Voxelization& voxels = context.kept<Voxelization>(Analysis::Voxels);
    const VoxelFourierTransform transform(voxels, parameters.fft, context.progress());
    reportPlan(context.progress(), parameters.fft, transform.voxels(), transform.planSeconds(),
               transform.planSource());
    SpectralDensityResult s =
        SpectralDensity(parameters)
            .compute(context.packing(), voxels, transform, context.progress());
    s.planSource = transform.planSource();
    if (context.settings().keepsVoxelSpectrum()) {
        DiscreteSpectrum spectrum =
            voxelSpectrum(transform, voxels, context.meanWidth(), {}, context.progress());
        const SpectralPeak peak = principalPeak(spectrum);
        context.keep(Analysis::SpectralDensity, KeptSpectrum{std::move(spectrum), peak});
    }
    return s;
}

} // namespace

bool runSpectralDensity(FileContext& context, schema::Record& record) {
    const SpectralDensityParameters parameters = context.settings().spectralDensity();
    DistributionFigures figures;
    SpectralDensityResult s;
    if (context.grids() != nullptr) {
        s = context.grids()->spectralDensity(context.packing(),
                                             context.kept<SlabVoxels>(Analysis::Voxels), parameters,
                                             context.progress(), figures);
        reportPlan(context.progress(), parameters.fft, s.voxels, s.planSeconds, s.planSource);
    }
#ifdef SBPACK_WITH_CUDA
    else if (context.gridsOnGpu())
        s = cudaSpectralDensity(context, parameters);
#endif
    else
        s = wholeGrid(context, parameters);
    report(context.progress(), s);
    const SpectralDensityFigures recorded{
        std::move(s), context.settings().fftSingle ? "single" : "double",
        context.grids() != nullptr ? std::optional(figures) : std::nullopt};
    spectral_density_fields::kTable.fill(record, recorded, context.scales());
    return true;
}

} // namespace sbpack::stages

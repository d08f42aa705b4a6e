#pragma once
// What the hyperuniformity benches share (bench_hyperuniformity, bench_chi_peak): their grid list
// and the voxel spectrum of one packing on one grid, computed as sbanalyze's chi and hyper stages
// compute it (estimate planning, no wisdom).

#include "hyperuniformity/discrete_spectrum.hpp"
#include "progress/progress.hpp"
#include "spectral/spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "voxels/voxelization.hpp"

#include <sstream>
#include <string>
#include <vector>

namespace sbpack::bench {

/// "100,200,300" as grids.
inline std::vector<int> parseGrids(const std::string& text) {
    std::vector<int> grids;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        grids.push_back(std::stoi(item));
    return grids;
}

/// The shell-averaged chi_V and the discrete spectrum of `packing` on an M^3 grid.
struct VoxelSpectrumRun {
    SpectralDensityResult chi;
    DiscreteSpectrum spectrum;
    double seconds = 0.0; ///< voxelization, FFT and both spectra
};

inline VoxelSpectrumRun voxelSpectrumRun(const Packing& packing, int m, const Progress& progress) {
    const Stopwatch clock;
    const Voxelization voxels = Voxelizer({m}).compute(packing, progress);
    const VoxelFourierTransform transform(voxels, {FftPlanning::Estimate, {}}, progress);
    SpectralDensityParameters parameters;
    parameters.fft = {FftPlanning::Estimate, {}};
    VoxelSpectrumRun run;
    run.chi = SpectralDensity(parameters).compute(packing, voxels, transform, progress);
    run.spectrum = voxelSpectrum(transform, voxels, packing.shape().meanWidth(), {}, progress);
    run.seconds = clock.seconds();
    return run;
}

} // namespace sbpack::bench

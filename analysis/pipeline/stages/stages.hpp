#pragma once
// The stages of the registry's analyses (pipeline/analysis_registry.cpp): each runs its compute
// object on one file, reports a progress line and fills its results group by the schema's names.

#include "hyperuniformity/hyperuniformity.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pipeline/distributed_grids.hpp"
#include "pores/distance_transform.hpp"
#include "shells/shell_average.hpp"
#include "spectral/spectral_density.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sbpack::stages {

/// What contacts keeps for order and voronoi: the contact network's pairs (i, j), i < j, and its
/// rattlers per particle (empty where the contacts are not resolved).
struct KeptContacts {
    std::vector<std::pair<int, int>> pairs;
    std::vector<bool> rattler;
};
bool runContacts(FileContext& context, schema::Record& record);

bool runOrder(FileContext& context, schema::Record& record);

/// jamming: the category reached (its group) and a group per category tested.
bool runJamming(FileContext& context, schema::Record& record);
/// An ensemble's count of members per category reached and, per category, per verdict.
void countJammingCategories(EnsembleResults& ensemble, std::span<const FileResults> files);

bool runStructureFactor(FileContext& context, schema::Record& record);
StageMemory structureFactorMemory(const Packing& packing, const RunSettings& settings);

bool runVoxels(FileContext& context, schema::Record& record);
StageMemory voxelsMemory(const Packing& packing, const RunSettings& settings);

bool runSpectralDensity(FileContext& context, schema::Record& record);
StageMemory spectralDensityMemory(const Packing& packing, const RunSettings& settings);

bool runPoreSizes(FileContext& context, schema::Record& record);
StageMemory poreSizesMemory(const Packing& packing, const RunSettings& settings);

bool runTransport(FileContext& context, schema::Record& record);

bool runVoronoi(FileContext& context, schema::Record& record);
StageMemory voronoiMemory(const Packing& packing, const RunSettings& settings);

/// What chi keeps for hyper: the voxel spectrum at every wave vector and the peak of chi_V.
struct KeptSpectrum {
    DiscreteSpectrum spectrum;
    SpectralPeak peak;
};
bool runHyperuniformity(FileContext& context, schema::Record& record);
/// The voxel spectrum with chi_V exact at Q w <= --chi-exact-qmax (none when it is 0), as hyper
/// and variance read it.
DiscreteSpectrum spectrumOf(FileContext& context, const DiscreteSpectrum& voxel);

bool runVariance(FileContext& context, schema::Record& record);
StageMemory varianceMemory(const Packing& packing, const RunSettings& settings);
/// An ensemble's alpha_pooled: the tail fit to its members' mean spectral sigma_V^2.
void poolVariance(EnsembleResults& ensemble, std::span<const FileResults> files);
/// An ensemble's alpha_pooled from its mean E(t) over the mean window, and the fit of every
/// member's wave vectors at that alpha (a0_pooled, a1_pooled, H_pooled).
void poolHyperuniformity(EnsembleResults& ensemble, std::span<const FileResults> files);

/// Writes `voxels` where --vdb exports them; the file written, nothing without --vdb.
std::optional<std::string> exportVoxels(const FileContext& context, const Voxelization& voxels);

#ifdef SBPACK_WITH_CUDA
// --device cuda (cuda_stages.cpp, docs/gpu.md): the grids on the GPU.
/// Refuses the run up front when its grids do not fit the device (gpu/gpu_memory.hpp).
void checkCudaRun(const RunSettings& settings);
/// voxels: the spectral grid voxelised on the GPU and kept there (a CudaGrid) for chi.
bool runCudaVoxels(FileContext& context, schema::Record& record);
/// chi from the kept CudaGrid, the transform by cuFFT.
SpectralDensityResult cudaSpectralDensity(FileContext& context,
                                          const SpectralDensityParameters& parameters);
/// The pore grid voxelised and distance-transformed on the GPU, the map copied to the host.
PoreSizeMap cudaPoreSizeMap(const FileContext& context, int voxels);
/// F(delta) of the voxel method with no map on the host: the squared distances' histogram made
/// on the GPU (CudaGrid::poreHistogram), what PoreSizeDistribution makes of the map.
PoreSizeDistributionResult cudaPoreSizes(const FileContext& context, int voxels,
                                         const PoreSizeParameters& parameters);
#endif

/// "6.12345": a number for progress lines (6 significant digits unless `digits`).
std::string describe(double value, int digits = 6);
/// Bytes of the collective-density tables of S(Q) (and the exact sphere chi) up to shell s.
double collectiveDensityBytes(const Packing& packing, int maxShell);

} // namespace sbpack::stages

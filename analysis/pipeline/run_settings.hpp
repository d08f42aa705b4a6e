#pragma once
// Everything one sbanalyze run is asked to do (filled by the command line, cli/): the run-wide
// settings, and each analysis's own parameter struct, declared with its defaults beside the
// analysis (docs/architecture.md, "Options").

#include "contacts/contact_network.hpp"
#include "gpu/compute_device.hpp"
#include "hyperuniformity/hyperuniformity.hpp"
#include "jamming/jamming_categories.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pores/pore_size_settings.hpp"
#include "spectral/spectral_density.hpp"
#include "structure/structure_factor.hpp"
#include "variance/volume_fraction_variance.hpp"
#include "voxels/voxelization.hpp"

#include <filesystem>
#include <vector>

namespace sbpack {

/// What the ranks of an MPI run share out (--distribute; docs/scale-out.md): whole files, or
/// the slabs of each file's grids (chi, voxels, pores and transport beyond one node's memory).
enum class Distribution { Files, Grids };

struct RunSettings {
    // The run.
    std::vector<std::filesystem::path> inputs;
    AnalysisSet analyses;
    std::filesystem::path output;       ///< results file (HDF5); empty: none
    std::filesystem::path json;         ///< JSON summary; "-": standard output; empty: none
    std::filesystem::path vdbDirectory; ///< .vdb export of each voxelization; empty: none
    int threads = 1;
    bool quiet = false;
    /// Where the grids are asked to be computed (--device; docs/gpu.md)
    ComputeDevice requestedDevice = ComputeDevice::Auto;
    /// ... and where they are, resolved once the options are read
    ResolvedDevice device;
    /// cuFFT in single precision (--fft-precision single; --device cuda only)
    bool fftSingle = false;
    Distribution distribute = Distribution::Files;
    /// --plan: print the per-rank memory and communication of the run and stop before any work
    bool plan = false;
    int planRanks = 0; ///< --plan-ranks P: plan for P ranks (0: the ranks of this run)

    // Each analysis's parameters (their options: AnalysisInfo::options).
    ContactParameters contacts;                ///< contacts, and info
    StructureFactorParameters structureFactor; ///< sq (--qmax)
    VoxelizationParameters voxelization;       ///< voxels: the spectral grid (--voxels)
    FftSettings fft;                           ///< chi: FFTW's planning (its Q range is sq's)
    PoreSizeSettings pores;                    ///< pores (and transport, which reads them)
    HyperuniformityParameters hyperuniformity; ///< hyper
    JammingSettings jamming;                   ///< jamming, and info --jamming
    VarianceParameters variance;               ///< variance

    bool runs(Analysis analysis) const { return analyses.count(analysis) != 0; }
    /// Whether chi keeps its voxel spectrum (hyper and variance read it).
    bool keepsVoxelSpectrum() const {
        return runs(Analysis::Hyperuniformity) || runs(Analysis::Variance);
    }
    /// chi's parameters: S(Q)'s Q range (--qmax serves both) and FFTW's planning.
    SpectralDensityParameters spectralDensity() const { return {structureFactor.maxQw, fft}; }
    /// The pores' method: --pores; else voxel under --distribute grids, the only one the
    /// distributed grid has (docs/scale-out.md); else the pores analysis's default.
    PoreMethod poreMethod() const {
        return pores.method.value_or(distribute == Distribution::Grids
                                         ? PoreMethod::Voxel
                                         : PoreSizeSettings::kDefaultMethod);
    }
    /// M of the pore grid (--pore-voxels, or the default of poreMethod()).
    int poreVoxels() const { return pores.gridVoxels(poreMethod()); }
    /// M of a grid; 0 for VoxelGrid::None.
    int voxelsOf(VoxelGrid grid) const {
        return grid == VoxelGrid::Spectral ? voxelization.voxels
               : grid == VoxelGrid::Pore   ? poreVoxels()
                                           : 0;
    }
    /// Why this run's grids must all stay on the CPU ("" when the GPU may compute those it can;
    /// refined pore sizes then run on the CPU beside them, docs/gpu.md).
    std::string cpuOnlyReason() const {
        if (runs(Analysis::Variance)) return "variance samples windows on the host's voxel grid";
        return distribute == Distribution::Grids ? "--distribute grids shares CPU slabs" : "";
    }
    /// Why --device cuda cannot compute every grid of the run ("" when it can).
    std::string cudaRefusal() const {
        if (runs(Analysis::PoreSizes) && poreMethod() == PoreMethod::Refined)
            return "--pores refined needs the feature transform (CPU only; --pores voxel runs on "
                   "the GPU, or --device auto puts only the pores on the CPU)";
        return cpuOnlyReason();
    }
    /// The grids the requested analyses work on.
    std::set<VoxelGrid> grids() const {
        std::set<VoxelGrid> used;
        for (Analysis a : analyses) {
            const bool voxelFree = a == Analysis::PoreSizes && poreMethod() == PoreMethod::Exact;
            if (analysisInfo(a).grid != VoxelGrid::None && !voxelFree)
                used.insert(analysisInfo(a).grid);
        }
        return used;
    }
};

} // namespace sbpack

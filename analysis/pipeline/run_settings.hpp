#pragma once
// Everything one sbanalyze run is asked to do (filled by the command line, cli/).

#include "contacts/contact_network.hpp"
#include "gpu/compute_device.hpp"
#include "hyperuniformity/hyperuniformity.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pores/pore_size_distribution.hpp"
#include "spectral/fftw_wisdom.hpp"

#include <filesystem>
#include <vector>

namespace sbpack {

/// What the ranks of an MPI run share out (--distribute; docs/scale-out.md): whole files, or
/// the slabs of each file's grids (chi, voxels, pores and transport beyond one node's memory).
enum class Distribution { Files, Grids };

struct RunSettings {
    std::vector<std::filesystem::path> inputs;
    AnalysisSet analyses;
    std::filesystem::path output;       ///< results file (HDF5); empty: none
    std::filesystem::path json;         ///< JSON summary; "-": standard output; empty: none
    std::filesystem::path vdbDirectory; ///< .vdb export of each voxelization; empty: none
    int threads = 1;
    int voxels = 300; ///< M of the spectral grid
    /// M of the pore grid: refined pore sizes at M = 200 are within 0.1 % of the exact ones, in
    /// less time than the paper's voxel method at M = 500 (+21-29 % on <delta>; bench/RESULTS.md,
    /// "Error against run time")
    int poreVoxels = 200;
    static constexpr int kPaperPoreVoxels = 500; ///< the paper's M, --pores voxel's default
    /// How the pores analysis measures pore sizes (--pores)
    PoreMethod poreMethod = PoreMethod::Refined;
    /// K (--pore-points): voxel and refined, K random void voxels (seeded) instead of every void
    /// voxel when K > 0; exact, K random points of the void (0: kDefaultExactPorePoints)
    std::int64_t porePoints = 0;
    static constexpr std::int64_t kDefaultExactPorePoints = 1'000'000; ///< the paper's 10^6
    std::uint64_t poreSeed = 1; ///< seed of the random points (--pore-seed)
    double maxQw = 30.0;        ///< S(Q) and chi(Q) up to Q w <= maxQw
    /// hyper: chi_V exactly (no voxels) at Q w <= chiExactQw; 0: voxel data alone
    double chiExactQw = 3.0;
    /// hyper: the fit a0 + a1 Q^alpha over Q w <= fitQw; times and an alpha window (t D / w^2)
    HyperuniformityParameters hyperuniformity;
    ContactParameters contacts;
    FftSettings fft;
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

    bool runs(Analysis analysis) const { return analyses.count(analysis) != 0; }
    /// M of a grid; 0 for VoxelGrid::None.
    int voxelsOf(VoxelGrid grid) const {
        return grid == VoxelGrid::Spectral ? voxels : grid == VoxelGrid::Pore ? poreVoxels : 0;
    }
    /// Why this run's grids must all stay on the CPU ("" when the GPU may compute those it can;
    /// refined pore sizes then run on the CPU beside them, docs/gpu.md).
    std::string cpuOnlyReason() const {
        return distribute == Distribution::Grids ? "--distribute grids shares CPU slabs" : "";
    }
    /// Why --device cuda cannot compute every grid of the run ("" when it can).
    std::string cudaRefusal() const {
        if (runs(Analysis::PoreSizes) && poreMethod == PoreMethod::Refined)
            return "--pores refined needs the feature transform (CPU only; --pores voxel runs on "
                   "the GPU, or --device auto puts only the pores on the CPU)";
        return cpuOnlyReason();
    }
    /// The grids the requested analyses work on.
    std::set<VoxelGrid> grids() const {
        std::set<VoxelGrid> used;
        for (Analysis a : analyses) {
            const bool voxelFree = a == Analysis::PoreSizes && poreMethod == PoreMethod::Exact;
            if (analysisInfo(a).grid != VoxelGrid::None && !voxelFree)
                used.insert(analysisInfo(a).grid);
        }
        return used;
    }
};

} // namespace sbpack

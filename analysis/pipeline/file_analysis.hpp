#pragma once
// The analyses of one packing file: what the results file and the summary report for it.

#include "contacts/contact_network.hpp"
#include "pipeline/run_settings.hpp"
#include "pores/pore_size_distribution.hpp"
#include "progress/progress.hpp"
#include "spectral/spectral_density.hpp"
#include "structure/structure_factor.hpp"
#include "transport/transport.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace sbpack {

struct ContactsRecord {
    ContactResult result;
    double runtimeSeconds = 0.0;
};

/// What is kept of a voxelization once its file is done (the grid itself is released).
struct VoxelizationRecord {
    VoxelizationParameters parameters;
    double voxelSize = 0.0;
    double phiVoxel = 0.0;
    double phiExact = 0.0;
    std::int64_t solidCount = 0;
    std::size_t memoryBytes = 0;   ///< OpenVDB tree
    std::filesystem::path vdbFile; ///< where it was exported; empty: not exported
    double runtimeSeconds = 0.0;
};

struct FileResults {
    std::filesystem::path input;
    double p = 0.0;
    std::int64_t particles = 0;
    double boxLength = 0.0;
    double semiAxis = 0.0;
    double phi = 0.0;
    double meanWidth = 0.0;
    std::optional<ContactsRecord> contacts;
    std::optional<StructureFactorResult> structureFactor;
    std::optional<VoxelizationRecord> voxelization;
    std::optional<SpectralDensityResult> spectralDensity;
    std::optional<PoreSizeDistributionResult> poreSizes;
    std::optional<TransportResult> transport;
};

/// Where a voxelization is exported: written to `temporary`, reported as `destination`.
struct VdbExport {
    std::filesystem::path temporary;
    std::filesystem::path destination;
};

/// Runs the analyses of `settings` on one packing (already validated), reporting one line per
/// stage. With `vdb`, the spectral-grid voxelization is exported (and the pore-size map beside
/// it, `poreVdb`, when pores are computed).
FileResults analyzeFile(const Packing& packing, const std::filesystem::path& input,
                        const RunSettings& settings, const Progress& progress,
                        const std::optional<VdbExport>& vdb,
                        const std::optional<VdbExport>& poreVdb = std::nullopt);

} // namespace sbpack

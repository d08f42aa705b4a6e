#include "pipeline/scale_plan.hpp"

#include "parallel/available_memory.hpp"
#include "pipeline/resources.hpp"
#include "voxels/voxelization.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace sbpack {

namespace {

/// The voxel tree of a slab of `planes` x-planes: the whole grid's estimate in proportion,
/// with the particles reaching in from either side.
double slabTreeBytes(const Packing& packing, int voxels, int planes) {
    const double reach = 2.0 * packing.shape().circumradius() / packing.boxLength * voxels + 16.0;
    const double share = std::min(1.0, (planes + reach) / voxels);
    return Voxelizer::memoryEstimateBytes(packing, voxels) * share;
}

int largestSlab(int voxels, int ranks) {
    return slabOf(voxels, ranks, 0).size();
}

} // namespace

Slab slabOf(int voxels, int ranks, int rank) {
    const int block = (voxels + ranks - 1) / ranks;
    return {std::min(voxels, rank * block), std::min(voxels, (rank + 1) * block)};
}

double transposeBytes(int voxels, int ranks, double cellBytes) {
    double bytes = 0.0;
    for (int r = 0; r < ranks; ++r) {
        const double planes = slabOf(voxels, ranks, r).size();
        bytes += planes * (voxels - planes) * cellBytes;
    }
    return bytes;
}

DistributionFigures spectralGridPlan(const Packing& packing, int voxels, int ranks) {
    const int slab = largestSlab(voxels, ranks);
    const int half = voxels / 2 + 1; // complex numbers per row of the r2c transform
    const double row = half;
    DistributionFigures f{ranks, slab, 0.0, 0.0};
    f.memoryPerRankBytes = 16.0 * slab * voxels * row + slabTreeBytes(packing, voxels, slab);
    f.communicationBytes = transposeBytes(voxels, ranks, 16.0 * row);
    return f;
}

DistributionFigures poreGridPlan(const Packing& packing, int voxels, int ranks) {
    const int slab = largestSlab(voxels, ranks);
    const double planeBytes = static_cast<double>(voxels) * voxels;
    DistributionFigures f{ranks, slab, 0.0, 0.0};
    f.memoryPerRankBytes = std::max(5.0 * slab * planeBytes + slabTreeBytes(packing, voxels, slab),
                                    8.0 * slab * planeBytes);
    f.communicationBytes = transposeBytes(voxels, ranks, 4.0 * voxels);
    return f;
}

void checkDistribution(const RunSettings& settings, const Communicator& comm) {
    if (settings.planRanks < 0)
        throw std::invalid_argument("option --plan-ranks: must be at least 1");
    if (settings.distribute != Distribution::Grids) return;
    const char* why = nullptr;
    if (settings.runs(Analysis::Hyperuniformity))
        why = "hyper (it needs every wave vector on one rank; leave it out of --compute)";
    else if (settings.runs(Analysis::Variance))
        why = "variance (its windows need the whole grid on one rank; leave it out of --compute)";
    else if (settings.runs(Analysis::Voronoi))
        why = "voronoi (its cells need the whole grid on one rank; leave it out of --compute)";
    else if (!settings.vdbDirectory.empty())
        why = "--vdb (a slab is not a whole grid)";
    else if (settings.pores.points > 0)
        why = "--pore-points (random points of the whole grid)";
    else if (settings.runs(Analysis::PoreSizes) && settings.poreMethod() != PoreMethod::Voxel)
        why = "--pores refined or exact (the distributed grid's pore sizes are --pores voxel)";
    if (why != nullptr)
        throw std::invalid_argument(std::string("option --distribute grids: does not take ") + why);
    if (comm.grids() == nullptr && !settings.plan)
        throw std::invalid_argument(
            "option --distribute grids: this sbanalyze is built without MPI "
            "(cmake -DSBPACK_WITH_MPI=ON) and runs on one process; --plan still plans");
}

void checkPlanMemory(const RunSettings& settings, const std::vector<Packing>& packings, int ranks) {
    const std::optional<double> available = availableMemoryBytes();
    if (!available) return;
    for (const Packing& packing : packings) {
        double bytes = 0.0;
        if (settings.grids().count(VoxelGrid::Spectral))
            bytes =
                spectralGridPlan(packing, settings.voxelization.voxels, ranks).memoryPerRankBytes;
        if (settings.grids().count(VoxelGrid::Pore))
            bytes = std::max(
                bytes, poreGridPlan(packing, settings.poreVoxels(), ranks).memoryPerRankBytes);
        if (bytes > *available)
            throw std::invalid_argument(fmt::format(
                "--distribute grids: each of the {} ranks needs about {} of memory, more than "
                "the {} available; use more ranks, a smaller --voxels or --pore-voxels (--plan)",
                ranks, formatBytes(bytes), formatBytes(*available)));
    }
}

namespace {

std::string gridLine(const char* name, int voxels, const DistributionFigures& f) {
    return fmt::format("  {} grid {}^3: slab of {} x-planes per rank, memory per rank {}, "
                       "communication {} in all ({} per rank)\n",
                       name, voxels, f.slab, formatBytes(f.memoryPerRankBytes),
                       formatBytes(f.communicationBytes),
                       formatBytes(f.communicationBytes / f.ranks));
}

std::string filePlan(const RunSettings& settings, const Packing& packing, int ranks) {
    if (settings.distribute == Distribution::Files) {
        const MemoryEstimate e = estimateMemory(packing, settings);
        return fmt::format("  memory per rank {} ({}); communication: its results records only\n",
                           formatBytes(e.bytes), e.breakdown.empty() ? "small" : e.breakdown);
    }
    std::string text;
    if (settings.grids().count(VoxelGrid::Spectral))
        text += gridLine("spectral (--voxels)", settings.voxelization.voxels,
                         spectralGridPlan(packing, settings.voxelization.voxels, ranks));
    if (settings.grids().count(VoxelGrid::Pore))
        text += gridLine("pore (--pore-voxels)", settings.poreVoxels(),
                         poreGridPlan(packing, settings.poreVoxels(), ranks));
    return text.empty() ? "  no grid: every rank runs the analyses alike\n" : text;
}

} // namespace

std::string planText(const RunSettings& settings, const std::vector<Packing>& packings,
                     const std::vector<std::size_t>& mine, int ranks) {
    if (settings.planRanks > 0) ranks = settings.planRanks;
    const bool grids = settings.distribute == Distribution::Grids;
    const std::size_t files = settings.inputs.size();
    std::string text =
        fmt::format("sbanalyze plan: {} rank(s), --distribute {}, {} file(s){}\n", ranks,
                    grids ? "grids" : "files", files,
                    grids ? ", each on every rank"
                          : fmt::format(", at most {} per rank", (files + ranks - 1) / ranks));
    for (std::size_t k = 0; k < packings.size(); ++k)
        text += fmt::format("'{}' (N = {}, {}):\n", settings.inputs[mine[k]].string(),
                            packings[k].size(), packings[k].shapeSpec.describe()) +
                filePlan(settings, packings[k], ranks);
    return text;
}

} // namespace sbpack

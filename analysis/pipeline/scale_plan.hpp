#pragma once
// The plan of a distributed run (--plan, docs/scale-out.md): how the inputs or the grids' slabs
// are shared out over the ranks, the memory each rank needs and the bytes the ranks exchange,
// computed before any work from the packings' headers, so that a user can size a job. The
// distributed implementation (analysis/mpi/) reports the same figures measured.

#include "packing/packing.hpp"
#include "parallel/communicator.hpp"
#include "pipeline/distributed_grids.hpp"
#include "pipeline/run_settings.hpp"

#include <string>
#include <vector>

namespace sbpack {

/// x-planes [begin, end) of one rank.
struct Slab {
    int begin = 0, end = 0;
    int size() const { return end - begin; }
};

/// Rank `rank` of `ranks` over M planes: blocks of ceil(M / P) planes, as FFTW's MPI transforms
/// distribute by default (the last ranks may get fewer, or none).
Slab slabOf(int voxels, int ranks, int rank);

/// Bytes a transpose from x-slabs to y-slabs (both slabOf) sends from one rank to another, all
/// ranks together, for `cellBytes` bytes per (x, y) cell: sum_r |x_r| (M - |y_r|) cellBytes.
double transposeBytes(int voxels, int ranks, double cellBytes);

/// The spectral grid (chi, voxels) over `ranks`: FFTW's transposed r2c transform, its slab of
/// max(|x_0|, |y_0|) M (M/2 + 1) complex numbers and the slab's voxel tree per rank, one transpose
/// of 16 (M/2 + 1) bytes per (x, y) cell.
DistributionFigures spectralGridPlan(const Packing& packing, int voxels, int ranks);
/// The pore grid (pores): the slab's mask and squared distances, then one transpose of 4 bytes
/// per voxel through a send and a receive buffer: 8 max(|x_0|, |y_0|) M^2 bytes per rank at the
/// peak.
DistributionFigures poreGridPlan(const Packing& packing, int voxels, int ranks);

/// The options --distribute grids refuses (hyper, --vdb, --pore-points; std::invalid_argument
/// naming the option), and --distribute grids without MPI unless only planning.
void checkDistribution(const RunSettings& settings, const Communicator& comm);
/// Throws std::invalid_argument when a rank's planned grid memory exceeds MemAvailable.
void checkPlanMemory(const RunSettings& settings, const std::vector<Packing>& packings, int ranks);

/// The plan as text, one block per input read on this rank (`mine`: their indices), for
/// settings.planRanks ranks, else `ranks`.
std::string planText(const RunSettings& settings, const std::vector<Packing>& packings,
                     const std::vector<std::size_t>& mine, int ranks);

} // namespace sbpack

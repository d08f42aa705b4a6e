#pragma once
// The exact periodic Euclidean distance transform of a slab-decomposed M^3 grid
// (docs/scale-out.md): the separable passes of pores/distance_transform.hpp, along z and y within
// each rank's x-slab, one distributed transpose to y-slabs (MPI_Alltoallv of whole z-rows), then
// the pass along x. The squared distances are those of periodicDistanceTransform exactly: every
// pass is the same exact integer min-plus transform, and their order does not change the minimum.

#include "mpi/mpi_communicator.hpp"
#include "pipeline/scale_plan.hpp"
#include "progress/progress.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace sbpack {

struct DistanceSlab {
    int voxels = 0;
    Slab y; ///< this rank's y-planes
    /// Squared distances (voxel units) at ((y - y.begin) M + x) M + z: the y-slab of the map.
    std::vector<std::uint32_t> squared;
    std::uint32_t largest = 0; ///< the largest squared distance of the whole grid
    double peakBytes = 0.0;    ///< this rank's largest simultaneous buffers
    double sentBytes = 0.0;    ///< what this rank sent to other ranks
};

/// Collective. `mask`: this rank's x-slab slabOf(M, ranks, rank) of the solid mask,
/// ((x - x.begin) M + y) M + z, nonzero solid. Parallel over lines within the rank (threads).
DistanceSlab distributedDistanceTransform(const MpiCommunicator& comm,
                                          std::span<const std::uint8_t> mask, int voxels,
                                          const Progress& progress);

} // namespace sbpack

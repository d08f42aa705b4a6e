#pragma once
// The grid computations of --distribute grids (docs/scale-out.md): every rank holds a slab of
// x-planes of each M^3 grid, voxelises only the particles that reach it, and the ranks combine
// through MPI: chi_V by FFTW's MPI transform, the pore sizes by the separable exact distance
// transform with one distributed transpose. The interface is here, so that the pipeline's stages
// are one code with and without MPI; the implementation is analysis/mpi/ (SBPACK_WITH_MPI).

#include "parallel/distribution_figures.hpp"
#include "pores/pore_size_distribution.hpp"
#include "spectral/spectral_density.hpp"
#include "voxels/voxelization.hpp"

#include <cstdint>

namespace sbpack {

/// One rank's slab of a distributed voxelization and the whole grid's figures.
struct SlabVoxels {
    Voxelization slab;
    std::int64_t solidCount = 0; ///< solid voxels of the whole M^3 grid
    DistributionFigures figures;

    double phiVoxel() const {
        const double m = slab.voxels();
        return static_cast<double>(solidCount) / (m * m * m);
    }
};

class DistributedGrids {
  public:
    virtual ~DistributedGrids() = default;
    /// Collective: this rank's slab of the M^3 voxelization (the spectral transform's slab).
    virtual SlabVoxels voxelize(const Packing& packing, int voxels,
                                const Progress& progress) const = 0;
    /// Collective: chi_V of the slabs' grid (SpectralDensity::compute's result, every rank).
    virtual SpectralDensityResult spectralDensity(const Packing& packing, const SlabVoxels& voxels,
                                                  const SpectralDensityParameters& parameters,
                                                  const Progress& progress,
                                                  DistributionFigures& figures) const = 0;
    /// Collective: the pore sizes of the M^3 pore grid (PoreSizeDistribution::compute's result
    /// over every void voxel, every rank).
    virtual PoreSizeDistributionResult poreSizes(const Packing& packing, int voxels,
                                                 const PoreSizeParameters& parameters,
                                                 double meanWidth, const Progress& progress,
                                                 DistributionFigures& figures) const = 0;
};

} // namespace sbpack

#pragma once
// Set-Voronoi cells of a packing (docs/local-structure.md §1; Schaller et al. 2013): the cell of
// particle i is the part of space closer to its surface than to any other particle's. On the
// voxel grid: every voxel goes to the particle of its nearest solid voxel (the exact periodic
// feature transform of the solid voxels, each labelled with the particle whose body holds its
// centre), so the cells tile the box exactly, and the local packing fraction is
// phi_i = v1 / v_cell(i).

#include "packing/packing.hpp"
#include "progress/progress.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace sbpack {

/// Moments of the local packing fractions of a set of particles.
struct LocalPhiMoments {
    std::int64_t count = 0;
    double mean = 0.0;
    double sd = 0.0; ///< sample standard deviation (n - 1)
    /// count / sum 1 / phi_i: the global phi of their cells (of identical particles only)
    double harmonicMean = 0.0;
    double min = 0.0;
    double max = 0.0;
};

struct SetVoronoiResult {
    int voxels = 0;                  ///< M
    double voxelSize = 0.0;          ///< a = L / M
    double particleVolume = 0.0;     ///< v1 (of a mixture, the largest particle's)
    std::vector<double> cellVolumes; ///< v_cell(i), length^3, in particle order
    /// phi_i = v_i / v_cell(i), v_i = v1 (R_i / R)^3 the particle's own volume
    std::vector<double> localPhi;
    /// Each particle's solid voxels times a^3 over v_i, minus 1: the voxel rounding of a particle
    /// (the cell boundaries are placed to that rounding).
    std::vector<double> particleVoxelError;
    LocalPhiMoments all;
    std::optional<LocalPhiMoments> nonRattlers; ///< given the rattlers
    std::optional<LocalPhiMoments> rattlers;    ///< given the rattlers, where there are any
    /// Sum of the cells over L^3, minus 1: zero but for rounding (the cells tile the box).
    double tilingError = 0.0;
    /// Root mean square of particleVoxelError.
    double voxelErrorRms = 0.0;
    std::vector<double> histogramPhi;     ///< bin centres of the local phi density
    std::vector<double> histogramDensity; ///< density of phi_i over all particles (integrates to 1)
    double runtimeSeconds = 0.0;
};

/// Compute object (docs/design.md §7).
class SetVoronoi {
  public:
    /// Bins of the local-phi density over [0, 1].
    static constexpr int kHistogramBins = 200;

    /// Throws VoxelResolutionError (voxels/voxelization.hpp) for M outside [1,
    /// maxFeatureTransformVoxels].
    explicit SetVoronoi(int voxels);

    /// The cells of `packing` on the M^3 grid; `rattler` (per particle, or empty) splits the
    /// moments. Memory: 13 bytes per voxel (labels, mask, squared distances, features). Throws
    /// as Voxelizer::compute and periodicFeatureTransform, and std::invalid_argument for a
    /// rattler vector of the wrong size.
    SetVoronoiResult compute(const Packing& packing, const std::vector<bool>& rattler,
                             const Progress& progress) const;

    /// Bytes compute() holds at M voxels per side.
    static double memoryBytes(int voxels);

    int voxels() const { return voxels_; }

  private:
    int voxels_;
};

} // namespace sbpack

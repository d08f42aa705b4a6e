#pragma once
// Near-exact pore sizes at voxel cost (paper Sec. II B, Eqs. 13-15): the distance from each void
// voxel centre to the nearest particle surface, exact up to a certified bound, instead of the
// distance between voxel centres (docs/design.md §5). The feature transform of the voxel grid
// names a nearby particle; its surface and those of the neighbours that can be nearer are solved
// exactly (ExactPoreSizes). F(delta) and the moments are then those of a regular grid of points
// of the void rather than of the voxel centres' distances.

#include "packing/packing.hpp"
#include "pores/distance_transform.hpp"
#include "pores/exact_pore_size.hpp"
#include "pores/pore_size_distribution.hpp"
#include "progress/progress.hpp"

#include <vector>

namespace sbpack {

/// The pore size of points of the void from a feature particle and its neighbours.
class VoxelRefiner {
  public:
    /// Neighbour lists of every particle up to centre distance 2 r_c + 2 maxPoreSize (r_c the
    /// circumradius), from common/'s CellList, when that is at most L / 2; otherwise every point
    /// takes the general search of ExactPoreSizes. maxPoreSize must bound every pore size
    /// (the voxel map's largest distance does).
    VoxelRefiner(const ExactPoreSizes& pores, double maxPoreSize);

    /// The distance from x (in [0, L)^3) to the nearest surface with its certificate, given a
    /// particle `feature` near x (-1: none known). Exact for any feature: a neighbour P can be
    /// nearer than the feature f only if |x - r_P| - r_c < d_f, hence
    /// |r_P - r_f| < d_f + r_c + |x - r_f|, and those are a prefix of f's sorted list.
    SurfaceDistance poreSize(const Vector3d& x, int feature) const;

    /// A particle containing s (in [0, L)^3), tried first `hint`, then its neighbours that can
    /// contain s, then ExactPoreSizes::particleContaining; -1 if none does.
    int particleContaining(const Vector3d& s, int hint) const;

    /// Whether the neighbour lists are used (false: the box is too small for them).
    bool usesNeighbourLists() const { return range_ > 0.0; }

  private:
    /// Minimum image of the difference of two points of [0, L)^3.
    Vector3d image(Vector3d d) const {
        const double length = pores_.boxLength();
        for (int k = 0; k < 3; ++k)
            d[k] += d[k] > 0.5 * length ? -length : (d[k] < -0.5 * length ? length : 0.0);
        return d;
    }

    struct Neighbour {
        double distance; ///< |r_P - r_f|, minimum image
        int particle;
        Vector3d offset; ///< r_P - r_f, minimum image
    };
    const ExactPoreSizes& pores_;
    bool spheres_;           ///< exact distances are as cheap as bounds
    double range_ = 0.0;     ///< 0: no lists
    std::vector<int> start_; ///< particle f: neighbours_[start_[f] .. start_[f + 1]), by distance
    std::vector<Neighbour> neighbours_;
};

/// Compute object: F(delta), P(delta) and moments from the refined pore sizes of every void voxel
/// centre (or, with randomPoints K > 0, of K random void voxels), method "refined" (or "random
/// voxels refined"). Each voxel's particle is the one containing its feature voxel (the nearest
/// solid voxel; that voxel's centre is inside it). F(delta) is binned at a / 256 (exact at the
/// bin edges); the moments are exact sums; the certified error bound, the standard errors of a
/// random sample and the largest pore (largestPore from the 16 largest points) are filled in.
class RefinedPoreSizeDistribution {
  public:
    /// Throws std::invalid_argument for randomPoints < 0 or densityBins < 1.
    explicit RefinedPoreSizeDistribution(PoreSizeParameters parameters);

    /// Throws std::invalid_argument unless the map carries features (periodicFeatureTransform)
    /// and covers the packing's box.
    PoreSizeDistributionResult compute(const PoreSizeMap& map, const Packing& packing,
                                       const Progress& progress) const;

    const PoreSizeParameters& parameters() const { return parameters_; }

  private:
    PoreSizeParameters parameters_;
};

} // namespace sbpack

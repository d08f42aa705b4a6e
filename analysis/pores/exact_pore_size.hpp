#pragma once
// Voxel-free pore sizes (paper Sec. II B): the distance from a point of the void to the nearest
// particle surface, computed exactly from the superball geometry of common/. The reference
// against which the voxel path (distance transform) is checked.

#include "packing/packing.hpp"
#include "pores/pore_size_distribution.hpp"

#include <cstdint>
#include <vector>

namespace sbpack {

/// The point of the superball (body frame, centred at the origin) nearest to xBody; xBody itself
/// when it is inside. Euclidean projection onto { sum |y_i / R|^{2p} <= 1 }: by symmetry in the
/// octant of |x|, from the KKT conditions u_i + kappa u_i^{2p-1} = |x_i| / R (u = |y| / R), a
/// monotone scalar equation per axis inside a monotone equation sum u_i^{2p} = 1 for kappa, both
/// solved by bracketed Newton steps to rounding. Closed forms for the sphere and, as the l1-ball
/// projection, for the octahedron p = 0.5. The distance |x - y| is certified by the support
/// function: with n = (x - y) / |x - y|, n.x - h(n) <= dist(x, body) <= |x - y|.
Vector3d closestPoint(const Superball& shape, const Vector3d& xBody);

/// Exact pore sizes of a packing: distance from a point to the nearest particle surface, over
/// all periodic images. Candidates come from a cell grid searched in shells of growing distance,
/// bounded below by |x - r| - circumradius and above by |x - r| - inradius, so that only the
/// particles that can be nearest are solved exactly.
class ExactPoreSizes {
  public:
    /// Throws std::invalid_argument for an empty packing or mismatched positions and orientations.
    explicit ExactPoreSizes(const Packing& packing);

    /// Distance from x (lab frame, any image) to the nearest particle; 0 if x is in a particle.
    double poreSize(const Vector3d& x) const;

    double boxLength() const { return boxLength_; }

  private:
    double distanceToParticle(int particle, const Vector3d& d) const;

    Superball shape_;
    double boxLength_;
    double circumradius_;
    double inradius_;
    std::vector<Vector3d> positions_;
    std::vector<Matrix3d> rotations_; ///< body to lab
    int cellsPerSide_;
    double cellSize_;
    std::vector<int> cellStart_; ///< cell c holds cellParticles_[cellStart_[c] .. cellStart_[c+1])
    std::vector<int> cellParticles_;
};

struct ExactPoreSizeParameters {
    std::int64_t randomPoints = 1'000'000; ///< K random points of the void (paper: 10^6)
    std::uint64_t seed = 1;
    int densityBins = 64;
    bool serial = false;
};

/// Compute object: F(delta) and moments from the exact pore sizes of K uniformly random points
/// of the void (points inside a particle are drawn again). Method "exact".
class ExactPoreSizeDistribution {
  public:
    /// Throws std::invalid_argument for randomPoints < 1 or densityBins < 1.
    explicit ExactPoreSizeDistribution(ExactPoreSizeParameters parameters);

    /// Throws std::invalid_argument for an empty packing and std::domain_error when no void
    /// point is found among 1000 K draws (no void).
    PoreSizeDistributionResult compute(const Packing& packing) const;

    const ExactPoreSizeParameters& parameters() const { return parameters_; }

  private:
    ExactPoreSizeParameters parameters_;
};

} // namespace sbpack

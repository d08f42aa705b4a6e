#pragma once
// Voxel-free pore sizes (paper Sec. II B): the distance from a point of the void to the nearest
// particle surface, computed exactly from the particle shape's geometry (ParticleShape). The
// reference against which the voxel path (distance transform) is checked.

#include "contacts/cell_list.hpp"
#include "packing/packing.hpp"
#include "pores/pore_size_distribution.hpp"
#include "progress/progress.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sbpack {

/// Certified bounds on a distance to a particle surface: the true distance lies in [lower, upper];
/// upper is the distance to a point of the surface (a distance that is realised), lower the
/// support function's bound n.x - h(n) (closestPoint). Both 0 inside a particle.
struct SurfaceDistance {
    double lower = 0.0;
    double upper = 0.0;
};

/// Exact pore sizes of a packing: distance from a point to the nearest particle surface, over
/// all periodic images. Candidates come from a cell grid searched in shells of growing distance,
/// bounded below by |x - r| - circumradius and above by |x - r| - inradius, so that only the
/// particles that can be nearest are solved exactly. A mixture's particle j of size s_j = R_j / R
/// is the largest particle's shape scaled by s_j: its distances s_j times those of d / s_j
/// (docs/mixtures.md).
class ExactPoreSizes {
  public:
    /// Throws std::invalid_argument for an empty packing or mismatched positions and orientations.
    explicit ExactPoreSizes(const Packing& packing);

    /// Distance from x (lab frame, any image) to the nearest particle; 0 if x is in a particle.
    double poreSize(const Vector3d& x) const { return poreSizeBounds(x).upper; }
    /// The same with its certificate: the minimum over the particles of particleDistance.
    SurfaceDistance poreSizeBounds(const Vector3d& x) const;
    /// Distance from x = r + d to particle `particle` centred at r (d in the lab frame; the
    /// caller picks the image), with its certificate.
    SurfaceDistance particleDistance(int particle, const Vector3d& d) const;
    /// A lower bound on particleDistance(particle, d) from one support function:
    /// n.d - h(n) with n = d / |d| (docs/design.md §5), cheaper than the exact distance.
    double distanceLowerBound(int particle, const Vector3d& d) const {
        const double centre = d.norm(), s = relativeSize(particle);
        if (shape_.isSphere() || centre == 0.0) return centre - s * shape_.semiAxis();
        return centre - s * shape_.support(rotations_[particle].transpose() * d / centre);
    }
    /// A particle whose minimum image contains x (the shape's gaugePower), or -1 if none does.
    int particleContaining(const Vector3d& x) const;
    /// Whether r + d is inside particle `particle` centred at r (gaugePower < 1, which may differ
    /// from the shape's inside test within rounding of the surface); no gauge well inside the
    /// inscribed sphere.
    bool inside(int particle, const Vector3d& d) const {
        const double s = relativeSize(particle);
        if (s != 1.0) return insideUnit(particle, d / s);
        return insideUnit(particle, d);
    }
    /// Particle j's size over the largest (1 for identical particles).
    double relativeSize(int j) const { return sizes_.empty() ? 1.0 : sizes_[j]; }

    double boxLength() const { return boxLength_; }
    double circumradius() const { return circumradius_; }
    bool isSphere() const { return shape_.isSphere(); }
    int size() const { return static_cast<int>(positions_.size()); }
    /// Centre of particle j, wrapped into [0, L)^3.
    const Vector3d& position(int j) const { return positions_[j]; }

  private:
    /// inside() and particleDistance() for the largest particle's shape.
    bool insideUnit(int particle, const Vector3d& d) const {
        const double squared = d.squaredNorm();
        if (shape_.isSphere()) return squared < shape_.semiAxis() * shape_.semiAxis();
        if (squared < (1.0 - 1e-12) * inradius_ * inradius_) return true;
        return shape_.gaugePower(rotations_[particle].transpose() * d) < 1.0;
    }
    SurfaceDistance unitDistance(int particle, const Vector3d& d) const;
    /// Calls visit(particle, shift) for each particle of cell `unwrapped` (cell indices taken
    /// modulo the cells per side, shift the image's lab offset).
    template <class Visit>
    void forEachInCell(const std::array<int, 3>& unwrapped, Visit&& visit) const;
    std::array<int, 3> homeCell(const Vector3d& xWrapped) const;

    ParticleShape shape_;
    double boxLength_;
    double circumradius_;
    double inradius_;
    std::vector<Vector3d> positions_;
    std::vector<Matrix3d> rotations_; ///< body to lab
    std::vector<double> sizes_;       ///< a mixture's R_j / R; empty for identical particles
    CellList cells_; ///< cells of edge >= the circumradius (common/contacts/cell_list)
};

struct ExactPoreSizeParameters {
    std::int64_t randomPoints = 1'000'000;          ///< K random points of the void (paper: 10^6)
    std::uint64_t seed = PoreSizeParameters{}.seed; ///< as the voxel methods' (--pore-seed)
    int densityBins = 64;
};

/// Compute object: F(delta) and moments from the exact pore sizes of K uniformly random points
/// of the void (points inside a particle are drawn again). Method "exact".
class ExactPoreSizeDistribution {
  public:
    /// Throws std::invalid_argument for randomPoints < 1 or densityBins < 1.
    explicit ExactPoreSizeDistribution(ExactPoreSizeParameters parameters);

    /// Throws std::invalid_argument for an empty packing and std::domain_error when no void
    /// point is found among 1000 K draws (no void); Interrupted when `progress` is (it is polled
    /// once per chunk of points).
    PoreSizeDistributionResult compute(const Packing& packing, const Progress& progress) const;

    const ExactPoreSizeParameters& parameters() const { return parameters_; }

  private:
    ExactPoreSizeParameters parameters_;
};

} // namespace sbpack

namespace sbpack {

template <class Visit>
void ExactPoreSizes::forEachInCell(const std::array<int, 3>& unwrapped, Visit&& visit) const {
    const int n = cells_.cellsPerSide();
    std::array<int, 3> cell{};
    Vector3d shift;
    for (int k = 0; k < 3; ++k) {
        const int image = static_cast<int>(std::floor(static_cast<double>(unwrapped[k]) / n));
        cell[k] = unwrapped[k] - image * n;
        shift[k] = image * boxLength_;
    }
    cells_.forEachInCell(cells_.cells().index(cell[0], cell[1], cell[2]),
                         [&](int particle) { visit(particle, shift); });
}

} // namespace sbpack

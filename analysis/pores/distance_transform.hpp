#pragma once
// Exact periodic Euclidean distance transform of the void phase of a voxelised packing (paper
// Sec. III B; docs/design.md §5): the pore-size map, from which F(delta) (Eq. 13) is computed.

#include "progress/progress.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace sbpack {

/// Memory of the pore-size path at M voxels per side: the solid mask the voxelisation hands over
/// (1 byte per voxel) and the squared distances (4 bytes per voxel), in bytes.
std::uint64_t poreSizeMemoryBytes(int voxels);

/// Throws std::invalid_argument for M < 1 or M > maxPoreSizeVoxels, and std::runtime_error with
/// the estimate poreSizeMemoryBytes(M) when it exceeds MemAvailable of /proc/meminfo (not checked
/// where that file cannot be read). Call it before voxelising.
void checkPoreSizeMemory(int voxels);

/// Largest M accepted: keeps the envelope's integer arithmetic and its floors exact (see the .cpp).
inline constexpr int maxPoreSizeVoxels = 16384;
/// Largest M of the feature transform: every voxel index (i * M + j) * M + k fits 32 bits.
inline constexpr int maxFeatureTransformVoxels = 1625;

namespace detail {
struct LineScratch;
}

/// "No site" in the min-plus passes (a void voxel before the first pass).
inline constexpr std::uint32_t kNoSite = 0xffffffffu;

/// One pass of the separable transform below along one line, for the passes of a distributed
/// grid (docs/scale-out.md): the exact periodic min-plus transform
/// out(p) = min_q f(q) + (min-image |p - q|)^2 in place on the M values of a line `stride`
/// apart (f = kNoSite: no site; f = 0 on solid and kNoSite on void gives the squared 1-D
/// distance to the nearest solid). Holds per-line scratch: one object per thread.
class PeriodicLineTransform {
  public:
    explicit PeriodicLineTransform(int voxels);
    PeriodicLineTransform(PeriodicLineTransform&&) noexcept = default;
    ~PeriodicLineTransform();
    /// Transforms the line; returns its largest value afterwards.
    std::uint32_t operator()(std::uint32_t* line, std::int64_t stride);

  private:
    std::unique_ptr<detail::LineScratch> scratch_;
};

/// Squared distances, in voxel units, from every voxel centre to the nearest solid voxel centre
/// of an M^3 periodic grid (minimum image), 0 on solid voxels. Index (i * M + j) * M + k with
/// i, j, k the x, y, z voxel indices; voxel centre ((i + 0.5) a, (j + 0.5) a, (k + 0.5) a).
/// The pore size of a void voxel is a sqrt(squared distance).
class PoreSizeMap {
  public:
    int voxels() const { return voxels_; }
    /// a = L / M (length units of the packing).
    double voxelSize() const { return voxelSize_; }
    double boxLength() const { return voxelSize_ * voxels_; }
    std::span<const std::uint32_t> squaredDistances() const;
    std::int64_t voidCount() const { return voidCount_; }
    /// The void voxels' share of the M^3.
    double voidFraction() const {
        return static_cast<double>(voidCount_) / (static_cast<double>(voxels_) * voxels_ * voxels_);
    }
    /// Largest squared distance (voxel units): the largest pore is a sqrt of it.
    std::uint32_t maxSquaredDistance() const { return maxSquaredDistance_; }
    /// Feature transform (periodicFeatureTransform only, else empty): for every voxel the index
    /// (i * M + j) * M + k of a nearest solid voxel (minimum image, any one on ties), the voxel
    /// itself on solid voxels. The squared distance to it is squaredDistances()[index].
    std::span<const std::uint32_t> features() const;
    bool hasFeatures() const { return features_ != nullptr; }

    /// A map computed elsewhere (the GPU, gpu/cuda_grid.cpp): the M^3 squared distances with
    /// their void count and largest value, counted where they were made. Throws
    /// std::invalid_argument for M outside [1, maxPoreSizeVoxels].
    static PoreSizeMap fromSquaredDistances(std::unique_ptr<std::uint32_t[]> squared, int voxels,
                                            double voxelSize, std::int64_t voidCount,
                                            std::uint32_t maxSquaredDistance);

    /// Writes the map as an OpenVDB FloatGrid named "pore_size": active on the void voxels only,
    /// value the pore size in length units, index (i, j, k) centred at ((i, j, k) + 0.5) a, with
    /// metadata box_length, voxels and units. Atomic (AtomicOutput); throws OutputPathError.
    void writeVdb(const std::filesystem::path& file) const;
    /// The bytes of that .vdb file; metadata length_unit: what one length unit of the map is in
    /// the packing's (voxels/vdb_image.hpp).
    std::string vdbImage(double lengthUnit = 1.0) const;

  private:
    friend PoreSizeMap transformMask(std::span<const std::uint8_t>, int, double, const Progress&,
                                     bool);
    PoreSizeMap(int voxels, double voxelSize);
    PoreSizeMap(int voxels, double voxelSize, std::unique_ptr<std::uint32_t[]> squared);

    int voxels_;
    double voxelSize_;
    std::unique_ptr<std::uint32_t[]> squaredDistances_; ///< M^3 entries
    std::unique_ptr<std::uint32_t[]> features_;         ///< M^3 entries, or none
    std::int64_t voidCount_ = 0;
    std::uint32_t maxSquaredDistance_ = 0;
};

/// Throws std::domain_error when `solid` of the M^3 voxels leave no solid or no void voxel (the
/// pore sizes are undefined).
void checkSolidCount(std::int64_t solid, int voxels);

/// Exact separable distance transform of a periodic M^3 grid; `solidMask[(i * M + j) * M + k]
/// != 0` marks a solid voxel (as Voxelization::copySolidMask fills it). A 1-D pass along x, then
/// per x plane the periodic min-plus transform along y and z: a Felzenszwalb-Huttenlocher lower
/// envelope of parabolas with exact rational breakpoints, or, on lines whose values are all
/// <= 32^2, an exact outward scan (at most 32 steps per voxel). Linear in M^3; parallel over
/// columns and planes (parallelFor), serial as `progress` asks. Memory: the map
/// (4 bytes per voxel) plus per-line scratch. Throws std::invalid_argument for a mask of the
/// wrong size, M outside [1, maxPoreSizeVoxels] or a voxel size that is not finite and positive,
/// std::runtime_error when the map exceeds MemAvailable, and std::domain_error when the grid has
/// no solid or no void voxel (the pore sizes are undefined).
PoreSizeMap periodicDistanceTransform(std::span<const std::uint8_t> solidMask, int voxels,
                                      double voxelSize, const Progress& progress = Progress());

/// The same distances with the feature transform (PoreSizeMap::features): each pass carries the
/// nearest solid voxel of the site that wins each voxel's minimum. Memory: 4 more bytes per
/// voxel. Throws as periodicDistanceTransform, and std::invalid_argument for M above
/// maxFeatureTransformVoxels.
PoreSizeMap periodicFeatureTransform(std::span<const std::uint8_t> solidMask, int voxels,
                                     double voxelSize, const Progress& progress = Progress());

/// The implementation of both (features when withFeatures).
PoreSizeMap transformMask(std::span<const std::uint8_t> solidMask, int voxels, double voxelSize,
                          const Progress& progress, bool withFeatures);

} // namespace sbpack

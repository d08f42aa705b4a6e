#pragma once
// Voxelization of a packing (paper Sec. III B, docs/design.md §5): M^3 cubic voxels of edge a = L /
// M tile the periodic box; voxel (i, j, k) has its centre at ((i + 1/2) a, (j + 1/2) a, (k + 1/2)
// a) and is solid when that centre lies inside a particle or one of its periodic images
// (the shape's inside test on the body-frame vector; the paper's epsilon rescaling is not applied).
// Stored sparsely as an OpenVDB mask grid; OpenVDB stays out of this header (pimpl).

#include "packing/packing.hpp"
#include "progress/progress.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

/// A grid too coarse for the particles, or too large to be represented.
class VoxelResolutionError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

struct VoxelizationParameters {
    int voxels = 300; ///< M, voxels along each box edge
    /// Only the slab of x-planes [slabBegin, slabEnd) (slabEnd -1: M; may be empty), as one rank of
    /// a distributed grid voxelises (docs/scale-out.md): only particles (and periodic images) whose
    /// circumscribed sphere reaches the slab are visited, and the tree holds the slab alone.
    int slabBegin = 0;
    int slabEnd = -1;
};

/// The immutable result: which voxels are solid.
class Voxelization {
  public:
    Voxelization(Voxelization&&) noexcept;
    Voxelization& operator=(Voxelization&&) noexcept;
    ~Voxelization();

    int voxels() const { return voxels_; }
    double boxLength() const { return boxLength_; }
    double voxelSize() const { return boxLength_ / voxels_; }
    std::int64_t solidCount() const { return solidCount_; }
    /// Fraction of solid voxels (of the slab's, for a slab).
    double phiVoxel() const;
    /// The x-planes [slabBegin, slabEnd) held (the whole grid: 0, M).
    int slabBegin() const { return slabBegin_; }
    int slabEnd() const { return slabEnd_; }
    /// N v1 / L^3 of the packing voxelized.
    double phiExact() const { return phiExact_; }
    /// Memory held by the OpenVDB tree (bytes).
    std::size_t memoryBytes() const;
    double runtimeSeconds() const { return runtimeSeconds_; }
    const VoxelizationParameters& parameters() const { return parameters_; }

    /// Whether voxel (i, j, k) is solid; indices are taken modulo M (periodic box).
    bool solid(std::int64_t i, std::int64_t j, std::int64_t k) const;
    /// Fills mask[(i * M + j) * M + k] with 1 (solid) or 0 for every voxel; parallel by blocks of
    /// the grid (serial as `progress` asks). Throws std::invalid_argument unless mask.size() ==
    /// M^3. For a slab, i counts from slabBegin() and the size is (slabEnd() - slabBegin()) M^2
    /// (also below).
    void copySolidMask(std::span<std::uint8_t> mask, const Progress& progress = Progress()) const;
    /// Fills values[(i * M + j) * rowStride + k] with 1.0 (solid) or 0.0 for k < M, leaving
    /// the padding k >= M of each row alone (FFTW's in-place real-to-complex layout).
    /// Throws std::invalid_argument unless rowStride >= M and values.size() == M^2 rowStride.
    void copySolidIndicator(std::span<double> values, std::int64_t rowStride,
                            const Progress& progress = Progress()) const;

    /// Writes the grid as an OpenVDB file (atomically, through AtomicOutput) for Blender,
    /// Houdini or ParaView: a float fog volume "density" (1 in the particles, 0 elsewhere) in
    /// the packing's length units, with metadata the shape's parameters (p), box_length, voxels,
    /// phi_voxel, phi_exact.
    void writeVdb(const std::filesystem::path& file) const;
    /// The bytes of that .vdb file (writeVdb writes them through AtomicOutput); metadata
    /// length_unit: what one length unit of the grid is in the packing's (voxels/vdb_image.hpp).
    std::string vdbImage(double lengthUnit = 1.0) const;

  private:
    friend class Voxelizer;
    struct Grid; // the OpenVDB mask grid
    Voxelization(std::unique_ptr<Grid> grid, VoxelizationParameters parameters, double boxLength,
                 const ShapeSpec& shape, double phiExact, std::int64_t solidCount,
                 double runtimeSeconds);
    template <class T>
    void copySolid(std::span<T> values, std::int64_t rowStride, const char* what,
                   const Progress& progress) const;

    std::unique_ptr<Grid> grid_;
    VoxelizationParameters parameters_;
    int voxels_;
    double boxLength_;
    ShapeSpec shape_;
    double phiExact_;
    std::int64_t solidCount_;
    double runtimeSeconds_;
    int slabBegin_;
    int slabEnd_;
};

/// Every periodic image of every particle whose sphere of radius rc can reach a voxel centre of
/// the box: along each axis the particle itself, and its copy shifted by +L (-L) where it sticks
/// out below 0 (above L); visit(centre, particle index) for each, in one fixed order. The CPU
/// and the GPU voxelisers (gpu/particle_images.cpp) visit these same images.
template <class Visit> void forEachPeriodicImage(const Packing& packing, double rc, Visit&& visit) {
    const double l = packing.boxLength;
    auto shifts = [l, rc](double c, std::array<double, 3>& out) {
        int n = 0;
        out[n++] = 0.0;
        if (c - rc < 0.0) out[n++] = l;
        if (c + rc > l) out[n++] = -l;
        return n;
    };
    std::array<double, 3> sx{}, sy{}, sz{};
    for (std::size_t j = 0; j < packing.size(); ++j) {
        const Vector3d& r = packing.positions[j];
        const int nx = shifts(r.x(), sx), ny = shifts(r.y(), sy), nz = shifts(r.z(), sz);
        for (int x = 0; x < nx; ++x)
            for (int y = 0; y < ny; ++y)
                for (int z = 0; z < nz; ++z)
                    visit(Vector3d(r + Vector3d(sx[x], sy[y], sz[z])), static_cast<int>(j));
    }
}

/// Compute object (docs/design.md §7): parameters validated at construction.
class Voxelizer {
  public:
    /// Largest M accepted (OpenVDB coordinates and M^3 stay far from overflow).
    static constexpr int kMaxVoxels = 1 << 16;
    /// Fewest voxels across the narrowest width of a particle (twice its inradius).
    static constexpr double kMinVoxelsAcross = 4.0;

    /// Throws VoxelResolutionError unless 1 <= voxels <= kMaxVoxels and the slab is in [0, M].
    explicit Voxelizer(VoxelizationParameters parameters);

    /// The circumscribed radius with the margin that keeps the sphere shortcuts exact: voxel
    /// centres farther from a particle's centre are never tested (the CPU and GPU voxelisers).
    static double reach(const ParticleShape& shape);
    /// Smallest M that puts kMinVoxelsAcross voxels across the particles of `packing`;
    /// kMaxVoxels + 1 where no grid can.
    static int minimumVoxels(const Packing& packing);
    /// Throws VoxelResolutionError if M < minimumVoxels(packing) (the message gives both), or if
    /// a particle's circumdiameter exceeds L (it would overlap its own periodic image).
    static void checkResolution(const Packing& packing, int voxels);
    /// Upper bound of the memory compute() needs (bytes): one bit per voxel plus OpenVDB's
    /// per-leaf overhead, and the per-block candidate lists.
    static double memoryEstimateBytes(const Packing& packing, int voxels);

    /// The voxelization of `packing` on M^3 voxels whose solid voxels are given as row bits
    /// (grid/voxel_rows.hpp's layout: M x M rows (x, y) of ceil(M / 32) words, bit z & 31 of
    /// word z >> 5, as the GPU voxeliser makes them): the tree compute() would build from the
    /// same voxels, for the host's export (--vdb with --device cuda). Throws
    /// std::invalid_argument unless `rows` holds exactly those words.
    static Voxelization fromRowBits(std::span<const std::uint32_t> rows, const Packing& packing,
                                    int voxels, double runtimeSeconds);

    /// Parallel by output blocks (the 8^3 leaves of the tree): each block tests the voxels of
    /// the particles whose circumscribed sphere reaches it (candidate lists, O(voxels + N));
    /// voxels inside the inscribed sphere are solid without a test, only the shell up to the
    /// circumscribed sphere needs the shape's inside test. Fully solid blocks become tiles.
    Voxelization compute(const Packing& packing, const Progress& progress) const;

    /// The particle whose body holds each voxel centre, the same test as compute(): index
    /// (i * M + j) * M + k, value the particle's index + 1, 0 on void voxels (where two
    /// overlapping particles hold a centre, one of them). The whole grid only (4 bytes per
    /// voxel), for the set-Voronoi cells (voronoi/set_voronoi.hpp). Throws as compute(), and
    /// std::invalid_argument for a slab.
    std::vector<std::uint32_t> particleLabels(const Packing& packing,
                                              const Progress& progress) const;

    const VoxelizationParameters& parameters() const { return parameters_; }

  private:
    VoxelizationParameters parameters_;
};

} // namespace sbpack

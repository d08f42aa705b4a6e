#pragma once
// The voxels of the grid, row by row (paper Sec. III B; docs/design.md §5): which voxels a
// particle image reaches, and which of them lie inside it, one grid row (x, y) at a time as 32-bit
// words. Plain C++ of the host and the device alike: the CPU voxeliser (voxels/voxelization.cpp)
// takes its voxel ranges and row layout from here, the GPU voxeliser (gpu/cuda_kernels.cu) runs
// imageRow as one thread's work, and tests/analysis/test_grid_kernels.cpp runs that on the host
// against the CPU path (docs/gpu.md).

#include "geometry/norm_parts.hpp"

#include <cmath>
#include <cstdint>

namespace sbpack::grid {

/// Voxels [first, last] along one axis (empty when first > last).
struct IndexRange {
    int first, last;
};

/// Voxels whose centres (i + 1/2) a lie within `radius` of c, clipped to [first, last]: the CPU
/// voxeliser's rule (voxels/voxelization.cpp), shared.
SBPACK_HD inline IndexRange voxelRange(double c, double radius, double a, int first, int last) {
    const double lo = std::ceil((c - radius) / a - 0.5);
    const double hi = std::floor((c + radius) / a - 0.5);
    return {static_cast<int>(lo > first ? lo : first), static_cast<int>(hi < last ? hi : last)};
}

/// 32-bit words per grid row along z: bit z & 31 of word z >> 5 is voxel z.
SBPACK_HD inline int wordsPerRow(int voxels) {
    return (voxels + 31) / 32;
}

/// One periodic image of a particle: its centre (lab frame, possibly outside [0, L)) and the
/// lab-to-body rotation R^T, row-major.
struct ParticleImage {
    double centre[3];
    double toBody[9];
};

/// The grid and the shape: M voxels of edge a per side, the circumscribed radius with the CPU's
/// margin, the semi-axis and p.
struct VoxelGeometry {
    int voxels;
    double a;
    double rc;
    double semiAxis, p;
};

/// The rows (x, y) that an image's circumscribed sphere reaches, numbered 0 .. count() - 1.
struct ImageRows {
    IndexRange x, y;
    SBPACK_HD int count() const {
        return x.first > x.last || y.first > y.last
                   ? 0
                   : (x.last - x.first + 1) * (y.last - y.first + 1);
    }
    SBPACK_HD int xOf(int r) const { return x.first + r / (y.last - y.first + 1); }
    SBPACK_HD int yOf(int r) const { return y.first + r % (y.last - y.first + 1); }
};

SBPACK_HD inline ImageRows imageRows(const ParticleImage& image, const VoxelGeometry& g) {
    return {voxelRange(image.centre[0], g.rc, g.a, 0, g.voxels - 1),
            voxelRange(image.centre[1], g.rc, g.a, 0, g.voxels - 1)};
}

/// The solid voxels that `image` puts on row (x, y): every z whose voxel centre lies inside it
/// (norm::insideSuperball, the CPU's test, on R^T (centre - c) in the CPU's order of operations),
/// passed to emit(word, bits) one 32-bit word at a time. The caller ORs the words together.
template <class Emit>
SBPACK_HD void imageRow(const ParticleImage& image, int x, int y, const VoxelGeometry& g,
                        Emit&& emit) {
    const double dx = (x + 0.5) * g.a - image.centre[0];
    const double dy = (y + 0.5) * g.a - image.centre[1];
    const double rxy2 = dx * dx + dy * dy;
    const double rc2 = g.rc * g.rc;
    if (rxy2 >= rc2) return;
    const IndexRange z = voxelRange(image.centre[2], std::sqrt(rc2 - rxy2), g.a, 0, g.voxels - 1);
    const double* r = image.toBody;
    const std::int64_t row = (std::int64_t{x} * g.voxels + y) * wordsPerRow(g.voxels);
    std::uint32_t bits = 0;
    int word = z.first >> 5;
    for (int k = z.first; k <= z.last; ++k) {
        if ((k >> 5) != word) {
            if (bits != 0) emit(row + word, bits);
            bits = 0;
            word = k >> 5;
        }
        const double dz = (k + 0.5) * g.a - image.centre[2];
        const double body[3] = {r[0] * dx + r[1] * dy + r[2] * dz,
                                r[3] * dx + r[4] * dy + r[5] * dz,
                                r[6] * dx + r[7] * dy + r[8] * dz};
        if (norm::insideSuperball(body, g.semiAxis, g.p)) bits |= std::uint32_t{1} << (k & 31);
    }
    if (bits != 0) emit(row + word, bits);
}

} // namespace sbpack::grid

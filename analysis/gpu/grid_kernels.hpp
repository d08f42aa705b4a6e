#pragma once
// The per-thread work of the GPU grid analysis (docs/gpu.md), in plain C++ that both nvcc (the
// kernels of cuda_kernels.cu) and the host compiler (the tests, tests/analysis/
// test_grid_kernels.cpp, which run every function here against the CPU path) compile: the
// voxels of one particle image along one grid row, the first distance pass along a bit row, and
// the exact periodic min-plus transform at one voxel of a line (paper Sec. III B; docs/design.md
// §5).

#include "geometry/norm_parts.hpp"

#include <cmath>
#include <cstdint>

namespace sbpack::gpu {

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

/// Signed wave index of DFT index k of an M-periodic transform: k for k <= M/2, else k - M (the
/// CPU's shell sums and spectra, the GPU's gather and sums, the compact cube of period 2s + 1).
SBPACK_HD inline int signedIndex(int k, int m) {
    return 2 * k <= m ? k : k - m;
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

/// "No site": a void voxel before the first pass, or a line without solid.
inline constexpr std::uint32_t kNoSite = 0xffffffffu;

/// First pass: the squared 1-D periodic distance from each voxel of a bit row (wordsPerRow(M)
/// words) to the nearest solid voxel of the row, into out[0, M); kNoSite on a row without solid.
/// Forward from the first solid voxel once around (distance to the previous solid), then
/// backward from the last (to the next); the smaller is the minimum image.
SBPACK_HD inline void rowDistances(const std::uint32_t* words, int m, std::uint32_t* out) {
    auto solid = [words](int z) { return ((words[z >> 5] >> (z & 31)) & 1u) != 0; };
    int first = 0;
    while (first < m && !solid(first))
        ++first;
    if (first == m) {
        for (int z = 0; z < m; ++z)
            out[z] = kNoSite;
        return;
    }
    std::uint32_t d = 0;
    for (int step = 0, z = first; step < m; ++step, z = z + 1 == m ? 0 : z + 1) {
        d = solid(z) ? 0u : d + 1;
        out[z] = d;
    }
    int last = m - 1;
    while (!solid(last))
        --last;
    d = 0;
    for (int step = 0, z = last; step < m; ++step, z = z == 0 ? m - 1 : z - 1) {
        d = solid(z) ? 0u : d + 1;
        const std::uint32_t best = d < out[z] ? d : out[z];
        out[z] = best * best;
    }
}

/// The exact periodic min-plus transform of a line at voxel p, by search:
///   out(p) = min_q [ f(q) + (min-image |p - q|)^2 ],  q in [0, M),  f = kNoSite: no site,
/// f read at f[q * stride]. q = p, p +- 1, p +- 2, ... (minimum images, k <= M/2) until k^2
/// reaches the best value so far: every farther q adds at least k^2, so the result is the exact
/// minimum, the CPU's (pores/distance_transform.cpp). A voxel takes about sqrt(out(p)) + 1 steps
/// (none on a solid voxel, where f(p) = 0), at most M/2 + 1 where its plane has no solid; one
/// thread per voxel, neighbours along z side by side (docs/gpu.md, "The search passes").
SBPACK_HD inline std::uint32_t searchedMinimum(const std::uint32_t* f, std::int64_t stride, int m,
                                               int p) {
    std::uint64_t best = f[p * stride]; // kNoSite lies above every finite candidate
    for (std::int64_t k = 1; 2 * k <= m && static_cast<std::uint64_t>(k * k) < best; ++k) {
        const std::int64_t after = p + k >= m ? p + k - m : p + k;
        const std::int64_t before = p - k < 0 ? p - k + m : p - k;
        const auto k2 = static_cast<std::uint64_t>(k * k);
        const std::uint64_t a = f[after * stride], b = f[before * stride];
        if (a != kNoSite && a + k2 < best) best = a + k2;
        if (b != kNoSite && b + k2 < best) best = b + k2;
    }
    return static_cast<std::uint32_t>(best);
}

/// searchedMinimum at voxel i of the M^3 grid ((x M + y) M + z) along the axis whose voxels lie
/// `stride` apart (M: y, M^2: x): the work of one thread of the search passes.
SBPACK_HD inline std::uint32_t searchedMinimumAt(const std::uint32_t* f, std::int64_t i, int m,
                                                 std::int64_t stride) {
    const auto p = static_cast<int>((i / stride) % m);
    return searchedMinimum(f + (i - p * stride), stride, m, p);
}

} // namespace sbpack::gpu

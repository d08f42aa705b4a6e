#pragma once
// The per-thread work of the GPU grid analysis (docs/gpu.md), in plain C++ that both nvcc (the
// kernels of cuda_kernels.cu) and the host compiler (the tests, tests/analysis/
// test_grid_kernels.cpp, which run every function here against the CPU path) compile: the
// voxels of one particle image along one grid row, the first distance pass along a bit row, and
// the exact periodic min-plus transform of one line (paper Sec. III B; docs/design.md §5).

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

/// Scratch of one line's lower envelope, 2M + 1 entries `stride` apart (so that the threads of
/// a warp, lines side by side, touch adjacent words).
struct EnvelopeScratch {
    std::int32_t* site;           ///< position q' of each parabola, periodic images included
    std::uint32_t* value;         ///< f(q' mod M)
    std::int64_t* startNumerator; ///< the parabola is lowest for p > numerator / denominator
    std::int32_t* startDenominator;
    std::int64_t stride;
};

/// The exact periodic min-plus transform of one line (Felzenszwalb-Huttenlocher):
///   out(p) = min_q [ f(q) + (min-image |p - q|)^2 ],  p, q in [0, M),  f = kNoSite: no site,
/// f read at in[q * inStride], written at out[p * outStride]; in and out may be the same line
/// (the envelope is built from `in` before anything is written, and read from the scratch). The
/// images q' in [-M/2, M + M/2) enter as further parabolas (a minimum image lies within M/2);
/// breakpoints are exact rationals compared by integer cross-multiplication (|numerator| <
/// 3 M^2 + 1 < 2^30, denominator <= 4M for M <= maxPoreSizeVoxels), so the result is exact, as
/// the CPU's (pores/distance_transform.cpp).
SBPACK_HD inline void envelopeLine(const std::uint32_t* in, std::int64_t inStride, int m,
                                   std::uint32_t* out, std::int64_t outStride,
                                   const EnvelopeScratch& s) {
    const std::int64_t st = s.stride;
    const int h = m / 2;
    int top = -1;
    for (int qq = -h; qq < m + h; ++qq) {
        const int q = qq < 0 ? qq + m : (qq >= m ? qq - m : qq);
        const std::uint32_t fq = in[q * inStride];
        if (fq == kNoSite) continue;
        const std::int64_t height = fq + std::int64_t{qq} * qq;
        std::int64_t numerator = 0;
        std::int32_t denominator = 1;
        while (top >= 0) {
            const std::int64_t t = s.site[top * st];
            numerator = height - (s.value[top * st] + t * t);
            denominator = static_cast<std::int32_t>(2 * (qq - t));
            if (top == 0 ||
                numerator * s.startDenominator[top * st] > s.startNumerator[top * st] * denominator)
                break;
            --top;
        }
        ++top;
        s.site[top * st] = qq;
        s.value[top * st] = fq;
        s.startNumerator[top * st] = numerator;
        s.startDenominator[top * st] = denominator;
    }
    int k = 0;
    for (int p = 0; p < m; ++p) {
        if (top < 0) {
            out[p * outStride] = kNoSite;
            continue;
        }
        while (k < top &&
               s.startNumerator[(k + 1) * st] < std::int64_t{p} * s.startDenominator[(k + 1) * st])
            ++k;
        const std::int64_t d = p - std::int64_t{s.site[k * st]};
        out[p * outStride] = static_cast<std::uint32_t>(d * d + s.value[k * st]);
    }
}

} // namespace sbpack::gpu

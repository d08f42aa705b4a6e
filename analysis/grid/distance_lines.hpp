#pragma once
// The exact periodic squared distance to the nearest solid voxel along the grid's lines (paper
// Eq. 13's pore sizes; docs/design.md §5): the first pass along a bit row (grid/voxel_rows.hpp's
// words) and the min-plus transform at one voxel of a line by an outward search. Host and device
// alike: one thread's work of the GPU's distance transform (gpu/cuda_kernels.cu), run on the
// host by tests/analysis/test_grid_kernels.cpp against the CPU's (pores/distance_transform.cpp).

#include "geometry/norm_parts.hpp"

#include <cstdint>

namespace sbpack::grid {

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

} // namespace sbpack::grid

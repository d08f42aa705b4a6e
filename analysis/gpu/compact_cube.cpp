#include "gpu/compact_cube.hpp"

#include "grid/wave_index.hpp"

#include <cstdint>

namespace sbpack::gpu {

SpectrumSlab compactCubeSlab(const std::vector<double>& cube, int voxels, int s) {
    const int rows = 2 * s + 1;
    return {cube.data(), voxels, 0, rows, rows, s + 1};
}

PowerAt compactCubePower(const std::vector<double>& cube, int voxels, int s) {
    return [&cube, voxels, s](int kx, int ky, int kz) {
        const int r = 2 * s + 1, m = voxels;
        const std::int64_t ox = (grid::signedIndex(kx, m) + r) % r,
                           oy = (grid::signedIndex(ky, m) + r) % r;
        const double* c = cube.data() + ((ox * r + oy) * (s + 1) + kz) * 2;
        return c[0] * c[0] + c[1] * c[1];
    };
}

} // namespace sbpack::gpu

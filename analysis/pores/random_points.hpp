#pragma once
// Reproducible random points for the pore-size samplers: the K points are drawn in fixed chunks,
// each from its own stream of the seed (common/random), so results do not depend on the threads.

#include "random/random.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace sbpack {

/// Points per chunk of a random sample.
inline constexpr std::int64_t kRandomPointChunk = 1 << 14;

/// `points` independent uniformly random void voxels (squared[v] != 0) of the `total` voxels of
/// a grid whose void fraction is about `voidFraction`, in ascending index order (a voxel may
/// come twice, as independent draws may). Candidates are drawn in batches and read in index
/// order (the grid forward, not at random); where a batch holds more void voxels than are still
/// needed, a uniformly random subset of them is kept. Each kept voxel is thus a uniform draw from
/// the void, as when drawing again after every solid one (the paper's sampling, Sec. III B).
inline std::vector<std::int64_t> randomVoidVoxels(const std::uint32_t* squared, std::int64_t total,
                                                  double voidFraction, std::int64_t points,
                                                  Random& generator) {
    std::vector<std::int64_t> kept, batch;
    kept.reserve(static_cast<std::size_t>(points));
    const auto draw = [&](std::int64_t range) {
        return std::min(
            range - 1, static_cast<std::int64_t>(generator.uniform() * static_cast<double>(range)));
    };
    while (static_cast<std::int64_t>(kept.size()) < points) {
        const std::int64_t needed = points - static_cast<std::int64_t>(kept.size());
        batch.resize(static_cast<std::size_t>(
            std::ceil(1.1 * static_cast<double>(needed) / std::max(voidFraction, 1e-3)) + 64));
        for (std::int64_t& v : batch)
            v = draw(total);
        std::sort(batch.begin(), batch.end());
        std::erase_if(batch, [&](std::int64_t v) { return squared[v] == 0; });
        const auto voids = static_cast<std::int64_t>(batch.size());
        for (std::int64_t i = 0; i < std::min(needed, voids); ++i) // partial Fisher-Yates
            std::swap(batch[static_cast<std::size_t>(i)],
                      batch[static_cast<std::size_t>(i + draw(voids - i))]);
        batch.resize(static_cast<std::size_t>(std::min(needed, voids)));
        kept.insert(kept.end(), batch.begin(), batch.end());
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

} // namespace sbpack

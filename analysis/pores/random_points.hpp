#pragma once
// Reproducible random points for the pore-size samplers: the K points are drawn in fixed chunks,
// each from its own stream of the seed (common/random), so results do not depend on the threads.

#include "random/random.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

/// Points per chunk of a random sample.
inline constexpr std::int64_t kRandomPointChunk = 1 << 14;

/// Random void voxels are drawn among all voxels, about 1 / (void fraction) draws each; below
/// this void fraction (over 1000 draws a voxel, the exact sampler's limit) they are refused.
inline constexpr double kMinRandomVoidFraction = 1e-3;

/// Throws std::domain_error, naming --pore-points, when the void fraction of an M^3 grid is too
/// small for random void voxels (kMinRandomVoidFraction): every void voxel is then the sample.
inline void checkRandomVoidFraction(double voidFraction, int voxels) {
    if (voidFraction >= kMinRandomVoidFraction) return;
    throw std::domain_error(
        "pore sizes: --pore-points: the void is " + std::to_string(voidFraction) + " of the " +
        std::to_string(voxels) + "^3 voxels, below " + std::to_string(kMinRandomVoidFraction) +
        ": random void voxels would take over 1000 draws each; take every void voxel "
        "(--pore-points 0)");
}

/// `count` independent uniform draws from [0, range), in ascending order without a sort: the
/// order statistics of n uniforms are the partial sums of n + 1 exponential spacings divided by
/// their total (Devroye, Non-Uniform Random Variate Generation, 1986, Sec. V.2). Like
/// Random::normal, the draws depend on the C library's log (here log1p) to its last bit.
inline void ascendingUniformDraws(std::int64_t count, std::int64_t range, Random& generator,
                                  std::vector<std::int64_t>& out) {
    // The partial sums are kept in out's own storage (their bits) until the total is known.
    out.resize(static_cast<std::size_t>(count));
    double sum = 0.0;
    for (std::int64_t& slot : out) {
        sum -= std::log1p(-generator.uniform()); // Exp(1)
        slot = std::bit_cast<std::int64_t>(sum);
    }
    sum -= std::log1p(-generator.uniform());
    const double scale = static_cast<double>(range) / sum;
    for (std::int64_t& slot : out)
        slot = std::min(range - 1, static_cast<std::int64_t>(std::bit_cast<double>(slot) * scale));
}

/// `points` independent uniformly random void voxels (squared[v] != 0) of the `total` voxels of
/// a grid whose void fraction is about `voidFraction`, in ascending index order (a voxel may
/// come twice, as independent draws may). Candidates are drawn in ascending batches
/// (ascendingUniformDraws), so the grid is read forward, not at random; where a batch holds more
/// void voxels than are still needed, a uniformly random subset of them is kept, in order, by
/// selection sampling (Knuth, TAOCP vol. 2, Sec. 3.4.2, Algorithm S). Each kept voxel is thus a
/// uniform draw from the void, as when drawing again after every solid one (the paper's
/// sampling, Sec. III B).
inline std::vector<std::int64_t> randomVoidVoxels(const std::uint32_t* squared, std::int64_t total,
                                                  double voidFraction, std::int64_t points,
                                                  Random& generator) {
    std::vector<std::int64_t> kept, batch;
    kept.reserve(static_cast<std::size_t>(points));
    while (static_cast<std::int64_t>(kept.size()) < points) {
        const auto merged = static_cast<std::ptrdiff_t>(kept.size());
        std::int64_t needed = points - static_cast<std::int64_t>(kept.size());
        ascendingUniformDraws(
            static_cast<std::int64_t>(std::ceil(1.1 * static_cast<double>(needed) /
                                                std::max(voidFraction, kMinRandomVoidFraction))) +
                64,
            total, generator, batch);
        std::erase_if(batch, [&](std::int64_t v) { return squared[v] == 0; });
        for (std::size_t i = 0; i < batch.size() && needed > 0; ++i)
            if (static_cast<double>(batch.size() - i) * generator.uniform() <
                static_cast<double>(needed)) { // keep with probability needed / remaining
                kept.push_back(batch[i]);
                --needed;
            }
        std::inplace_merge(kept.begin(), kept.begin() + merged, kept.end());
    }
    return kept;
}

} // namespace sbpack

#pragma once
// Reproducible random points for the pore-size samplers: the K points are drawn in fixed chunks,
// each from its own generator seeded from (seed, chunk), so results do not depend on the threads.

#include <cstdint>
#include <random>

namespace sbpack {

/// Points per chunk of a random sample.
inline constexpr std::int64_t kRandomPointChunk = 1 << 14;

/// The generator of chunk `chunk` of a sample with seed `seed` (splitmix64 of both).
inline std::mt19937_64 chunkGenerator(std::uint64_t seed, std::int64_t chunk) {
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(chunk) + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return std::mt19937_64(z ^ (z >> 31));
}

/// Uniform in [0, 1) with 53 random bits, the same on every platform.
inline double uniform01(std::mt19937_64& generator) {
    return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

} // namespace sbpack

#pragma once
// Reproducible random points for the pore-size samplers: the K points are drawn in fixed chunks,
// each from its own stream of the seed (common/random), so results do not depend on the threads.

#include <cstdint>

namespace sbpack {

/// Points per chunk of a random sample.
inline constexpr std::int64_t kRandomPointChunk = 1 << 14;

} // namespace sbpack

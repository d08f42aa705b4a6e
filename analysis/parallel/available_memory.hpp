#pragma once
// The machine's available memory, the one reader of /proc/meminfo (the run's memory check,
// pipeline/resources, and the distance transform's refusal of grids that cannot fit).

#include <optional>

namespace sbpack {

/// MemAvailable of /proc/meminfo in bytes; nullopt where it cannot be read.
std::optional<double> availableMemoryBytes();

} // namespace sbpack

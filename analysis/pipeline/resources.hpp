#pragma once
// Memory a run will need, checked before anything is allocated (refused with the estimate).

#include "packing/packing.hpp"
#include "parallel/available_memory.hpp"
#include "pipeline/run_settings.hpp"

#include <optional>
#include <string>

namespace sbpack {

/// Peak memory (bytes) of the analyses of `settings` on one packing, itemised for messages.
struct MemoryEstimate {
    double bytes = 0.0;
    std::string breakdown; ///< e.g. "FFT grid 217 MB, voxel tree 9 MB"
    std::string options;   ///< the options that size them, e.g. "--voxels or --pore-voxels"
};
MemoryEstimate estimateMemory(const Packing& packing, const RunSettings& settings);

/// "217 MB", "1.3 GB" (decimal units).
std::string formatBytes(double bytes);

/// Throws std::invalid_argument, giving the estimate and what is available, when the estimate
/// exceeds the available memory (not checked where that is unknown). `source` names the input.
void checkMemory(const Packing& packing, const RunSettings& settings, const std::string& source);

} // namespace sbpack

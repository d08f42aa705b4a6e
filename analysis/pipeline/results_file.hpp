#pragma once
// The results file of sbanalyze (HDF5, docs/design.md §6; the README documents the layout).

#include "pipeline/ensemble.hpp"
#include "pipeline/file_analysis.hpp"
#include "pipeline/run_settings.hpp"

#include <filesystem>
#include <vector>

namespace sbpack {

inline constexpr const char* kResultsFormat = "sbpack.results";
inline constexpr std::int64_t kResultsFormatVersion = 1;

/// Everything one run produced.
struct RunResults {
    std::vector<FileResults> files;
    std::optional<EnsembleResults> ensemble; ///< with more than one file
    double runtimeSeconds = 0.0;
};

/// Writes `results` to `file` (a fresh file; the caller makes it atomic). One input: the
/// docs/design.md §6 layout at the root. Several: root attributes format, format_version, n_files
/// and the run's parameters; groups files/0, files/1, ... each with the §6 layout; and group
/// ensemble (see the README). Throws Hdf5Error.
void writeResultsFile(const std::filesystem::path& file, const RunResults& results,
                      const RunSettings& settings);

} // namespace sbpack

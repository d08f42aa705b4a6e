#pragma once
// FFTW planning and its wisdom file: plans measured once are remembered between runs
// (default $XDG_CACHE_HOME/sbpack/fftw-wisdom, else ~/.cache/sbpack/fftw-wisdom). A wisdom file
// that cannot be read or written is a warning, never an error.

#include "progress/progress.hpp"

#include <filesystem>
#include <string_view>

namespace sbpack {

/// How hard FFTW searches for a fast plan: FFTW_ESTIMATE, FFTW_MEASURE or FFTW_PATIENT.
enum class FftPlanning { Estimate, Measure, Patient };

/// Throws std::invalid_argument unless name is "estimate", "measure" or "patient".
FftPlanning fftPlanningFromName(std::string_view name);
std::string_view fftPlanningName(FftPlanning planning);

struct FftSettings {
    FftPlanning planning = FftPlanning::Measure;
    /// Wisdom file read before planning and rewritten after; empty: none.
    std::filesystem::path wisdomFile;
};

/// $XDG_CACHE_HOME/sbpack/fftw-wisdom, else $HOME/.cache/sbpack/fftw-wisdom; empty if neither
/// variable is set.
std::filesystem::path defaultWisdomFile();

/// Adds the wisdom of `file` to FFTW's (once per file and process); a missing file is silent,
/// an unreadable one a warning.
void importWisdom(const std::filesystem::path& file, const Progress& progress);
/// Writes FFTW's wisdom to `file` atomically, creating its directory; failures are warnings.
void exportWisdom(const std::filesystem::path& file, const Progress& progress);

} // namespace sbpack

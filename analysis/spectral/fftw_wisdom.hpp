#pragma once
// FFTW planning and its wisdom file: plans measured once are remembered between runs
// (default $XDG_CACHE_HOME/sbpack/fftw-wisdom, else ~/.cache/sbpack/fftw-wisdom). A wisdom file
// that cannot be read or written is a warning, never an error.

#include "progress/progress.hpp"

#include <filesystem>
#include <functional>
#include <limits>
#include <string_view>

namespace sbpack {

/// How hard FFTW searches for a fast plan: FFTW_ESTIMATE, FFTW_MEASURE or FFTW_PATIENT.
enum class FftPlanning { Estimate, Measure, Patient };

/// Throws std::invalid_argument unless name is "estimate", "measure" or "patient".
FftPlanning fftPlanningFromName(std::string_view name);
std::string_view fftPlanningName(FftPlanning planning);

/// The default of --fft-planning-budget, seconds (README, "No hidden first-run costs").
inline constexpr double kDefaultFftPlanningBudget = 2.0;

struct FftSettings {
    FftPlanning planning = FftPlanning::Measure;
    /// Wisdom file read before planning and rewritten after; empty: none.
    std::filesystem::path wisdomFile;
    /// Seconds that measure or patient planning may take when the wisdom has no plan: planning
    /// predicted to take longer (predictedPlanningSeconds) falls back on estimate, and measuring
    /// is cut off near the budget (fftw_set_timelimit, approximate). Infinite: no limit.
    double planningBudget = kDefaultFftPlanningBudget;
};

/// Where a plan came from.
enum class FftPlanSource {
    Estimate,       ///< --fft-plan estimate: no measuring, no wisdom
    Wisdom,         ///< the wisdom held a plan
    OverBudget,     ///< no wisdom, and measuring was predicted over the budget: estimate
    Measured,       ///< measured without a budget (no wisdom yet); kept as wisdom
    MeasuredBudget, ///< measured, cut off near the budget (no wisdom yet); kept as wisdom
};
std::string_view fftPlanSourceName(FftPlanSource source);

/// Predicted wall time of measure (or patient) planning of an M^3 real-to-complex transform
/// without wisdom: c n log2 n with n = M^3, c calibrated on the reference machine
/// (bench/RESULTS.md, "FFT planning": 20 s for a measured 300^3 plan on 2 threads), patient 10
/// times measure; 0 for estimate.
double predictedPlanningSeconds(int voxels, FftPlanning planning);

/// The one planning policy of sbanalyze's transforms, serial and distributed (issue 65 item 6:
/// --distribute grids measured past the budget). `plan(flags)` calls FFTW's planner of the
/// transform with those flags, keeps the plan and returns whether there is one. In order:
/// --fft-plan estimate; the wisdom's plan (FFTW_WISDOM_ONLY); measured without a budget; an
/// estimate plan where measuring is predicted over the budget (predictedPlanningSeconds);
/// else measured, with FFTW's time limit at the budget as a backstop where `collective` is
/// false (a collective MPI planner gets none: ranks cut off at different moments could choose
/// different plans). Returns where the plan came from; throws std::runtime_error where FFTW
/// returns no plan.
FftPlanSource planWithinBudget(int voxels, const FftSettings& fft, bool collective,
                               const std::function<bool(unsigned flags)>& plan);

/// $XDG_CACHE_HOME/sbpack/fftw-wisdom, else $HOME/.cache/sbpack/fftw-wisdom; empty if neither
/// variable is set.
std::filesystem::path defaultWisdomFile();

/// Adds the wisdom of `file` to FFTW's (once per file and process); a missing file is silent,
/// an unreadable one a warning.
void importWisdom(const std::filesystem::path& file, const Progress& progress);
/// Writes FFTW's wisdom to `file` atomically, creating its directory; failures are warnings.
void exportWisdom(const std::filesystem::path& file, const Progress& progress);

} // namespace sbpack

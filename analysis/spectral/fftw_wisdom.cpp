#include "spectral/fftw_wisdom.hpp"

#include "io/atomic_file.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>

namespace sbpack {

namespace fs = std::filesystem;

FftPlanning fftPlanningFromName(std::string_view name) {
    if (name == "estimate") return FftPlanning::Estimate;
    if (name == "measure") return FftPlanning::Measure;
    if (name == "patient") return FftPlanning::Patient;
    throw std::invalid_argument("FFT planning '" + std::string(name) +
                                "' is not one of estimate, measure, patient");
}

std::string_view fftPlanningName(FftPlanning planning) {
    switch (planning) {
    case FftPlanning::Estimate:
        return "estimate";
    case FftPlanning::Measure:
        return "measure";
    case FftPlanning::Patient:
        return "patient";
    }
    return "?";
}

std::string_view fftPlanSourceName(FftPlanSource source) {
    switch (source) {
    case FftPlanSource::Estimate:
        return "estimate";
    case FftPlanSource::Wisdom:
        return "wisdom";
    case FftPlanSource::OverBudget:
        return "estimate (measuring predicted over the budget)";
    case FftPlanSource::Measured:
        return "measured";
    case FftPlanSource::MeasuredBudget:
        return "measured within the budget";
    }
    return "?";
}

namespace {

unsigned plannerFlags(FftPlanning planning) {
    switch (planning) {
    case FftPlanning::Estimate:
        return FFTW_ESTIMATE;
    case FftPlanning::Measure:
        return FFTW_MEASURE;
    case FftPlanning::Patient:
        return FFTW_PATIENT;
    }
    return FFTW_ESTIMATE;
}

} // namespace

FftPlanSource planWithinBudget(int voxels, const FftSettings& fft, bool collective,
                               const std::function<bool(unsigned flags)>& plan) {
    const auto planned = [&](unsigned flags, FftPlanSource source) {
        if (!plan(flags))
            throw std::runtime_error("FFTW: cannot plan the " + std::to_string(voxels) +
                                     "^3 transform");
        return source;
    };
    const unsigned flags = plannerFlags(fft.planning);
    if (fft.planning == FftPlanning::Estimate) return planned(flags, FftPlanSource::Estimate);
    if (plan(flags | FFTW_WISDOM_ONLY)) return FftPlanSource::Wisdom;
    if (!std::isfinite(fft.planningBudget)) return planned(flags, FftPlanSource::Measured);
    if (predictedPlanningSeconds(voxels, fft.planning) > fft.planningBudget)
        return planned(FFTW_ESTIMATE, FftPlanSource::OverBudget);
    if (collective) return planned(flags, FftPlanSource::Measured);
    fftw_set_timelimit(std::max(fft.planningBudget, 0.0));
    try {
        planned(flags, FftPlanSource::MeasuredBudget);
    } catch (...) {
        fftw_set_timelimit(FFTW_NO_TIMELIMIT);
        throw;
    }
    fftw_set_timelimit(FFTW_NO_TIMELIMIT);
    return FftPlanSource::MeasuredBudget;
}

double predictedPlanningSeconds(int voxels, FftPlanning planning) {
    if (planning == FftPlanning::Estimate) return 0.0;
    // 20 s at n = 300^3 (bench/RESULTS.md, "FFT planning"): c = 20 / (n log2 n).
    constexpr double kSecondsPerPoint = 20.0 / (27e6 * 24.69);
    const double n = std::pow(static_cast<double>(voxels), 3);
    const double measure = kSecondsPerPoint * n * std::log2(std::max(n, 2.0));
    return planning == FftPlanning::Patient ? 10.0 * measure : measure;
}

fs::path defaultWisdomFile() {
    // The XDG Base Directory specification: a relative XDG_CACHE_HOME is invalid and ignored.
    if (const char* cache = std::getenv("XDG_CACHE_HOME");
        cache != nullptr && fs::path(cache).is_absolute())
        return fs::path(cache) / "sbpack" / "fftw-wisdom";
    if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
        return fs::path(home) / ".cache" / "sbpack" / "fftw-wisdom";
    return {};
}

void importWisdom(const fs::path& file, const Progress& progress) {
    static std::mutex mutex;
    static std::set<fs::path> imported;
    const std::lock_guard lock(mutex);
    if (file.empty() || imported.count(file) != 0) return;
    imported.insert(file);
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status)) return;    // first run: nothing remembered yet
    if (!fs::is_regular_file(status)) { // a FIFO would block the open (docs/reliability.md)
        progress.warn("FFTW wisdom '" + file.string() +
                      "' is not a regular file (a FIFO, device or directory): not read; planning "
                      "afresh");
        return;
    }
    if (fftw_import_wisdom_from_filename(file.c_str()) == 0)
        progress.warn("cannot read FFTW wisdom from '" + file.string() + "'; planning afresh");
}

void exportWisdom(const fs::path& file, const Progress& progress) {
    if (file.empty()) return;
    try {
        std::error_code ec;
        if (file.has_parent_path()) fs::create_directories(file.parent_path(), ec);
        AtomicOutput out(file);
        char* wisdom = fftw_export_wisdom_to_string();
        if (wisdom == nullptr) throw OutputPathError("FFTW could not export its wisdom");
        const std::string text(wisdom);
        fftw_free(wisdom);
        out.write(text);
        out.commit();
    } catch (const std::exception& e) {
        progress.warn(std::string("cannot store FFTW wisdom: ") + e.what());
    }
}

} // namespace sbpack

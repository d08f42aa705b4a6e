#include "progress/stage_log.hpp"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace sbpack {

void StageLog::stageDone(std::string_view stage, double seconds, std::string_view detail) const {
    if (log_ == nullptr) return;
    // One write per line: the ranks of an MPI run share standard error (docs/scale-out.md).
    std::ostringstream line;
    line << "sbanalyze: ";
    if (!context_.empty()) line << context_ << ": ";
    line << stage;
    if (!detail.empty()) line << ": " << detail;
    line << " (" << std::fixed << std::setprecision(3) << seconds << " s)\n";
    *log_ << line.str() << std::flush;
}

void StageLog::warn(std::string_view message) const {
    if (warnings_ == nullptr) return;
    std::ostringstream line;
    line << "sbanalyze: warning: ";
    if (!context_.empty()) line << context_ << ": ";
    line << message << '\n';
    *warnings_ << line.str() << std::flush;
}

} // namespace sbpack

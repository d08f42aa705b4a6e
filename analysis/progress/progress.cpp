#include "progress/progress.hpp"

#include <csignal>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

namespace sbpack {

namespace {

std::string interruptMessage(int signal) {
    const char* name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : nullptr;
    return std::string("interrupted") + (name != nullptr ? std::string(" by ") + name : "") +
           ": no output was written (earlier files at the output paths are kept)";
}

} // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(interruptMessage(signal)), signal_(signal) {}

Progress::Progress(std::ostream* log, std::ostream* warnings, const StopRequest& stop)
    : log_(log), warnings_(warnings), stop_(&stop) {}

void Progress::stageDone(std::string_view stage, double seconds, std::string_view detail) const {
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

void Progress::warn(std::string_view message) const {
    if (warnings_ == nullptr) return;
    std::ostringstream line;
    line << "sbanalyze: warning: ";
    if (!context_.empty()) line << context_ << ": ";
    line << message << '\n';
    *warnings_ << line.str() << std::flush;
}

void Progress::checkInterrupt() const {
    if (stop_->requested()) throw Interrupted(stop_->signal());
}

} // namespace sbpack

#include "progress/progress.hpp"

#include <atomic>
#include <csignal>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace sbpack {

namespace {

std::atomic<bool> interruptRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void onInterruptSignal(int) {
    interruptRequested.store(true, std::memory_order_relaxed);
}

} // namespace

void installInterruptHandler() {
    std::signal(SIGINT, onInterruptSignal);
    std::signal(SIGTERM, onInterruptSignal);
}

void requestInterrupt() {
    interruptRequested.store(true, std::memory_order_relaxed);
}

void clearInterrupt() {
    interruptRequested.store(false, std::memory_order_relaxed);
}

Progress::Progress(std::ostream* log, std::ostream* warnings) : log_(log), warnings_(warnings) {}

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
    if (interruptRequested.load(std::memory_order_relaxed)) throw Interrupted();
}

} // namespace sbpack

#include "progress/progress.hpp"

#include <atomic>
#include <csignal>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

namespace sbpack {

namespace {

/// -1: none requested; else the signal that asked (0: requestInterrupt() without one).
std::atomic<int> interruptRequested{-1};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void onInterruptSignal(int signal) {
    interruptRequested.store(signal, std::memory_order_relaxed);
}

std::string interruptMessage(int signal) {
    const char* name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : nullptr;
    return std::string("interrupted") + (name != nullptr ? std::string(" by ") + name : "") +
           ": no output was written (earlier files at the output paths are kept)";
}

} // namespace

void installInterruptHandler() {
    std::signal(SIGINT, onInterruptSignal);
    std::signal(SIGTERM, onInterruptSignal);
}

Interrupted::Interrupted(int signal)
    : std::runtime_error(interruptMessage(signal)), signal_(signal) {}

void requestInterrupt(int signal) {
    interruptRequested.store(signal, std::memory_order_relaxed);
}

void clearInterrupt() {
    interruptRequested.store(-1, std::memory_order_relaxed);
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
    const int signal = interruptRequested.load(std::memory_order_relaxed);
    if (signal >= 0) throw Interrupted(signal);
}

} // namespace sbpack

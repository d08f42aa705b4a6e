#include "progress/progress.hpp"

#include <atomic>
#include <csignal>
#include <iomanip>
#include <ostream>

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
    *log_ << "sbanalyze: ";
    if (!context_.empty()) *log_ << context_ << ": ";
    *log_ << stage;
    if (!detail.empty()) *log_ << ": " << detail;
    *log_ << " (" << std::fixed << std::setprecision(3) << seconds << " s)" << std::defaultfloat
          << std::endl;
}

void Progress::warn(std::string_view message) const {
    if (warnings_ == nullptr) return;
    *warnings_ << "sbanalyze: warning: ";
    if (!context_.empty()) *warnings_ << context_ << ": ";
    *warnings_ << message << std::endl;
}

void Progress::checkInterrupt() const {
    if (interruptRequested.load(std::memory_order_relaxed)) throw Interrupted();
}

} // namespace sbpack

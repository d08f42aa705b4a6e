#include "io/read_guard.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace sbpack {

namespace {

struct Limit {
    std::string program;
    double seconds = 0.0;
};

Limit& limit() {
    static Limit value;
    return value;
}

/// The fault message of the file being read, formatted beforehand: a signal handler may only
/// write(2) it.
char faultMessage[1024];
std::size_t faultLength = 0;

extern "C" void onReadFault(int) {
    (void)!::write(STDERR_FILENO, faultMessage, faultLength);
    ::_exit(EXIT_FAILURE);
}

} // namespace

struct ReadGuard::Watch {
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::thread thread;
    struct sigaction segv {
    }, bus{}; // the handlers before the guard
};

void armReadGuard(const std::string& program, double seconds) {
    if (const char* text = std::getenv("SBPACK_READ_DEADLINE_S")) {
        char* end = nullptr;
        errno = 0;
        seconds = std::strtod(text, &end);
        if (end == text || *end != '\0' || errno != 0 || !(seconds >= kFewestDeadlineSeconds) ||
            !(seconds <= kMostDeadlineSeconds))
            throw std::invalid_argument(
                "environment variable SBPACK_READ_DEADLINE_S='" + std::string(text) +
                "' is not a number of seconds in [" + std::to_string(kFewestDeadlineSeconds) +
                ", " + std::to_string(kMostDeadlineSeconds) + "] (unset it for the default)");
    }
    limit() = {program, seconds};
}

ReadGuard::ReadGuard(const std::filesystem::path& file) {
    const Limit armed = limit();
    if (!(armed.seconds > 0.0)) return;
    const std::string name = file.string();
    const int length = std::snprintf(faultMessage, sizeof faultMessage,
                                     "%s: error: '%s': the HDF5 library crashed reading it: the "
                                     "file is corrupt; nothing was written\n",
                                     armed.program.c_str(), name.c_str());
    faultLength = std::min(sizeof faultMessage - 1, static_cast<std::size_t>(std::max(length, 0)));
    watch_ = std::make_unique<Watch>();
    struct sigaction fault {};
    fault.sa_handler = onReadFault;
    sigemptyset(&fault.sa_mask);
    sigaction(SIGSEGV, &fault, &watch_->segv);
    sigaction(SIGBUS, &fault, &watch_->bus);
    watch_->thread = std::thread([watch = watch_.get(), armed, name] {
        std::unique_lock lock(watch->mutex);
        const auto wait = std::chrono::duration<double>(armed.seconds);
        if (watch->finished.wait_for(lock, wait, [watch] { return watch->done; })) return;
        std::fprintf(stderr,
                     "%s: error: '%s': reading did not finish within %g s: the file is corrupt "
                     "(a damaged HDF5 heap makes the HDF5 library loop); nothing was written\n",
                     armed.program.c_str(), name.c_str(), armed.seconds);
        std::fflush(stderr);
        std::_Exit(EXIT_FAILURE);
    });
}

ReadGuard::~ReadGuard() {
    if (watch_ == nullptr) return;
    {
        const std::lock_guard lock(watch_->mutex);
        watch_->done = true;
    }
    watch_->finished.notify_one();
    watch_->thread.join();
    sigaction(SIGSEGV, &watch_->segv, nullptr);
    sigaction(SIGBUS, &watch_->bus, nullptr);
}

} // namespace sbpack

#include "io/read_deadline.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace sbpack {

namespace {

struct Deadline {
    std::string program;
    double seconds = 0.0;
};

Deadline& deadline() {
    static Deadline value;
    return value;
}

} // namespace

struct ReadDeadline::Watch {
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::thread thread;
};

void armReadDeadline(const std::string& program, double seconds) {
    if (const char* text = std::getenv("SBPACK_READ_DEADLINE_S")) seconds = std::atof(text);
    deadline() = {program, seconds};
}

ReadDeadline::ReadDeadline(const std::filesystem::path& file) {
    const Deadline limit = deadline();
    if (!(limit.seconds > 0.0)) return;
    watch_ = new Watch;
    watch_->thread = std::thread([watch = watch_, limit, name = file.string()] {
        std::unique_lock lock(watch->mutex);
        const auto wait = std::chrono::duration<double>(limit.seconds);
        if (watch->finished.wait_for(lock, wait, [watch] { return watch->done; })) return;
        std::fprintf(stderr,
                     "%s: error: '%s': reading did not finish within %g s: the file is corrupt "
                     "(a damaged HDF5 heap makes the HDF5 library loop); nothing was written\n",
                     limit.program.c_str(), name.c_str(), limit.seconds);
        std::fflush(stderr);
        std::_Exit(EXIT_FAILURE);
    });
}

ReadDeadline::~ReadDeadline() {
    if (watch_ == nullptr) return;
    {
        const std::lock_guard lock(watch_->mutex);
        watch_->done = true;
    }
    watch_->finished.notify_one();
    watch_->thread.join();
    delete watch_;
}

} // namespace sbpack

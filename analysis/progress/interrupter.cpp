#include "progress/interrupter.hpp"

#include <csignal>
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

void Interrupter::checkInterrupt() const {
    if (stop_->requested()) throw Interrupted(stop_->signal());
}

} // namespace sbpack

#include "stop/stop_request.hpp"

#include <csignal>

namespace sbpack {

namespace {

constinit StopRequest processRequest;

extern "C" void onStopSignal(int signal) {
    processRequest.request(signal);
}

} // namespace

StopRequest& processStopRequest() noexcept {
    return processRequest;
}

void installStopHandler() {
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
}

} // namespace sbpack

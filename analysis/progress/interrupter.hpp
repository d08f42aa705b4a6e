#pragma once
// Cooperative interruption of long analyses (docs/design.md §7), as OpenVDB's interrupter: compute
// loops poll the stop request (common/stop) once per chunk and unwind when it was made.

#include "stop/stop_request.hpp"

#include <stdexcept>

namespace sbpack {

/// Thrown by Interrupter::checkInterrupt() once a stop was requested: `signal` is the SIGINT or
/// SIGTERM that asked (0 for a request without one).
class Interrupted : public std::runtime_error {
  public:
    explicit Interrupted(int signal);
    int signal() const { return signal_; }

  private:
    int signal_;
};

/// Polls `stop` (sbanalyze's: the process's, which SIGINT and SIGTERM make; Python's: one per
/// call; tests: their own). Thread-safe.
class Interrupter {
  public:
    explicit Interrupter(const StopRequest& stop = processStopRequest()) : stop_(&stop) {}

    /// Throws Interrupted if a stop was requested; call once per chunk of work.
    void checkInterrupt() const;

  private:
    const StopRequest* stop_;
};

} // namespace sbpack

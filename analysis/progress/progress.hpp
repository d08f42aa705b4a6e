#pragma once
// Stage reports and cooperative interruption of long analyses (docs/design.md §7): one line per
// finished stage, and the stop request (common/stop) that compute loops poll once per chunk (as
// OpenVDB's interrupter).

#include "stop/stop_request.hpp"

#include <chrono>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace sbpack {

/// Thrown by Progress::checkInterrupt() once a stop was requested: `signal` is the SIGINT or
/// SIGTERM that asked (0 for a request without one).
class Interrupted : public std::runtime_error {
  public:
    explicit Interrupted(int signal);
    int signal() const { return signal_; }

  private:
    int signal_;
};

/// Wall-clock seconds since construction.
class Stopwatch {
  public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

  private:
    std::chrono::steady_clock::time_point start_;
};

/// The execution context passed down every stage: where analyses report, and how they run.
/// Stage lines go to `log` (nullptr: quiet); warnings always go to `warnings` (nullptr: dropped);
/// `stop` is the request the stages poll (sbanalyze's: the process's, which SIGINT and SIGTERM
/// make; Python's: one per call). Thread-safe for checkInterrupt() only: report from the calling
/// thread.
class Progress {
  public:
    explicit Progress(std::ostream* log = nullptr, std::ostream* warnings = nullptr,
                      const StopRequest& stop = processStopRequest());

    /// Prefix of the following lines, e.g. "[2/5] packing.h5".
    void setContext(std::string context) { context_ = std::move(context); }
    /// "sbanalyze: <context>: <stage>: <detail> (<seconds> s)".
    void stageDone(std::string_view stage, double seconds, std::string_view detail = {}) const;
    /// "sbanalyze: warning: <context>: <message>".
    void warn(std::string_view message) const;
    /// Throws Interrupted if a stop was requested; call once per chunk of work.
    void checkInterrupt() const;

    /// Run the parallel loops (parallelFor, orderedReduce) in order on one thread; results equal
    /// the parallel ones (FFTW keeps the ThreadBudget's threads). Default false: tests set it to
    /// compare the two.
    void setSerial(bool serial) { serial_ = serial; }
    bool serial() const { return serial_; }

  private:
    std::ostream* log_;
    std::ostream* warnings_;
    const StopRequest* stop_;
    std::string context_;
    bool serial_ = false;
};

} // namespace sbpack

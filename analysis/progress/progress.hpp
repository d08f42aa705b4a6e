#pragma once
// Stage reports and cooperative interruption of long analyses (docs/design.md §7): one line per
// finished stage, and an interrupt flag that compute loops poll once per chunk (as OpenVDB's
// interrupter).

#include <chrono>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace sbpack {

/// Thrown by Progress::checkInterrupt() once an interrupt was requested: `signal` is the
/// SIGINT or SIGTERM that asked (0 for requestInterrupt() without one).
class Interrupted : public std::runtime_error {
  public:
    explicit Interrupted(int signal);
    int signal() const { return signal_; }

  private:
    int signal_;
};

/// Makes SIGINT and SIGTERM request an interrupt instead of killing the process, so that the
/// running stage stops at its next chunk and unwinds (no output file is left behind).
void installInterruptHandler();
/// What the signal handler does (with its signal); also usable from tests (signal 0).
void requestInterrupt(int signal = 0);
/// Clears a pending request (tests).
void clearInterrupt();

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
/// Stage lines go to `log` (nullptr: quiet); warnings always go to `warnings` (nullptr: dropped).
/// Thread-safe for checkInterrupt() only: report from the calling thread.
class Progress {
  public:
    explicit Progress(std::ostream* log = nullptr, std::ostream* warnings = nullptr);

    /// Prefix of the following lines, e.g. "[2/5] packing.h5".
    void setContext(std::string context) { context_ = std::move(context); }
    /// "sbanalyze: <context>: <stage>: <detail> (<seconds> s)".
    void stageDone(std::string_view stage, double seconds, std::string_view detail = {}) const;
    /// "sbanalyze: warning: <context>: <message>".
    void warn(std::string_view message) const;
    /// Throws Interrupted if an interrupt was requested; call once per chunk of work.
    void checkInterrupt() const;

    /// Run the parallel loops (parallelFor, orderedReduce) in order on one thread; results equal
    /// the parallel ones (FFTW keeps the ThreadBudget's threads). Default false: tests set it to
    /// compare the two.
    void setSerial(bool serial) { serial_ = serial; }
    bool serial() const { return serial_; }

  private:
    std::ostream* log_;
    std::ostream* warnings_;
    std::string context_;
    bool serial_ = false;
};

} // namespace sbpack

#pragma once
// One way to stop long work (docs/design.md §7): a request that a signal handler, Python's
// Ctrl-C watch or a test makes, and that the work polls at its safe points. The analysis stops
// at its next chunk (analysis/progress, Interrupter::checkInterrupt); sbgen at the end of its
// window on the first request, at its next event on a second (generator/protocol,
// JammingProtocol::run).

#include <atomic>

namespace sbpack {

class StopRequest {
  public:
    /// Asks the work to stop; `signal` the SIGINT or SIGTERM that asked (0: none).
    /// Async-signal-safe: lock-free atomics only.
    void request(int signal = 0) noexcept {
        signal_.store(signal, std::memory_order_relaxed);
        count_.fetch_add(1, std::memory_order_relaxed);
    }
    /// Whether a stop was asked.
    bool requested() const noexcept { return count_.load(std::memory_order_relaxed) > 0; }
    /// Whether it was asked twice or more: stop at once, not at the next safe point.
    bool repeated() const noexcept { return count_.load(std::memory_order_relaxed) > 1; }
    /// The signal of the last request (0: none).
    int signal() const noexcept { return signal_.load(std::memory_order_relaxed); }

  private:
    static_assert(std::atomic<int>::is_always_lock_free, "a signal handler requests");
    std::atomic<int> count_{0};
    std::atomic<int> signal_{0};
};

/// The process's request: what the handler of installStopHandler() makes, and what the work
/// polls unless it is given its own (Python gives each call one; tests theirs).
StopRequest& processStopRequest() noexcept;

/// SIGINT and SIGTERM make a request on processStopRequest() instead of ending the process.
void installStopHandler();

} // namespace sbpack

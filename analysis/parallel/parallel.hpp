#pragma once
// The one parallel-for of sbanalyze (docs/design.md §7): TBB over an index range, with a serial
// switch so that every parallel result can be compared with a serial one. Thread count is set once
// per run by ThreadBudget and honoured by TBB and by FFTW, whose threads are OpenMP's
// (libfftw3_omp), alike (no oversubscription).

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <memory>

namespace sbpack {

/// Calls body(begin, end) over consecutive chunks of [begin, end) of about `grain` indices each.
/// With serial = true the chunks run in order on the calling thread.
template <class Body>
void parallelFor(std::int64_t begin, std::int64_t end, std::int64_t grain, const Body& body,
                 bool serial = false) {
    if (end <= begin) return;
    if (grain < 1) grain = 1;
    if (serial) {
        for (std::int64_t b = begin; b < end; b += grain)
            body(b, std::min(end, b + grain));
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(begin, end, grain),
                      [&](const tbb::blocked_range<std::int64_t>& r) { body(r.begin(), r.end()); });
}

/// Caps every threading library at `threads` for its lifetime: TBB (global_control), FFTW
/// (fftw_plan_with_nthreads) and OpenMP (omp_set_num_threads). Create one per run, before any work.
class ThreadBudget {
  public:
    /// Throws std::invalid_argument when threads < 1 or above maxThreads().
    explicit ThreadBudget(int threads);
    ~ThreadBudget();
    ThreadBudget(const ThreadBudget&) = delete;
    ThreadBudget& operator=(const ThreadBudget&) = delete;

    int threads() const { return threads_; }
    /// Largest sensible request: 4 times the hardware threads (at least 1).
    static int maxThreads();

  private:
    int threads_;
    std::unique_ptr<struct ThreadBudgetState> state_;
};

} // namespace sbpack

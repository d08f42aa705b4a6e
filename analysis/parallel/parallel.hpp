#pragma once
// The one parallel-for of sbanalyze (docs/design.md §7): TBB over an index range, run in order on
// one thread when the execution context asks (LoopSchedule::serial), so that every parallel result
// can be compared with a serial one; and the one ordered reduce over it (partials per fixed
// chunk, combined in chunk order). Thread count is set once per run by ThreadBudget and honoured
// by TBB and by FFTW, whose threads are OpenMP's (libfftw3_omp), alike (no oversubscription).

#include "parallel/loop_schedule.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace sbpack {

/// Calls body(begin, end) over consecutive chunks of [begin, end) of about `grain` indices each.
/// With schedule.serial() the chunks run in order on the calling thread.
template <class Body>
void parallelFor(std::int64_t begin, std::int64_t end, std::int64_t grain, const Body& body,
                 const LoopSchedule& schedule = LoopSchedule()) {
    if (end <= begin) return;
    if (grain < 1) grain = 1;
    if (schedule.serial()) {
        for (std::int64_t b = begin; b < end; b += grain)
            body(b, std::min(end, b + grain));
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(begin, end, grain),
                      [&](const tbb::blocked_range<std::int64_t>& r) { body(r.begin(), r.end()); });
}

/// The ordered reduce of sbanalyze (docs/design.md §7): maps every chunk index of [0, chunks) to
/// a partial result, mapChunk(c) -> T, in parallel (over parallelFor), then folds the partials
/// into init in chunk order, combine(T& total, T&& partial), on the calling thread. The chunks
/// are the caller's, fixed, so the result does not depend on the threads and equals the serial
/// one (schedule.serial()) bit for bit. Interrupt polls and progress belong in mapChunk, once per
/// chunk. Every partial is kept until the fold: size the chunks for that.
template <class T, class Map, class Combine>
T orderedReduce(std::int64_t chunks, T init, const Map& mapChunk, const Combine& combine,
                const LoopSchedule& schedule = LoopSchedule()) {
    std::vector<std::optional<T>> partials(
        static_cast<std::size_t>(std::max<std::int64_t>(0, chunks)));
    parallelFor(
        0, chunks, 1,
        [&](std::int64_t begin, std::int64_t end) {
            for (std::int64_t c = begin; c < end; ++c)
                partials[c].emplace(mapChunk(c));
        },
        schedule);
    for (std::optional<T>& partial : partials)
        combine(init, std::move(*partial));
    return init;
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

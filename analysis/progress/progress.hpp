#pragma once
// The execution context passed down every stage and compute object (docs/design.md §7), made of
// three parts with one job each: where it reports (StageLog), the stop request it polls
// (Interrupter, as OpenVDB's) and how its parallel loops run (LoopSchedule). A function that
// needs one part takes that part (parallelFor takes the LoopSchedule); a Progress is each.

#include "parallel/loop_schedule.hpp"
#include "progress/interrupter.hpp"
#include "progress/stage_log.hpp"

#include <chrono>

namespace sbpack {

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

/// Stage lines to `log`, warnings to `warnings` (StageLog), the stop request `stop`
/// (Interrupter), the loops parallel until setSerial (LoopSchedule).
class Progress : public StageLog, public Interrupter, public LoopSchedule {
  public:
    explicit Progress(std::ostream* log = nullptr, std::ostream* warnings = nullptr,
                      const StopRequest& stop = processStopRequest())
        : StageLog(log, warnings), Interrupter(stop) {}
};

} // namespace sbpack

#pragma once
// How the parallel loops of a run go (parallel/parallel.hpp, docs/design.md §7): on TBB's
// threads, or in order on the calling thread, so that every parallel result can be compared with
// a serial one.

namespace sbpack {

/// Run the parallel loops (parallelFor, orderedReduce) in order on one thread; results equal the
/// parallel ones (FFTW keeps the ThreadBudget's threads). Default false: tests set it to compare
/// the two.
class LoopSchedule {
  public:
    void setSerial(bool serial) { serial_ = serial; }
    bool serial() const { return serial_; }

  private:
    bool serial_ = false;
};

} // namespace sbpack

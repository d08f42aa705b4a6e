#pragma once
// Where a run reports (docs/design.md §7): one line per finished stage, and warnings, each after
// the name of what is being analysed.

#include <iosfwd>
#include <string>
#include <string_view>
#include <utility>

namespace sbpack {

/// Stage lines go to `log` (nullptr: quiet), warnings to `warnings` (nullptr: dropped). Report
/// from the calling thread.
class StageLog {
  public:
    explicit StageLog(std::ostream* log = nullptr, std::ostream* warnings = nullptr)
        : log_(log), warnings_(warnings) {}

    /// Prefix of the following lines, e.g. "[2/5] packing.h5".
    void setContext(std::string context) { context_ = std::move(context); }
    /// "sbanalyze: <context>: <stage>: <detail> (<seconds> s)".
    void stageDone(std::string_view stage, double seconds, std::string_view detail = {}) const;
    /// "sbanalyze: warning: <context>: <message>".
    void warn(std::string_view message) const;

  private:
    std::ostream* log_;
    std::ostream* warnings_;
    std::string context_;
};

} // namespace sbpack

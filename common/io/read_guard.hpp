#pragma once
// A guard on reading one input file, for the command-line programs (docs/reliability.md,
// "Inputs"). libhdf5 itself can loop forever or crash on a damaged file (a corrupt global heap
// under H5Aread: both found by the fuzz target, tests/fuzz/regressions/). No library call can be
// interrupted or recovered from safely, so a program that armed the guard ends with an error
// naming the file and exit status 1 when reading takes longer than its deadline or faults
// (SIGSEGV, SIGBUS). Inputs are read before any output is opened, so nothing is lost.
// Libraries and the Python module leave it unarmed.

#include <filesystem>
#include <memory>
#include <string>

namespace sbpack {

/// Deadlines SBPACK_READ_DEADLINE_S may set (seconds): a longer one would overflow the clock.
inline constexpr double kFewestDeadlineSeconds = 0.1;
inline constexpr double kMostDeadlineSeconds = 1e6;

/// Arms the guard for every later ReadGuard: `program` names the messages; a deadline of
/// `seconds` <= 0 disarms it. The environment variable SBPACK_READ_DEADLINE_S overrides it:
/// std::invalid_argument naming it unless it is a number in [kFewestDeadlineSeconds,
/// kMostDeadlineSeconds].
void armReadGuard(const std::string& program, double seconds);

/// While alive, reading `file` must finish before the armed deadline and must not fault.
class ReadGuard {
  public:
    explicit ReadGuard(const std::filesystem::path& file);
    ~ReadGuard();
    ReadGuard(const ReadGuard&) = delete;
    ReadGuard& operator=(const ReadGuard&) = delete;

  private:
    struct Watch;
    std::unique_ptr<Watch> watch_; ///< none when unarmed
};

} // namespace sbpack

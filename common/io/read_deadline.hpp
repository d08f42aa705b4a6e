#pragma once
// A deadline on reading one input file, for the command-line programs (docs/reliability.md,
// "Inputs"). A damaged HDF5 heap can make libhdf5 itself loop forever inside H5Aread (found by
// the fuzz target, tests/fuzz/regressions/); no library call can be interrupted safely, so a
// program that armed the deadline prints an error naming the file and exits with status 1.
// Inputs are read before any output is opened, so nothing is lost. Libraries and the Python
// module leave it unarmed.

#include <filesystem>
#include <string>

namespace sbpack {

/// Arms the deadline for every later ReadDeadline: `program` names the messages; `seconds`
/// <= 0 disarms. The environment variable SBPACK_READ_DEADLINE_S overrides `seconds`.
void armReadDeadline(const std::string& program, double seconds);

/// While alive, reading `file` must finish before the armed deadline.
class ReadDeadline {
  public:
    explicit ReadDeadline(const std::filesystem::path& file);
    ~ReadDeadline();
    ReadDeadline(const ReadDeadline&) = delete;
    ReadDeadline& operator=(const ReadDeadline&) = delete;

  private:
    struct Watch;
    Watch* watch_ = nullptr;
};

} // namespace sbpack

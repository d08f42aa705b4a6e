#pragma once
// sbanalyze's command line (CLI11): the analysis options on the main command and the
// subcommands info, convert and schema, each option defined once, each command with its --help.

#include "parallel/communicator.hpp"
#include "pipeline/run_settings.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace sbpack {

/// Parses argv and runs the command; prints errors as "sbanalyze: error: ..." on `err` and
/// returns the exit status (0 for --help and --version). The analysis runs on the ranks of
/// `communicator` (docs/scale-out.md); every rank calls this alike.
int runCommandLine(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                   const Communicator& communicator = SerialCommunicator());

/// The settings of the analysis command (`sbanalyze FILE... [options]`, without the program
/// name). Throws std::invalid_argument naming the option and what is wrong with its value.
RunSettings parseAnalyzeArguments(const std::vector<std::string>& args);

/// The main --help text.
std::string usage();

} // namespace sbpack

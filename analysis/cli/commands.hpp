#pragma once
// The command line of sbanalyze: its usage text and one function per command.

#include "pipeline/run_settings.hpp"

#include <string>
#include <vector>

namespace sbpack {

/// The full --help text.
std::string usage();

/// Parses the arguments of the analysis command (`sbanalyze FILE... [options]`). Throws
/// std::invalid_argument naming the option and what is wrong with its value.
RunSettings parseAnalyzeArguments(const std::vector<std::string>& args);

/// Each returns the exit status; bad arguments throw std::invalid_argument.
int analyzeCommand(const std::vector<std::string>& args);
int infoCommand(const std::vector<std::string>& args);
int convertCommand(const std::vector<std::string>& args);

} // namespace sbpack

#pragma once
// What sbanalyze's commands do once their command line is parsed (cli/command_line.hpp).

#include "contacts/contact_network.hpp"
#include "parallel/communicator.hpp"
#include "pipeline/run_settings.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace sbpack {

/// Each returns the exit status; bad input throws std::invalid_argument (or the reader's error)
/// naming the file and the problem.
int analyzeCommand(const RunSettings& settings, const Communicator& communicator);
/// Reports every file; a bad one is an error line on `err`, and the status is then 1. Given
/// `jamming`, the report adds the jamming categories (info --jamming).
int infoCommand(const std::vector<std::string>& files, const ContactParameters& parameters,
                const JammingSettings* jamming, std::ostream& out, std::ostream& err);
int convertCommand(const std::string& input, const std::string& output, std::ostream& err);
/// The results schema as Markdown (docs/results-schema.md) or, with `json`, as JSON; with
/// `packing`, the packing file's (docs/packing-schema.md).
int schemaCommand(bool json, bool packing, std::ostream& out);

} // namespace sbpack

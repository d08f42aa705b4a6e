#pragma once
// One sbanalyze run: validate everything first, analyse each file, then write the results
// file, the JSON summary and the .vdb exports, all committed together at the end (a failure
// anywhere leaves no output file).

#include "pipeline/results_file.hpp"
#include "pipeline/run_settings.hpp"

#include <iosfwd>

namespace sbpack {

/// Runs `settings`. Stage lines go to `log` unless settings.quiet; warnings always do; a JSON
/// summary requested as "-" goes to `out`. Throws on bad input (before any analysis starts:
/// threads, output paths, unreadable or invalid packings, grids too coarse, memory) and on
/// failures, naming the file and the problem.
RunResults runAnalyses(const RunSettings& settings, std::ostream& log, std::ostream& out);

} // namespace sbpack

#pragma once
// The short JSON summary of a run (--json): the results file's attributes under the same names
// (docs/results-schema.md), per file and per ensemble, plus each curve's number of shells and
// principal peak. Datasets (curves, per-particle values) are in the results file only.

#include "pipeline/results_file.hpp"

#include <iosfwd>

namespace sbpack {

void writeJsonSummary(std::ostream& out, const RunResults& results, const RunSettings& settings);

} // namespace sbpack

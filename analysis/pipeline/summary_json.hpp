#pragma once
// The short JSON summary of a run (--json): per file the scalars and the main peak of each curve,
// the ensemble's scalars, and the runtimes. Curves are in the results file only.

#include "pipeline/results_file.hpp"

#include <iosfwd>

namespace sbpack {

void writeJsonSummary(std::ostream& out, const RunResults& results, const RunSettings& settings);

} // namespace sbpack

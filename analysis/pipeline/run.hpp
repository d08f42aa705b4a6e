#pragma once
// One sbanalyze run: validate everything first, analyse each file, then write the results
// file, the JSON summary and the .vdb exports, all committed together at the end (a failure
// anywhere leaves no output file).

#include "pipeline/results_file.hpp"
#include "pipeline/run_settings.hpp"

#include "packing/packing.hpp"
#include "parallel/communicator.hpp"
#include "stop/stop_request.hpp"

#include <filesystem>
#include <iosfwd>

namespace sbpack {

/// The checks a packing passes before its analyses start (each grid puts at least 4 voxels across
/// a particle; the memory the run needs is available); std::invalid_argument naming `input` and
/// the option. runAnalyses makes them for every input; the Python module (python/) for its own.
void checkPackingForRun(const Packing& packing, const RunSettings& settings,
                        const std::filesystem::path& input);

/// Runs `settings`. Stage lines go to `log` unless settings.quiet; warnings always do; a JSON
/// summary requested as "-" goes to `out`. Throws on bad input (before any analysis starts:
/// threads, output paths, unreadable or invalid packings, grids too coarse, memory) and on
/// failures, naming the file and the problem. `stop`: the request its stages poll (Interrupted
/// once made).
RunResults runAnalyses(const RunSettings& settings, std::ostream& log, std::ostream& out,
                       const StopRequest& stop = processStopRequest());

/// The same on the ranks of `comm` (docs/scale-out.md), every rank calling it: --distribute files
/// shares the inputs out round robin, --distribute grids analyses each input on all ranks
/// together (comm.grids()). Errors are agreed on collectively (CollectiveError on every rank,
/// naming the file), rank 0 gathers the per-file records in input order, runs the ensemble
/// reducer and writes the outputs; its RunResults hold them (the other ranks' hold none).
/// With settings.plan nothing runs: rank 0 prints the plan (pipeline/scale_plan.hpp) to `out`.
RunResults runAnalyses(const RunSettings& settings, std::ostream& log, std::ostream& out,
                       const Communicator& comm, const StopRequest& stop = processStopRequest());

} // namespace sbpack

#pragma once
// The results file of sbanalyze (HDF5; layout and names in docs/results-schema.md, generated
// from the schema's tables: schema/field_table.hpp).

#include "pipeline/ensemble.hpp"
#include "pipeline/file_analysis.hpp"
#include "pipeline/run_settings.hpp"
#include "schema/record.hpp"

#include <filesystem>
#include <vector>

namespace sbpack {

/// Everything one run produced.
struct RunResults {
    std::vector<FileResults> files;
    std::vector<EnsembleResults> ensembles; ///< one per (p, N) of the files
    double runtimeSeconds = 0.0;
    int ranks = 1; ///< MPI processes of the run
};

/// The run's own attributes (the root of the results file).
schema::Record runRecord(const RunResults& results, const RunSettings& settings);

/// The bytes of the results file of `results` (built in memory; the caller writes them through
/// AtomicOutput): the run's attributes at the root, files/<i> and ensembles/<k> as in
/// docs/results-schema.md, every dataset with its `units` attribute and every numeric attribute
/// NAME with NAME_units. `name` is for messages. Throws Hdf5Error.
std::string resultsFileImage(const std::string& name, const RunResults& results,
                             const RunSettings& settings);

} // namespace sbpack

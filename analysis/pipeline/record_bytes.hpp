#pragma once
// The per-file results as bytes, for the MPI gather to rank 0 (docs/scale-out.md): every entry
// of every record by its schema name, numbers as their exact bit patterns, so that the records
// rank 0 decodes equal those the analysing rank filled, and the ensemble reducer
// (pipeline/ensemble.cpp) gives the single-process result bit for bit.

#include "pipeline/file_analysis.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace sbpack {

/// Files with their index in the run's input order.
using IndexedFiles = std::vector<std::pair<std::size_t, FileResults>>;

std::string encodeFiles(const IndexedFiles& files);
/// Throws std::logic_error on bytes encodeFiles did not write (a group or name the schema does
/// not declare, a truncated buffer).
IndexedFiles decodeFiles(const std::string& bytes);

} // namespace sbpack

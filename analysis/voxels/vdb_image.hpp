#pragma once
// The one .vdb writer of sbanalyze (--vdb): every grid it exports carries the same metadata,
// box_length (the packing's length unit), voxels (M, int64) and units (what a value means), and
// is serialised in memory, to be written through AtomicOutput (docs/reliability.md).

#include <openvdb/openvdb.h>

#include <string>

namespace sbpack {

/// Adds the common metadata to `grid` and returns the bytes of a .vdb file holding it.
std::string vdbImage(const openvdb::GridBase::Ptr& grid, double boxLength, int voxels,
                     const std::string& units);

} // namespace sbpack

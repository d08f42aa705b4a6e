#pragma once
// The one .vdb writer of sbanalyze (--vdb): every grid it exports carries the same metadata,
// box_length, voxels (M, int64), units (what a value means) and length_unit, and is serialised in
// memory, to be written through AtomicOutput (docs/reliability.md). A grid is in the unit the
// analyses computed in (Packing::analysisLengthUnit, a power of two: 1 where 1 <= D < 2):
// its transform, box_length and lengths times length_unit are the packing's lengths, so that
// grids of packings in any units are within OpenVDB's range of scales.

#include <openvdb/openvdb.h>

#include <string>

namespace sbpack {

/// Adds the common metadata to `grid` and returns the bytes of a .vdb file holding it;
/// `boxLength` and the grid in units of `lengthUnit`, the packing's length.
std::string vdbImage(const openvdb::GridBase::Ptr& grid, double boxLength, int voxels,
                     const std::string& units, double lengthUnit);

} // namespace sbpack

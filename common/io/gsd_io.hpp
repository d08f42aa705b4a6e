#pragma once
// GSD (HOOMD-blue's binary format, read by HOOMD, freud, gsd.hoomd and OVITO) in and out, by the
// reference C library vendored in common/third_party/gsd (BSD-2-Clause, gsd 5.0.1); docs/formats.md
// ("GSD").

#include "packing/packing.hpp"

#include <filesystem>

namespace sbpack {

/// Writes one frame of the HOOMD schema 1.4 (what HOOMD 4, gsd 4 and OVITO read): the cubic box
/// (configuration/box), particles/N, one type "superball" whose particles/type_shapes is a
/// ConvexPolyhedron of points on the superball's surface (OVITO draws their hull),
/// particles/position in [-L/2, L/2) and particles/orientation (w, x, y, z) in single precision
/// as the schema has them, and, so that nothing is lost, the double-precision copies
/// log/particles/sbpack/position (in [0, L), sbpack's convention) and .../orientation with the
/// scalars log/sbpack/p, semi_axis, box_length and, where the packing has them,
/// reduced_pressure and seed. Atomic (io/atomic_file.hpp). Throws OutputPathError, or
/// PackingFileError where the library fails.
void writeGsd(const Packing& packing, const std::filesystem::path& file);

/// Reads the last frame of a GSD file (chunks missing there from frame 0, as the schema says):
/// sbpack's double-precision copies where present (the file round-trips exactly), else the
/// schema's single-precision position (shifted into [0, L)) and orientation (identity where
/// absent), the shape from log/sbpack/p and semi_axis, or, for a file from elsewhere, a Sphere
/// type_shape of one type (p = 1, a = diameter / 2). Throws PackingFileError naming the file for
/// a file the library cannot open, a box that is not cubic, missing positions or shape, chunks
/// of the wrong size or type, or particles of more than one type with differing shapes.
Packing readGsd(const std::filesystem::path& file);

} // namespace sbpack

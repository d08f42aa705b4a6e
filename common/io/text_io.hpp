#pragma once
// Plain-text import/export of packings and an extended-XYZ export for OVITO (docs/design.md §4
// conventions: quaternions (w, x, y, z) body to lab, positions in [0, L)).

#include "io/packing_io.hpp"
#include "packing/packing.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sbpack {

/// Writes the text format, atomically:
///   # sbpack text packing v1
///   # p 1.5
///   # semi_axis 0.5
///   # box_length 10
///   # n_particles N
///   # reduced_pressure 1e+12     (where the packing has one)
///   # seed 1                     (likewise)
///   # columns x y z qw qx qy qz
/// then one particle per line at full precision (17 significant digits). Velocities and
/// provenance are not part of the text format (io/packing_formats.hpp, notCarriedBy). The reduced
/// pressure sets the jam check's contact tolerance, so a packing keeps its contact numbers through
/// the text format.
void writeTextPacking(const Packing& packing, const std::filesystem::path& file);

/// Reads the text format. Other comment lines and blank lines are ignored. Throws
/// PackingFileError (naming the file and line) for a malformed line, a missing or repeated
/// header key, or a wrong particle count, and InvalidPacking for invalid contents; normalises
/// the quaternions and wraps positions into [0, L).
Packing readTextPacking(const std::filesystem::path& file);

/// Reads one frame of extended XYZ (sbpack's export; the same columns in other spellings, as
/// OVITO names them): the particle
/// count, a comment line of key=value pairs (keys in any case, values "quoted" where they hold
/// blanks) with a cubic Lattice and Properties (pos required; orientation as OVITO's
/// (x, y, z, w); aspherical_shape and superquadric_roundness (OVITO: SuperquadricRoundness), or
/// the keys semi_axis and p, give the shape: roundness 1 / p, equal semi-axes; a p within 1e-7
/// of one of 6 significant digits is that one, as a single-precision roundness rounds it), then
/// one line per particle. Throws
/// PackingFileError naming the file and line for a non-cubic cell, a missing column or key, a
/// wrong count, particles of differing shapes, or superballs without orientations; normalises
/// the quaternions and wraps positions into [0, L).
Packing readExtendedXyz(const std::filesystem::path& file);

/// Writes an extended-XYZ file that OVITO opens with the periodic cell, orientations and
/// superquadric shapes (Properties species, pos, orientation, aspherical_shape,
/// superquadric_roundness).
void writeExtendedXyz(const Packing& packing, const std::filesystem::path& file);

} // namespace sbpack

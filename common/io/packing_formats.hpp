#pragma once
// The packing formats by extension, in one place (docs/cli.md, "Files"): what every reader of the
// tools takes its inputs through, what convert and the Python module write, and what each format
// leaves out.

#include "packing/packing.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sbpack {

enum class PackingFormat {
    Hdf5,        ///< .h5, .hdf5: the packing file (io/packing_io.hpp), everything
    Text,        ///< .txt: the text format (io/text_io.hpp)
    ExtendedXyz, ///< .xyz: extended XYZ for OVITO (io/text_io.hpp)
    Gsd,         ///< .gsd: HOOMD's GSD (io/gsd_io.hpp)
    LammpsDump,  ///< .dump, .lammpstrj: a LAMMPS dump (io/lammps_io.hpp)
    LammpsData,  ///< .data: a LAMMPS data file, atom_style ellipsoid (io/lammps_io.hpp)
};

/// The format of `file` by its extension. Throws std::invalid_argument naming the file and the
/// extensions known for any other.
PackingFormat packingFormatOf(const std::filesystem::path& file);

/// A packing in any documented format, by its extension: `.txt`, `.xyz`, `.gsd`, `.dump`,
/// `.lammpstrj` and `.data` by their readers, anything else the HDF5 file (readPacking, which names
/// a file that is not one). Every reader of the tools takes its inputs through here (issue 43).
Packing readPackingFile(const std::filesystem::path& file);

/// Writes `packing` in the format of `file`'s extension (packingFormatOf), atomically.
void writePackingFile(const Packing& packing, const std::filesystem::path& file);

/// What of `packing` the format leaves out, in words ("velocities", "provenance", "contact
/// forces", ...): what `convert` warns of (issue 65 item 4). Empty for Hdf5.
std::vector<std::string> notCarriedBy(const Packing& packing, PackingFormat format);

} // namespace sbpack

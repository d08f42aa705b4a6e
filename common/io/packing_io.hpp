#pragma once
// The HDF5 packing file shared by every tool (docs/design.md §4; its entries declared in
// io/packing_schema.hpp).

#include "io/packing_schema.hpp"
#include "packing/packing.hpp"

#include <filesystem>
#include <stdexcept>

namespace sbpack {

/// A file that cannot be read as a packing (missing, not HDF5, truncated, wrong format or
/// version, missing or misshapen data); the message names the file and the problem. Invalid
/// contents of a well-formed file are reported as InvalidPacking (packing/validation.hpp).
class PackingFileError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Throws PackingFileError unless `file` is an existing regular file (after symlinks): a
/// directory, FIFO, device or socket is refused before it is opened, so that no reader blocks.
void checkInputFile(const std::filesystem::path& file);

/// Reads and validates a packing file; normalises the quaternions and wraps positions into
/// [0, L). Throws PackingFileError or InvalidPacking.
Packing readPacking(const std::filesystem::path& file);

/// Validates `packing` (InvalidPacking) and writes it atomically through AtomicOutput
/// (OutputPathError, Hdf5Error); positions are written wrapped into [0, L).
void writePacking(const Packing& packing, const std::filesystem::path& file);

} // namespace sbpack

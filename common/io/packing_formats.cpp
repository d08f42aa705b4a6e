#include "io/packing_formats.hpp"

#include "io/gsd_io.hpp"
#include "io/lammps_io.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"

#include <optional>
#include <stdexcept>

namespace fs = std::filesystem;

namespace sbpack {

namespace {

/// The format of `file`'s extension; nullopt for an extension of none of them.
std::optional<PackingFormat> knownFormat(const fs::path& file) {
    const fs::path extension = file.extension();
    if (extension == ".h5" || extension == ".hdf5") return PackingFormat::Hdf5;
    if (extension == ".txt") return PackingFormat::Text;
    if (extension == ".xyz") return PackingFormat::ExtendedXyz;
    if (extension == ".gsd") return PackingFormat::Gsd;
    if (extension == ".dump" || extension == ".lammpstrj") return PackingFormat::LammpsDump;
    if (extension == ".data") return PackingFormat::LammpsData;
    return std::nullopt;
}

} // namespace

PackingFormat packingFormatOf(const fs::path& file) {
    if (const auto format = knownFormat(file)) return *format;
    throw std::invalid_argument("'" + file.string() +
                                "': unknown extension (use .h5, .txt, .xyz, .gsd, .dump or .data)");
}

Packing readPackingFile(const fs::path& file) {
    switch (knownFormat(file).value_or(PackingFormat::Hdf5)) { // any other: the HDF5 reader
    case PackingFormat::Hdf5:
        break;
    case PackingFormat::Text:
        return readTextPacking(file);
    case PackingFormat::ExtendedXyz:
        return readExtendedXyz(file);
    case PackingFormat::Gsd:
        return readGsd(file);
    case PackingFormat::LammpsDump:
        return readLammpsDump(file);
    case PackingFormat::LammpsData:
        return readLammpsData(file);
    }
    return readPacking(file);
}

void writePackingFile(const Packing& packing, const fs::path& file) {
    const PackingFormat format = packingFormatOf(file);
    switch (format) {
    case PackingFormat::Hdf5:
        return writePacking(packing, file);
    case PackingFormat::Text:
        return writeTextPacking(packing, file);
    case PackingFormat::ExtendedXyz:
        return writeExtendedXyz(packing, file);
    case PackingFormat::Gsd:
        return writeGsd(packing, file);
    case PackingFormat::LammpsDump:
        return writeLammpsDump(packing, file);
    case PackingFormat::LammpsData:
        return writeLammpsData(packing, file);
    }
}

std::vector<std::string> notCarriedBy(const Packing& packing, PackingFormat format) {
    std::vector<std::string> left;
    if (format == PackingFormat::Hdf5) return left;
    const bool scalars = format == PackingFormat::Text || format == PackingFormat::Gsd;
    if (!scalars && packing.reducedPressure) left.emplace_back("reduced_pressure");
    if (!scalars && packing.seed) left.emplace_back("seed");
    if (!packing.velocities.empty()) left.emplace_back("velocities");
    if (!packing.angularVelocities.empty()) left.emplace_back("angular velocities");
    if (!packing.provenance.empty() || !packing.generatorVersion.empty())
        left.emplace_back("provenance");
    if (packing.contactForces) left.emplace_back("contact forces");
    if (!packing.resumeState.empty() || !packing.pairRecords.empty())
        left.emplace_back("resume state (a checkpoint's)");
    return left;
}

} // namespace sbpack

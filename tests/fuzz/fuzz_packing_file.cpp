// libFuzzer target for the file-type dispatch readPackingFile (io/packing_formats.hpp; issue 46):
// the tools take every packing through it, which picks the reader from the name (".txt": the
// text format, ".xyz": extended XYZ, ".gsd": GSD, ".dump" and ".data": LAMMPS; anything else:
// HDF5). The input's bytes are
// written under one of several names, picked by the input's size so that the bytes stay the file
// (scripts/fuzz.sh checks findings against the release sbanalyze as they are). Whatever the name,
// the outcome must be the one of the reader its extension names, called directly: the same packing,
// or the same refusal of the documented type (PackingFileError, InvalidPacking) naming the file.
#include "fuzz_input.hpp"
#include "io/gsd_io.hpp"
#include "io/lammps_io.hpp"
#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"

#include <cstdint>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

/// Names whose extension is none of ".txt", ".xyz", ".gsd", ".dump", ".data" go to HDF5's reader.
constexpr const char* kNames[] = {"input.txt",    "input.h5",  "input.xyz",          "input",
                                  "input.txt.h5", "input.TXT", "it's a packing.txt", "input.gsd",
                                  "input.dump",   "input.data"};

struct Outcome {
    std::optional<sbpack::Packing> packing;
    std::string refusal;
};

template <class Read> Outcome outcome(const std::filesystem::path& path, Read read) {
    const std::string quoted = "'" + path.string() + "'";
    try {
        return {read(path), {}};
    } catch (const std::exception& e) {
        sbpack::fuzz::requirePackingRefusal(e, quoted, "readPackingFile");
        return {std::nullopt, e.what()};
    }
}

bool samePacking(const sbpack::Packing& a, const sbpack::Packing& b) {
    if (a.size() != b.size() || !(a.shapeSpec == b.shapeSpec) || a.semiAxis != b.semiAxis ||
        a.boxLength != b.boxLength)
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a.positions[i] != b.positions[i] ||
            a.orientations[i].coeffs() != b.orientations[i].coeffs())
            return false;
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const char* name = kNames[size % (sizeof kNames / sizeof *kNames)];
    const auto path = sbpack::fuzz::writeInput(data, size, name);
    const Outcome dispatched = outcome(path, sbpack::readPackingFile);
    const auto extension = path.extension();
    const auto [reader, read] =
        extension == ".txt"    ? std::pair{"readTextPacking", &sbpack::readTextPacking}
        : extension == ".xyz"  ? std::pair{"readExtendedXyz", &sbpack::readExtendedXyz}
        : extension == ".gsd"  ? std::pair{"readGsd", &sbpack::readGsd}
        : extension == ".dump" ? std::pair{"readLammpsDump", &sbpack::readLammpsDump}
        : extension == ".data" ? std::pair{"readLammpsData", &sbpack::readLammpsData}
                               : std::pair{"readPacking", &sbpack::readPacking};
    const Outcome direct = outcome(path, read);
    const bool same = dispatched.packing
                          ? direct.packing && samePacking(*dispatched.packing, *direct.packing)
                          : !direct.packing && dispatched.refusal == direct.refusal;
    if (!same)
        sbpack::fuzz::finding(std::string("readPackingFile('") + name + "') differs from " + reader,
                              std::runtime_error(dispatched.refusal + " | " + direct.refusal));
    return 0;
}

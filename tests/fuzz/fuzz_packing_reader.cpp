// libFuzzer target for the packing readers (issue 20; docs/reliability.md, "Inputs"): any bytes,
// read as an HDF5 packing and as a text packing, give a valid packing or a refusal of the
// documented type (PackingFileError, InvalidPacking) whose message names the file, and never a
// crash, a hang, undefined behaviour or an allocation the file does not justify. Built by the
// CMake preset "fuzz" (clang); run by scripts/fuzz.sh.
#include "fuzz_input.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"

#include <cstdint>
#include <exception>
#include <string>

namespace {

template <class Read>
void readBytes(const std::uint8_t* data, std::size_t size, Read read, const char* name) {
    const auto path = sbpack::fuzz::writeInput(data, size, name);
    const std::string quoted = "'" + path.string() + "'";
    try {
        read(path);
    } catch (const std::exception& e) {
        // A refused input is the expected outcome for almost every mutation.
        sbpack::fuzz::requirePackingRefusal(e, quoted, name);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    readBytes(
        data, size, [](const auto& path) { sbpack::readPacking(path); }, "input.h5");
    readBytes(
        data, size, [](const auto& path) { sbpack::readTextPacking(path); }, "input.txt");
    return 0;
}

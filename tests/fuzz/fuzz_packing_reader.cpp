// libFuzzer target for the packing readers (issue 20; docs/reliability.md, "Inputs"): any bytes,
// read as an HDF5 packing and as a text packing, give a valid packing or a std::exception that
// names the file, and never a crash, a hang, undefined behaviour or an allocation the file does
// not justify. Built by the CMake preset "fuzz" (clang); run by scripts/fuzz.sh.
#include "io/packing_io.hpp"
#include "io/text_io.hpp"

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

/// A private directory for the inputs (the readers take paths, as the programs do).
const std::filesystem::path& inputDirectory() {
    static const std::filesystem::path directory = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "sbpack-fuzz-XXXXXX");
        if (mkdtemp(pattern.data()) == nullptr) std::abort();
        return std::filesystem::path(pattern);
    }();
    return directory;
}

template <class Read>
void readBytes(const std::uint8_t* data, std::size_t size, Read read, const char* name) {
    const std::filesystem::path path = inputDirectory() / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    try {
        read(path);
    } catch (const std::exception&) {
        // A refused input is the expected outcome for almost every mutation.
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

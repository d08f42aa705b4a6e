#pragma once
// What the libFuzzer targets of tests/fuzz share (docs/reliability.md, "Fuzzing and sanitizers"):
// the input written to a file (the readers take paths, as the programs do) and the checks on a
// refusal. A refusal must be an exception of the documented type whose message names the file
// (or the option) it refuses; anything else aborts, which libFuzzer records as a crash with the
// input that caused it.
#include "io/packing_io.hpp"
#include "packing/validation.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <typeinfo>
#include <unistd.h>

namespace sbpack::fuzz {

/// A private directory for the inputs, removed when the process exits normally (libFuzzer's
/// jobs end that way; one that crashes leaves it, with the input that crashed it).
class InputDirectory {
  public:
    InputDirectory() {
        std::string pattern = (std::filesystem::temp_directory_path() / "sbpack-fuzz-XXXXXX");
        if (mkdtemp(pattern.data()) == nullptr) std::abort();
        path_ = pattern;
    }
    ~InputDirectory() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    InputDirectory(const InputDirectory&) = delete;
    InputDirectory& operator=(const InputDirectory&) = delete;
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

inline const std::filesystem::path& inputDirectory() {
    static const InputDirectory directory;
    return directory.path();
}

/// The input's bytes as the file `name` of the private directory.
inline std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size,
                                        const std::string& name) {
    const std::filesystem::path path = inputDirectory() / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

/// Ends the run as a finding: libFuzzer saves the input as crash-*.
[[noreturn]] inline void finding(const std::string& what, const std::exception& e) {
    std::fprintf(stderr, "FUZZ FINDING: %s: %s: %s\n", what.c_str(), typeid(e).name(), e.what());
    std::abort();
}

/// A refusal of `subject` (a file, written as the readers quote it, or an option) must say
/// `subject` in its message.
inline void requireNamed(const std::exception& e, const std::string& subject,
                         const std::string& where) {
    if (std::string(e.what()).find(subject) == std::string::npos)
        finding(where + ": the message does not name " + subject, e);
}

/// A packing reader's refusal `e` (of the file written as `quoted`) must be a PackingFileError or
/// an InvalidPacking that names the file; anything else is a finding.
inline void requirePackingRefusal(const std::exception& e, const std::string& quoted,
                                  const std::string& where) {
    if (dynamic_cast<const PackingFileError*>(&e) == nullptr &&
        dynamic_cast<const InvalidPacking*>(&e) == nullptr)
        finding(where + ": not PackingFileError or InvalidPacking", e);
    requireNamed(e, quoted, where);
}

} // namespace sbpack::fuzz

// sbgen: Donev-Torquato-Stillinger event-driven MD generator of jammed superball packings.
#include "version.hpp"

#include <cstdlib>
#include <iostream>
#include <string>

namespace {
constexpr const char* kUsage = R"(usage: sbgen --help | --version

sbgen will generate maximally random jammed packings of superballs by the
Donev-Torquato-Stillinger event-driven molecular dynamics algorithm. The event-driven
engine is not part of this version yet: this build answers --help and --version only.
Stored packings are analysed with sbanalyze (sbanalyze --help).
)";
} // namespace

int main(int argc, char** argv) {
    const std::string arg = argc > 1 ? argv[1] : "";
    if (arg == "--version") {
        std::cout << "sbgen " << sbpack::kVersion << '\n';
        return EXIT_SUCCESS;
    }
    std::cout << kUsage;
    return arg == "--help" || arg == "-h" ? EXIT_SUCCESS : EXIT_FAILURE;
}

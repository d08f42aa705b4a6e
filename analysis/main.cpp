// sbanalyze: thread-parallel analysis engine for stored packings (usage in cli/commands.cpp).
#include "cli/commands.hpp"
#include "info/library_versions.hpp"
#include "version.hpp"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty() || args[0] == "--help" || args[0] == "-h") {
            (args.empty() ? std::cerr : std::cout) << sbpack::usage();
            return args.empty() ? EXIT_FAILURE : EXIT_SUCCESS;
        }
        if (args[0] == "--version") {
            std::cout << "sbanalyze " << sbpack::kVersion << '\n' << sbpack::libraryVersions();
            return EXIT_SUCCESS;
        }
        const std::vector<std::string> rest(args.begin() + 1, args.end());
        if (args[0] == "info") return sbpack::infoCommand(rest);
        if (args[0] == "convert") return sbpack::convertCommand(rest);
        return sbpack::analyzeCommand(args);
    } catch (const std::exception& e) {
        std::cerr << "sbanalyze: error: " << e.what() << '\n';
        return EXIT_FAILURE;
    }
}

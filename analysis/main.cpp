// sbanalyze: thread-parallel analysis engine for stored packings.
#include "info/library_versions.hpp"
#include "info/packing_info.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"
#include "version.hpp"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

constexpr const char* kUsage = R"(usage:
  sbanalyze info [--tolerance T] [--rattler-threshold K] FILE.h5...
      Validate each packing and print N, p, L, R, phi (closed form), the mean width,
      the smallest gap or worst overlap, the mean contact number Z over non-rattlers
      and the rattler fraction phi_R. Contacts: gap < T * D (default 1e-10, as the
      paper); rattlers: fewer than K contacts, removed iteratively (default 4).
  sbanalyze convert IN OUT
      Convert between the HDF5 packing format (.h5), plain text (.txt: a header with
      p, semi_axis, box_length, then `x y z qw qx qy qz` per particle) and, for output
      only, extended XYZ (.xyz) that OVITO opens with orientations and shapes.
  sbanalyze --help | --version

Every input is validated; a bad file is reported with its name and the problem,
and the exit status is nonzero. Outputs are written to a temporary name and renamed.
)";

enum class Format { Hdf5, Text, Xyz };

Format formatOf(const std::string& name) {
    const auto dot = name.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : name.substr(dot);
    if (ext == ".h5" || ext == ".hdf5") return Format::Hdf5;
    if (ext == ".txt") return Format::Text;
    if (ext == ".xyz") return Format::Xyz;
    throw std::invalid_argument("'" + name + "': unknown extension (use .h5, .txt or .xyz)");
}

double parseNumber(const std::string& option, const std::string& text) {
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument("option " + option + ": '" + text + "' is not a number");
}

int info(const std::vector<std::string>& args) {
    sbpack::ContactParameters parameters;
    std::vector<std::string> files;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--tolerance" || a == "--rattler-threshold") {
            if (i + 1 == args.size()) throw std::invalid_argument("option " + a + " needs a value");
            const double value = parseNumber(a, args[++i]);
            if (a == "--tolerance") {
                parameters.tolerance = value;
            } else {
                if (value != static_cast<int>(value))
                    throw std::invalid_argument("option --rattler-threshold: must be an integer");
                parameters.rattlerThreshold = static_cast<int>(value);
            }
        } else if (a.rfind("--", 0) == 0) {
            throw std::invalid_argument("unknown option " + a + " for info");
        } else {
            files.push_back(a);
        }
    }
    if (files.empty()) throw std::invalid_argument("info: no packing file given");
    int failures = 0;
    for (const std::string& file : files) {
        try {
            sbpack::printPackingInfo(file, sbpack::packingInfo(file, parameters), std::cout);
        } catch (const std::exception& e) {
            std::cerr << "sbanalyze: error: " << e.what() << '\n';
            ++failures;
        }
    }
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int convert(const std::vector<std::string>& args) {
    if (args.size() != 2) throw std::invalid_argument("convert takes IN and OUT");
    const Format in = formatOf(args[0]), out = formatOf(args[1]);
    if (in == Format::Xyz) throw std::invalid_argument("'" + args[0] + "': XYZ is output only");
    const sbpack::Packing packing =
        in == Format::Hdf5 ? sbpack::readPacking(args[0]) : sbpack::readTextPacking(args[0]);
    if (out == Format::Hdf5) sbpack::writePacking(packing, args[1]);
    if (out == Format::Text) sbpack::writeTextPacking(packing, args[1]);
    if (out == Format::Xyz) sbpack::writeExtendedXyz(packing, args[1]);
    std::cerr << "wrote " << args[1] << " (" << packing.size() << " particles)\n";
    return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty() || args[0] == "--help" || args[0] == "-h") {
            std::cout << kUsage;
            return args.empty() ? EXIT_FAILURE : EXIT_SUCCESS;
        }
        if (args[0] == "--version") {
            std::cout << "sbanalyze " << sbpack::kVersion << '\n' << sbpack::libraryVersions();
            return EXIT_SUCCESS;
        }
        const std::vector<std::string> rest(args.begin() + 1, args.end());
        if (args[0] == "info") return info(rest);
        if (args[0] == "convert") return convert(rest);
        throw std::invalid_argument("unknown command '" + args[0] + "' (see sbanalyze --help)");
    } catch (const std::exception& e) {
        std::cerr << "sbanalyze: error: " << e.what() << '\n';
        return EXIT_FAILURE;
    }
}

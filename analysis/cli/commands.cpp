#include "cli/commands.hpp"

#include "info/packing_info.hpp"
#include "io/atomic_file.hpp"
#include "io/naming_file.hpp"
#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pipeline/run.hpp"
#include "progress/progress.hpp"
#include "schema/packing_schema_docs.hpp"
#include "schema/results_schema.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace sbpack {

int analyzeCommand(const RunSettings& settings, const Communicator& communicator) {
    installStopHandler();
    runAnalyses(settings, std::cerr, std::cout, communicator);
    return EXIT_SUCCESS;
}

int infoCommand(const std::vector<std::string>& files, const ContactParameters& parameters,
                const JammingSettings* jamming, std::ostream& out, std::ostream& err) {
    if (files.empty()) throw std::invalid_argument("info: no packing file given");
    int failures = 0;
    for (const std::string& file : files) {
        try {
            printPackingInfo(file, packingInfo(file, parameters, jamming), out);
        } catch (const std::exception& e) { // readers name the file, analyses do not
            err << "sbanalyze: error: " << messageNamingFile(e.what(), file) << '\n';
            ++failures;
        }
    }
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int convertCommand(const std::string& input, const std::string& output, std::ostream& err) {
    static_cast<void>(packingFormatOf(input)); // refuses an unknown extension
    const PackingFormat out = packingFormatOf(output);
    checkWritable(output);
    checkNotInput(output, input, "convert");
    const Packing packing = readPackingFile(input); // by the extension (io/packing_formats.hpp)
    if (const auto left = notCarriedBy(packing, out); !left.empty())
        err << "sbanalyze: warning: '" << output << "' cannot carry the "
            << fmt::format("{}", fmt::join(left, ", ")) << " of '" << input << "': left out\n";
    writePackingFile(packing, output);
    err << "wrote " << output << " (" << packing.size() << " particles)\n";
    return EXIT_SUCCESS;
}

int schemaCommand(bool json, bool packing, std::ostream& out) {
    if (packing)
        out << (json ? schema::packingSchemaJson() : schema::packingSchemaMarkdown());
    else
        out << (json ? schema::schemaJson(resultGroups()) : schema::schemaMarkdown(resultGroups()));
    return EXIT_SUCCESS;
}

} // namespace sbpack

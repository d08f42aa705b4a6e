#include "cli/command_line.hpp"

#include "cli/commands.hpp"
#include "cli/option_suggestion.hpp"
#include "cli/repeated_options.hpp"
#include "info/library_versions.hpp"
#include "pipeline/option_table.hpp"
#include "pores/distance_transform.hpp"
#include "progress/progress.hpp"
#include "version.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ostream>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr const char* kFooter =
    R"(Every input is read, validated and checked (at least 4 voxels across a particle, the memory
the grids need against MemAvailable) before any analysis starts. On any error or interrupt
no output file is written and earlier ones stay: exit 1 after an error, 128 + the signal after
SIGINT (Ctrl-C, 130) or SIGTERM (143), within a second of it (or of the FFT planning budget,
while FFTW measures a plan). Each subcommand has its own
--help (sbanalyze info --help).)";

/// The table's row on `app`, filling `settings` (the default printed from `defaults`).
void addOption(CLI::App& app, RunSettings& settings, const OptionRow& row,
               const RunSettings& defaults) {
    const std::string name = "--" + std::string(row.name);
    const std::string help = optionHelp(row, defaults);
    if (row.valueName.empty()) {
        app.add_flag_callback(
            name, [&settings, &row, name] { row.parse(settings, name, ""); }, help);
        return;
    }
    app.add_option_function<std::string>(
           name, [&settings, &row, name](const std::string& v) { row.parse(settings, name, v); },
           help)
        ->type_name(std::string(row.valueName));
}

/// The command line and what it fills.
class CommandLine {
  public:
    explicit CommandLine(const Communicator& communicator = SerialCommunicator());
    void parse(int argc, const char* const* argv);
    int run(std::ostream& out, std::ostream& err);
    const RunSettings& settings() const { return settings_; }
    CLI::App& app() { return app_; }

  private:
    void addSubcommands();
    void finishAnalysis();
    void refuseAnalysisOptionsWith(const CLI::App& subcommand) const;

    CLI::App app_{"sbanalyze: analysis of stored superball packings (threads: TBB, FFTW, "
                  "OpenMP).",
                  "sbanalyze"};
    const Communicator& communicator_;
    RunSettings settings_ = defaultRunSettings();
    std::vector<std::string> inputs_;
    CLI::App* info_ = nullptr;
    RunSettings infoSettings_; ///< info reads only the contact and jamming options
    std::vector<std::string> infoFiles_;
    bool infoJamming_ = false;
    CLI::App* convert_ = nullptr;
    std::string convertIn_, convertOut_;
    CLI::App* schema_ = nullptr;
    bool schemaMarkdown_ = false;
    bool schemaJson_ = false;
    bool schemaPacking_ = false;
};

CommandLine::CommandLine(const Communicator& communicator) : communicator_(communicator) {
    // A repeat parses, to be refused by name after (cli/repeated_options.hpp).
    app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    app_.set_version_flag("--version", [] {
        std::string text = std::string("sbanalyze ") + kVersion + '\n' + libraryVersions();
        text.pop_back(); // CLI11 ends the line
        return text;
    });
    app_.footer(kFooter);
    app_.get_formatter()->column_width(28);
    app_.add_option(
        "FILE", inputs_,
        "packing files (.h5, .txt, .xyz, .gsd, .dump or .data) to analyse, one after the other");
    const RunSettings defaults = defaultRunSettings();
    for (const OptionRow& row : analysisOptionTable())
        addOption(app_, settings_, row, defaults);
    addSubcommands();
    app_.require_subcommand(0, 1);
}

void CommandLine::addSubcommands() {
    info_ = app_.add_subcommand(
        "info", "validate each packing and print N, p, L, R, phi, the mean width, the smallest\n"
                "gap or worst overlap, Z over non-rattlers and the rattler fraction phi_R");
    const RunSettings defaults = defaultRunSettings();
    for (std::string_view name : {"tolerance", "rattler-threshold"})
        addOption(*info_, infoSettings_, findOption(name), defaults);
    info_->add_flag(
        "--jamming", infoJamming_,
        "also test the jamming categories (first order, and second where collective\n"
        "is undecided), as --compute jamming (docs/jamming.md), with the options below");
    for (std::string_view name :
         {"jamming-categories", "jamming-tolerance", "jamming-max-step", "jamming-contacts",
          "jamming-unjam-distance", "jamming-second-order", "jamming-relax"})
        addOption(*info_, infoSettings_, findOption(name), defaults);
    info_->add_option(
        "FILE", infoFiles_,
        "packing files (.h5, .txt, .xyz, .gsd, .dump or .data); a bad one is reported, "
        "the others still are");
    convert_ = app_.add_subcommand(
        "convert", "convert between .h5, .txt (a header with p, semi_axis, box_length, then\n"
                   "x y z qw qx qy qz per particle), extended XYZ (.xyz, for OVITO), GSD (.gsd:\n"
                   "HOOMD-blue, freud, OVITO) and LAMMPS (.dump, .data); docs/cli.md, \"Files\"");
    convert_
        ->add_option("IN", convertIn_, "packing to read (.h5, .txt, .xyz, .gsd, .dump or .data)")
        ->required();
    convert_
        ->add_option("OUT", convertOut_, "packing to write (.h5, .txt, .xyz, .gsd, .dump or .data)")
        ->required();
    schema_ = app_.add_subcommand(
        "schema",
        "print the results file's schema: groups, names, units (docs/results-schema.md);\n"
        "with --packing, the packing file's (docs/packing-schema.md)");
    schema_->add_flag("--markdown", schemaMarkdown_,
                      "Markdown, as docs/results-schema.md (the default)");
    schema_->add_flag("--json", schemaJson_, "JSON, for programs (not with --markdown)");
    schema_->add_flag("--packing", schemaPacking_,
                      "the packing file's schema instead (docs/packing-schema.md)");
    for (CLI::App* sub : {info_, convert_, schema_}) {
        sub->footer(""); // the analysis's footer is not theirs
        for (CLI::Option* positional : sub->get_options())
            if (positional->get_positional()) positional->type_name("");
    }
    app_.get_option("FILE")->type_name("");
}

/// What the options imply together, checked once all are read.
void CommandLine::finishAnalysis() {
    settings_.inputs.assign(inputs_.begin(), inputs_.end());
    if (!settings_.vdbDirectory.empty()) settings_.analyses.insert(Analysis::Voxels);
    const PoreMethod method = settings_.poreMethod();
    const std::int64_t m = settings_.poreVoxels();
    if (method == PoreMethod::Refined && m > maxFeatureTransformVoxels)
        throw std::invalid_argument(
            fmt::format("option --pore-voxels: {} is above {}, the largest grid of --pores refined",
                        m, maxFeatureTransformVoxels));
    if (settings_.runs(Analysis::Voronoi) &&
        settings_.voxelization.voxels > maxFeatureTransformVoxels)
        throw std::invalid_argument(fmt::format(
            "option --voxels: {} is above {}, the largest grid of voronoi (leave it out of "
            "--compute, or use a smaller --voxels)",
            settings_.voxelization.voxels, maxFeatureTransformVoxels));
    if (method != PoreMethod::Exact && settings_.pores.points > m * m * m)
        throw std::invalid_argument(fmt::format(
            "option --pore-points: K = {} random void voxels exceed the {}^3 = {} voxels of "
            "--pore-voxels (every void voxel, --pore-points 0, is the exact answer and cheaper)",
            settings_.pores.points, m, m * m * m));
    static_cast<void>(ContactNetwork(settings_.contacts)); // throws on a bad tolerance or threshold
    if (!app_.get_subcommands().empty()) return;           // info, convert, schema: no grids
    settings_.device = resolveComputeDevice(settings_.requestedDevice,
                                            settings_.requestedDevice == ComputeDevice::Cuda
                                                ? settings_.cudaRefusal()
                                                : settings_.cpuOnlyReason());
    if (settings_.fftSingle && settings_.device.device != ComputeDevice::Cuda)
        throw std::invalid_argument(
            "option --fft-precision single: only cuFFT has it (--device cuda on a CUDA build)");
}

void CommandLine::refuseAnalysisOptionsWith(const CLI::App& subcommand) const {
    if (!inputs_.empty())
        throw std::invalid_argument(fmt::format("'{}' before {}: files go after the subcommand",
                                                inputs_.front(), subcommand.get_name()));
    for (const CLI::Option* option : app_.get_options())
        if (option->count() > 0)
            throw std::invalid_argument(fmt::format("option {} is not an option of {}",
                                                    option->get_name(), subcommand.get_name()));
}

void CommandLine::parse(int argc, const char* const* argv) {
    app_.parse(argc, argv);
    refuseRepeatedOptions(app_);
    for (const CLI::App* sub : app_.get_subcommands())
        refuseAnalysisOptionsWith(*sub);
    if (schemaMarkdown_ && schemaJson_)
        throw std::invalid_argument("schema: --markdown and --json exclude each other");
    for (const CLI::Option* option : info_->get_options())
        if (!infoJamming_ && option->count() > 0 && option->get_name().starts_with("--jamming-"))
            throw std::invalid_argument(
                fmt::format("option {}: info tests the jamming categories only with --jamming",
                            option->get_name()));
    finishAnalysis();
}

int CommandLine::run(std::ostream& out, std::ostream& err) {
    if (info_->parsed())
        return infoCommand(infoFiles_, infoSettings_.contacts,
                           infoJamming_ ? &infoSettings_.jamming : nullptr, out, err);
    if (convert_->parsed()) return convertCommand(convertIn_, convertOut_, err);
    if (schema_->parsed()) return schemaCommand(schemaJson_, schemaPacking_, out);
    return analyzeCommand(settings_, communicator_);
}

} // namespace

std::string usage() {
    CommandLine commandLine;
    return commandLine.app().help();
}

namespace {

/// CLI11's "arguments were not expected", with "did you mean" for a mistyped option of the
/// command (or of its subcommand) and the --help to read.
std::string extrasMessage(const CLI::App& app, const CLI::ExtrasError& error) {
    const CLI::App* command = &app;
    for (const CLI::App* sub : app.get_subcommands())
        command = sub;
    for (const std::string& given : app.remaining(true))
        if (given.rfind("--", 0) == 0) {
            std::vector<std::string> known = longOptionNames(*command);
            const std::string help = command == &app
                                         ? "sbanalyze --help"
                                         : "sbanalyze " + command->get_name() + " --help";
            const std::vector<std::string> parent = longOptionNames(app);
            // An analysis option after a command that does not take it: not a typo to suggest
            // (it was "did you mean --out?" for --out itself).
            const std::string name = given.substr(0, given.find('='));
            if (command != &app && std::find(parent.begin(), parent.end(), name) != parent.end())
                return name + " is an option of the analysis, not of sbanalyze " +
                       command->get_name() + " (see " + help + ")";
            if (command != &app) known.insert(known.end(), parent.begin(), parent.end());
            return unknownOptionMessage(given, known) + " (see " + help + ")";
        }
    return std::string(error.what()) + " (see sbanalyze --help)";
}

int runParsed(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
              const Communicator& communicator) {
    CommandLine commandLine(communicator);
    if (argc <= 1) {
        err << commandLine.app().help();
        return EXIT_FAILURE;
    }
    try {
        commandLine.parse(argc, argv);
        return commandLine.run(out, err);
    } catch (const CLI::Success& e) { // --help, --version
        return commandLine.app().exit(e, out, err);
    } catch (const CLI::ExtrasError& e) {
        err << "sbanalyze: error: " << extrasMessage(commandLine.app(), e) << '\n';
    } catch (const CLI::ParseError& e) {
        err << "sbanalyze: error: " << e.what() << " (see sbanalyze --help)\n";
    } catch (const Interrupted& e) { // 128 + the signal, as sbgen and the shells report it
        err << "sbanalyze: " << e.what() << '\n';
        return e.signal() > 0 ? 128 + e.signal() : EXIT_FAILURE;
    } catch (const std::exception& e) {
        err << "sbanalyze: error: " << e.what() << '\n';
    }
    return EXIT_FAILURE;
}

} // namespace

int runCommandLine(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                   const Communicator& communicator) {
    const int status = runParsed(argc, argv, out, err, communicator);
    // What went to standard output (--json -, info, schema, --help) must have arrived: a full
    // disk or a closed pipe is an error, not a silent loss (docs/reliability.md).
    errno = 0;
    out.flush();
    if (out.fail()) {
        err << "sbanalyze: error: cannot write to standard output"
            << (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()) << '\n';
        return EXIT_FAILURE;
    }
    return status;
}

RunSettings parseAnalyzeArguments(const std::vector<std::string>& args) {
    std::vector<const char*> argv{"sbanalyze"};
    for (const std::string& a : args)
        argv.push_back(a.c_str());
    CommandLine commandLine;
    try {
        commandLine.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError& e) {
        throw std::invalid_argument(e.what());
    }
    if (!commandLine.app().get_subcommands().empty())
        throw std::invalid_argument("not the analysis command: " + args.front());
    return commandLine.settings();
}

} // namespace sbpack

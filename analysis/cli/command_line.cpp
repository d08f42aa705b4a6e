#include "cli/command_line.hpp"

#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "info/library_versions.hpp"
#include "parallel/parallel.hpp"
#include "pores/distance_transform.hpp"
#include "progress/progress.hpp"
#include "version.hpp"
#include "voxels/voxelization.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <thread>

namespace sbpack {

namespace {

int hardwareThreads() {
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int parseInt(const std::string& option, const std::string& text) {
    return static_cast<int>(parseInteger(option, text, INT32_MIN, INT32_MAX));
}

/// --compute's help: the registry's analyses, one a line.
std::string computeHelp() {
    std::string text = "analyses, comma-separated (default all); what they need is added (chi\n"
                       "needs voxels) and nothing else runs (sq alone voxelises nothing):";
    for (const AnalysisInfo& info : analysisRegistry())
        text += fmt::format("\n  {:<10}{}", info.name, info.description);
    return text + "\n  all       every analysis above";
}

constexpr const char* kFooter =
    R"(Every input is read, validated and checked (at least 4 voxels across a particle, the memory
the grids need against MemAvailable) before any analysis starts. On any error or interrupt
no output file is written and earlier ones stay: exit 1 after an error, 128 + the signal after
SIGINT (Ctrl-C, 130) or SIGTERM (143), within a second of it. Each subcommand has its own
--help (sbanalyze info --help).)";

/// --tolerance and --rattler-threshold, shared by the analysis and info.
void addContactOptions(CLI::App& app, ContactParameters& contacts) {
    app.add_option_function<std::string>(
           "--tolerance",
           [&contacts](const std::string& v) {
               contacts.tolerance = parseNumber("--tolerance", v);
           },
           "contact: gap < T D (default 1e-10, as the paper)")
        ->type_name("T");
    app.add_option_function<std::string>(
           "--rattler-threshold",
           [&contacts](const std::string& v) {
               contacts.rattlerThreshold = parseInt("--rattler-threshold", v);
           },
           "rattler: fewer than K contacts, removed iteratively (default 4 = d + 1)")
        ->type_name("K");
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
    void addAnalysisOptions();
    void addDistributionOptions();
    void addGridOptions();
    void addFftOptions();
    void addOutputOptions();
    void addHyperuniformityOptions();
    void addSubcommands();
    void finishAnalysis();
    void refuseAnalysisOptionsWith(const CLI::App& subcommand) const;

    CLI::App app_{"sbanalyze: analysis of stored superball packings (threads: TBB, FFTW, "
                  "OpenMP).",
                  "sbanalyze"};
    const Communicator& communicator_;
    RunSettings settings_;
    ComputeDevice device_ = ComputeDevice::Auto;
    std::vector<std::string> inputs_;
    CLI::App* info_ = nullptr;
    ContactParameters infoContacts_;
    std::vector<std::string> infoFiles_;
    CLI::App* convert_ = nullptr;
    std::string convertIn_, convertOut_;
    CLI::App* schema_ = nullptr;
    bool schemaMarkdown_ = false;
    bool schemaJson_ = false;
    bool schemaPacking_ = false;
};

CommandLine::CommandLine(const Communicator& communicator) : communicator_(communicator) {
    settings_.threads = hardwareThreads();
    settings_.analyses = resolveAnalyses("all");
    settings_.fft.wisdomFile = defaultWisdomFile();
    app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    app_.set_version_flag("--version", [] {
        std::string text = std::string("sbanalyze ") + kVersion + '\n' + libraryVersions();
        text.pop_back(); // CLI11 ends the line
        return text;
    });
    app_.footer(kFooter);
    app_.get_formatter()->column_width(28);
    app_.add_option("FILE", inputs_, "packing files (.h5 or .txt) to analyse, one after the other");
    addAnalysisOptions();
    addGridOptions();
    addOutputOptions();
    addSubcommands();
    app_.require_subcommand(0, 1);
}

void CommandLine::addAnalysisOptions() {
    RunSettings& s = settings_;
    app_.add_option_function<std::string>(
            "--compute", [&s](const std::string& v) { s.analyses = resolveAnalyses(v); },
            computeHelp())
        ->type_name("LIST");
    app_.add_option_function<std::string>(
            "--threads",
            [&s](const std::string& v) {
                s.threads = parseInt("--threads", v);
                if (s.threads < 1 || s.threads > ThreadBudget::maxThreads())
                    throw std::invalid_argument(fmt::format(
                        "option --threads: {} is not in [1, {}] (4 times the hardware threads)",
                        s.threads, ThreadBudget::maxThreads()));
            },
            fmt::format("threads for TBB, FFTW and OpenMP alike (default: the hardware's, {})",
                        hardwareThreads()))
        ->type_name("T");
    app_.add_option_function<std::string>(
            "--device", [this](const std::string& v) { device_ = computeDeviceFromName(v); },
            "where the grids of voxels, chi, hyper and pores are computed: cpu, cuda (an\n"
            "NVIDIA GPU, builds with SBPACK_WITH_CUDA; not with --pores refined or\n"
            "--distribute grids) or auto (default: cuda where granted, else cpu; docs/gpu.md)")
        ->type_name("cpu|cuda|auto");
    addContactOptions(app_, s.contacts);
    addDistributionOptions();
    app_.add_flag("--quiet", s.quiet, "no progress lines (by default one per stage on stderr)");
}

void CommandLine::addDistributionOptions() {
    RunSettings& s = settings_;
    app_.add_option_function<std::string>(
            "--distribute",
            [&s](const std::string& v) {
                if (v != "files" && v != "grids")
                    throw std::invalid_argument("option --distribute: '" + v +
                                                "' is not files or grids");
                s.distribute = v == "grids" ? Distribution::Grids : Distribution::Files;
            },
            "under mpirun (SBPACK_WITH_MPI): files (default) shares the inputs out over the\n"
            "ranks; grids analyses each input on all ranks, each holding a slab of the\n"
            "--voxels and --pore-voxels grids (chi, voxels, pores, transport; docs/scale-out.md)")
        ->type_name("files|grids");
    app_.add_flag("--plan", s.plan,
                  "print the memory per rank and the communication of the run, then stop\n"
                  "before any analysis (no output file is needed)");
    app_.add_option_function<std::string>(
            "--plan-ranks",
            [&s](const std::string& v) {
                s.planRanks = static_cast<int>(parseInteger("--plan-ranks", v, 1, 1 << 24));
                s.plan = true;
            },
            "plan for P ranks instead of this run's (implies --plan)")
        ->type_name("P");
}

void CommandLine::addGridOptions() {
    RunSettings& s = settings_;
    const auto grid = [](const char* option, int& m) {
        return [option, &m](const std::string& v) {
            m = static_cast<int>(parseInteger(option, v, 1, Voxelizer::kMaxVoxels));
        };
    };
    app_.add_option_function<std::string>(
            "--voxels", grid("--voxels", s.voxels),
            "spectral grid, M^3 voxels of the box, for chi and voxels (default 300)")
        ->type_name("M");
    app_.add_option_function<std::string>(
            "--pore-voxels", grid("--pore-voxels", s.poreVoxels),
            "pore grid, M^3 voxels, of pores and transport (default 500, as the paper);\n"
            "the exact periodic distance transform needs 5 bytes per voxel")
        ->type_name("M");
    app_.add_option_function<std::string>(
            "--pores", [&s](const std::string& v) { s.poreMethod = poreMethodFromName(v); },
            "pore sizes: voxel (default; distance between voxel centres, as the paper),\n"
            "refined (each void voxel centre's distance to the nearest particle surface,\n"
            "certified; 4 more bytes per voxel) or exact (K random points, no voxels)")
        ->type_name("voxel|refined|exact");
    app_.add_option_function<std::string>(
            "--pore-points",
            [&s](const std::string& v) {
                s.porePoints = parseInteger("--pore-points", v, 0, std::int64_t(1) << 40);
            },
            "K random points: voxel and refined, K random void voxels instead of every\n"
            "one (default 0: every one; refused where the void is under 1e-3 of the voxels);\n"
            "exact, K points of the void (default 0: 10^6, as the paper); random samples\n"
            "record the standard errors of the moments")
        ->type_name("K");
    app_.add_option_function<std::string>(
            "--pore-seed",
            [&s](const std::string& v) {
                s.poreSeed = static_cast<std::uint64_t>(
                    parseInteger("--pore-seed", v, 0, std::numeric_limits<std::int64_t>::max()));
            },
            "seed of the random points of --pore-points (default 1)")
        ->type_name("S");
    app_.add_option_function<std::string>(
            "--qmax",
            [&s](const std::string& v) {
                s.maxQw = parseNumber("--qmax", v);
                if (!(s.maxQw > 0.0) || !std::isfinite(s.maxQw))
                    throw std::invalid_argument("option --qmax: must be positive and finite");
            },
            "S(Q) and chi(Q) up to Q w <= X, w the mean width (default 30); chi also below\n"
            "the grid's Nyquist limit |n| < M/2")
        ->type_name("X");
    addHyperuniformityOptions();
    addFftOptions();
}

void CommandLine::addFftOptions() {
    RunSettings& s = settings_;
    app_.add_option_function<std::string>(
            "--fft-plan", [&s](const std::string& v) { s.fft.planning = fftPlanningFromName(v); },
            "FFTW planning: estimate, measure (default) or patient; measured plans are kept\n"
            "in the wisdom file, so only the first run per size pays")
        ->type_name("P");
    app_.add_option_function<std::string>(
            "--fft-planning-budget",
            [&s](const std::string& v) {
                if (v == "none") {
                    s.fft.planningBudget = std::numeric_limits<double>::infinity();
                    return;
                }
                s.fft.planningBudget = parseNumber("--fft-planning-budget", v);
                if (!(s.fft.planningBudget >= 0.0) || !std::isfinite(s.fft.planningBudget))
                    throw std::invalid_argument(
                        "option --fft-planning-budget: must be >= 0 and finite, or none");
            },
            fmt::format("seconds measure/patient planning may take when the wisdom has no plan\n"
                        "(default {}): planning predicted to take longer uses estimate; none:\n"
                        "no limit (a measured 300^3 plan takes ~20 s once, then is wisdom)",
                        kDefaultFftPlanningBudget))
        ->type_name("SECONDS|none");
    app_.add_option_function<std::string>(
            "--fft-precision",
            [&s](const std::string& v) {
                if (v != "double" && v != "single")
                    throw std::invalid_argument("option --fft-precision: '" + v +
                                                "' is not double or single");
                s.fftSingle = v == "single";
            },
            "chi's transform on the GPU: double (default) or single (cuFFT, --device cuda;\n"
            "its error against double is tabulated in docs/gpu.md)")
        ->type_name("double|single");
    app_.add_option_function<std::string>(
            "--fft-wisdom",
            [&s](const std::string& v) {
                s.fft.wisdomFile = v == "none" ? std::filesystem::path() : std::filesystem::path(v);
            },
            "wisdom file (default $XDG_CACHE_HOME/sbpack/fftw-wisdom, else\n"
            "~/.cache/sbpack/fftw-wisdom); none: no file. Failures only warn.")
        ->type_name("FILE|none");
}

/// "A,B" with 0 < A < B, for --alpha-window and --spread-times.
ExponentWindow parseTimes(const std::string& option, const std::string& text) {
    const auto comma = text.find(',');
    if (comma == std::string::npos)
        throw std::invalid_argument(fmt::format("option {}: '{}' is not T1,T2", option, text));
    const ExponentWindow w{parseNumber(option, text.substr(0, comma)),
                           parseNumber(option, text.substr(comma + 1))};
    if (!(w.tMin > 0.0 && w.tMax > w.tMin && std::isfinite(w.tMax)))
        throw std::invalid_argument(fmt::format("option {}: needs 0 < T1 < T2", option));
    return w;
}

void CommandLine::addHyperuniformityOptions() {
    RunSettings& s = settings_;
    app_.add_option_function<std::string>(
            "--chi-exact-qmax",
            [&s](const std::string& v) {
                s.chiExactQw = parseNumber("--chi-exact-qmax", v);
                if (!(s.chiExactQw >= 0.0) || !std::isfinite(s.chiExactQw))
                    throw std::invalid_argument("option --chi-exact-qmax: must be >= 0");
            },
            "hyper: chi_V without voxels at Q w <= X, where alpha, a0 and H are fitted\n"
            "(default 3; 0: voxel data alone)")
        ->type_name("X");
    app_.add_option_function<std::string>(
            "--fit-qmax",
            [&s](const std::string& v) {
                s.hyperuniformity.fitQmaxW = parseNumber("--fit-qmax", v);
                if (!(s.hyperuniformity.fitQmaxW > 0.0))
                    throw std::invalid_argument("option --fit-qmax: must be positive");
            },
            "hyper: fit chi_V = a0 + a1 Q^alpha over 0 < Q w <= X (default 1.4, as the paper)")
        ->type_name("X");
    app_.add_option_function<std::string>(
            "--alpha-window",
            [&s](const std::string& v) {
                s.hyperuniformity.window = parseTimes("--alpha-window", v);
            },
            "hyper: alpha from E(t) over t D / w^2 in [T1, T2] (default: from the chi_V peak's\n"
            "decay, 10 / (Q_peak w)^2, to a quarter of the box's cutoff time)")
        ->type_name("T1,T2");
    app_.add_option_function<std::string>(
            "--bootstrap",
            [&s](const std::string& v) {
                s.hyperuniformity.replicas =
                    static_cast<int>(parseInteger("--bootstrap", v, 0, 100000));
            },
            "hyper: bootstrap replicas over the wave vectors for alpha's error (default 200;\n"
            "0: none, about 0.3 s less at N = 5000)")
        ->type_name("R");
    app_.add_option_function<std::string>(
            "--spread-times",
            [&s](const std::string& v) {
                const ExponentWindow w = parseTimes("--spread-times", v);
                s.hyperuniformity.tMin = w.tMin;
                s.hyperuniformity.tMax = w.tMax;
            },
            "hyper: E(t) at t D / w^2 from T1 to T2, 20 a decade (default 1e-3,1e4)")
        ->type_name("T1,T2");
}

void CommandLine::addOutputOptions() {
    RunSettings& s = settings_;
    app_.add_option_function<std::string>(
            "--out", [&s](const std::string& v) { s.output = v; },
            "results file (HDF5): files/<i>/ per input, ensembles/<k>/ per (p, N) with the\n"
            "mean and standard deviation; names and units in docs/results-schema.md")
        ->type_name("FILE");
    app_.add_option_function<std::string>(
            "--json", [&s](const std::string& v) { s.json = v; },
            "short JSON summary (the attributes, each curve's peak); - for standard output\n"
            "(at least one of --out and --json is required)")
        ->type_name("FILE|-");
    app_.add_option_function<std::string>(
            "--vdb", [&s](const std::string& v) { s.vdbDirectory = v; },
            "export each voxelization as DIR/<input stem>.vdb, a float fog volume \"density\"\n"
            "for Blender, Houdini or ParaView (implies voxels), and with pores the pore-size\n"
            "map as DIR/<input stem>-pore-size.vdb (float grid \"pore_size\", length units)")
        ->type_name("DIR");
}

void CommandLine::addSubcommands() {
    info_ = app_.add_subcommand(
        "info", "validate each packing and print N, p, L, R, phi, the mean width, the smallest\n"
                "gap or worst overlap, Z over non-rattlers and the rattler fraction phi_R");
    addContactOptions(*info_, infoContacts_);
    info_->add_option("FILE", infoFiles_,
                      "packing files (.h5 or .txt); a bad one is reported, the others still are");
    convert_ = app_.add_subcommand(
        "convert", "convert between .h5 and .txt (a header with p, semi_axis, box_length, then\n"
                   "x y z qw qx qy qz per particle), and to extended XYZ (.xyz) for OVITO");
    convert_->add_option("IN", convertIn_, "packing to read (.h5 or .txt)")->required();
    convert_->add_option("OUT", convertOut_, "packing to write (.h5, .txt or .xyz)")->required();
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
    if (settings_.poreMethod == PoreMethod::Refined &&
        settings_.poreVoxels > maxFeatureTransformVoxels)
        throw std::invalid_argument(
            fmt::format("option --pore-voxels: {} is above {}, the largest grid of --pores refined",
                        settings_.poreVoxels, maxFeatureTransformVoxels));
    const std::int64_t m = settings_.poreVoxels;
    if (settings_.poreMethod != PoreMethod::Exact && settings_.porePoints > m * m * m)
        throw std::invalid_argument(fmt::format(
            "option --pore-points: K = {} random void voxels exceed the {}^3 = {} voxels of "
            "--pore-voxels (every void voxel, --pore-points 0, is the exact answer and cheaper)",
            settings_.porePoints, m, m * m * m));
    static_cast<void>(ContactNetwork(settings_.contacts)); // throws on a bad tolerance or threshold
    if (!app_.get_subcommands().empty()) return;           // info, convert, schema: no grids
    settings_.device = resolveComputeDevice(device_, settings_.cpuOnlyReason());
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
    for (const CLI::App* sub : app_.get_subcommands())
        refuseAnalysisOptionsWith(*sub);
    if (schemaMarkdown_ && schemaJson_)
        throw std::invalid_argument("schema: --markdown and --json exclude each other");
    finishAnalysis();
}

int CommandLine::run(std::ostream& out, std::ostream& err) {
    if (info_->parsed()) return infoCommand(infoFiles_, infoContacts_, out, err);
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

#include "cli/options.hpp"

#include "cli/option_suggestion.hpp"
#include "cli/option_values.hpp"
#include "cli/repeated_options.hpp"
#include "io/atomic_file.hpp"
#include "shapes/registry.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr const char* kDescription =
    R"(Generates a maximally random jammed packing with the Donev-Torquato-Stillinger event-driven
molecular dynamics: N particles start at random (phi-init), fly, collide elastically and grow
at rate gamma (dD/dt = gamma sqrt(kT/m)) until the reduced pressure P = PV/(NkT) diverges.
In the DTS sphere code's units (dR/dt at <|v|^2> = 1) that rate is gamma / (2 sqrt 3).

usage: sbgen --out FILE.h5 [options]
       sbgen --resume CHECKPOINT.h5 --out FILE.h5 [--pressure-final P] [--cost-limit K]
             [--pressure-finish P] [--finish-speed X]
             [--checkpoint FILE.h5])";

constexpr const char* kFooter =
    R"(No jam is declared from the pressure alone: at --pressure-final the contact network must hold
(at most 10 % rattlers or particles whose contacts lie in one hemisphere, at gaps below 100 / P D,
clamped to [1e-10, 1e-2] D), and a pressure
carried by a chain of particles that wraps around the periodic box (columns of near-cubes in
small boxes) ends the run early, and so does --cost-limit. Such an output is still written, with
provenance jammed = 0 and the reason; one stopped at the cost limit resumes.

Exit status: 0 jammed; 1 bad input or error; 3 written but not jammed; 128 + signal when
SIGINT or SIGTERM wrote a checkpoint (to --checkpoint, else OUT with .checkpoint.h5). A signal
stops the run at the end of its window, so the checkpoint resumes bit for bit; a second one
stops it at once and writes the window's start, which resumes bit for bit too. Before the
first window has ended (the set-up included) a signal stops the run at once and writes
nothing.)";

/// CLI11's help without its generic "Usage: sbgen [OPTIONS]" line: the description carries
/// sbgen's own two usage lines.
class HelpFormatter : public CLI::Formatter {
  public:
    std::string make_usage(const CLI::App* /*app*/, std::string /*name*/) const override {
        return "";
    }
};

/// sbgen's options, each defined once (CLI11); values are parsed by common/cli/option_values so
/// every message names the option.
class GeneratorCommandLine {
  public:
    GeneratorCommandLine() {
        app_.footer(kFooter);
        auto help = std::make_shared<HelpFormatter>();
        help->column_width(26);
        app_.formatter(help);
        // A repeat parses, to be refused by name after (cli/repeated_options.hpp).
        app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
        app_.add_flag("--version", options_.version, "print the version and exit");
        app_.add_flag("--quiet", options_.quiet, "no progress lines on stderr");
        addShapeOptions();
        addProtocolOptions();
        addFileOptions();
    }

    CLI::App& app() { return app_; }
    GeneratorOptions& options() { return options_; }
    const std::set<std::string>& protocolOptions() const { return protocolOptions_; }
    /// The shape the options give: --shape's family (default the superball), each of its
    /// parameters as given (--p) or its fallback; a parameter of another family is refused.
    ShapeSpec shape() const;

  private:
    /// A protocol option, its value named `placeholder` in the help: `set` parses it; noted, since
    /// --resume refuses them.
    template <class Set>
    void protocol(const std::string& name, const std::string& placeholder, Set set,
                  const std::string& help) {
        app_.add_option_function<std::string>(
                name,
                [this, name, set](const std::string& v) {
                    protocolOptions_.insert(name);
                    set(name.c_str(), v);
                },
                help)
            ->type_name(placeholder);
    }
    /// A number that a resumed run may change: kept as given (`given`, applied to the resumed
    /// protocol) and as the new run's parameter (`parameter`).
    void resumable(const char* name, const char* placeholder, std::optional<double>& given,
                   double& parameter, const char* help) {
        app_.add_option_function<std::string>(
                name,
                [name, &given, &parameter](const std::string& v) {
                    given = parameter = parseNumber(name, v);
                },
                help)
            ->type_name(placeholder);
    }
    void addShapeOptions();
    void addProtocolOptions();
    void addFileOptions();

    CLI::App app_{kDescription, "sbgen"};
    GeneratorOptions options_;
    std::set<std::string> protocolOptions_;
    std::optional<std::string> shapeFamily_;                ///< --shape
    std::map<std::string, double, std::less<>> shapeGiven_; ///< the shape parameters given, by name
};

void GeneratorCommandLine::addShapeOptions() {
    // From the family list (common/geometry/shape_families.hpp) and the registry's help
    // (generator/shapes/registry): a new family adds no option here.
    protocol(
        "--shape", "FAMILY", [this](auto, const std::string& v) { shapeFamily_ = v; },
        "the particles' shape family (default superball; known: " + shapeFamilyNames() +
            "); each of\nits parameters is the option of its name");
    std::set<std::string_view> defined;
    for (const ShapeFamily& family : shapeFamilies())
        for (const ShapeParameter& parameter : family.parameters) {
            if (!defined.insert(parameter.name).second) continue;
            std::string placeholder(parameter.name);
            for (char& c : placeholder)
                c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            protocol(
                "--" + std::string(parameter.name), placeholder,
                [this, key = std::string(parameter.name)](auto n, const std::string& v) {
                    shapeGiven_[key] = parseNumber(n, v);
                },
                shapeOptionHelp(family.name, parameter));
        }
}

ShapeSpec GeneratorCommandLine::shape() const {
    const ShapeFamily* family = writtenShapeFamily(shapeFamily_);
    if (family == nullptr)
        throw std::invalid_argument("option --shape: unknown shape family '" + *shapeFamily_ +
                                    "' (the families: " + shapeFamilyNames() + ")");
    for (const auto& [name, value] : shapeGiven_)
        if (findShapeParameter(*family, name) == nullptr)
            throw std::invalid_argument("option --" + name + ": not a parameter of the " +
                                        std::string(family->name) + " shape");
    return ShapeSpec::readOrFallback(shapeFamily_, [&](std::string_view name) {
        const auto given = shapeGiven_.find(name);
        return given != shapeGiven_.end() ? std::optional(given->second) : std::nullopt;
    });
}

void GeneratorCommandLine::addProtocolOptions() {
    ProtocolParameters& p = options_.protocol;
    protocol(
        "--n", "N",
        [&p](auto n, auto v) {
            p.particles = static_cast<int>(parseInteger(n, v, ProtocolParameters::kFewestParticles,
                                                        ProtocolParameters::kMostParticles));
        },
        "number of particles (default 1000)");
    protocol(
        "--seed", "S",
        [&p](auto n, auto v) {
            p.seed = static_cast<std::uint64_t>(parseInteger(n, v, 0, std::int64_t(1) << 53));
        },
        "random seed (default 1); same seed and options: identical packing");
    protocol(
        "--phi-init", "PHI", [&p](auto n, auto v) { p.phiInit = parseNumber(n, v); },
        "initial packing fraction in [0.001, 0.5) (default 0.2, as the paper)");
    protocol(
        "--gamma-fast", "GAMMA", [&p](auto n, auto v) { p.gammaFast = parseNumber(n, v); },
        "growth rate until --pressure-switch (default: the paper's protocol at --p,\n"
        "0.0112 for spheres, 0.016-0.033 for superballs: the rate that gives the\n"
        "paper's phi, bench/RESULTS.md, \"Fidelity\", E8)");
    protocol(
        "--gamma-slow", "GAMMA", [&p](auto n, auto v) { p.gammaSlow = parseNumber(n, v); },
        "growth rate from there to --pressure-final (default 1e-4 for spheres and, for\n"
        "superballs, the paper's protocol at --p, 4.4e-3 to 1e-2: the rate that gives\n"
        "the paper's Z, bench/RESULTS.md, \"Fidelity\", E11)");
    protocol(
        "--speed", "X", [&p](auto n, auto v) { p.speed = parseNumber(n, v); },
        "faster, less accurate: the default slow rate times X, in [1, 1000], for every\n"
        "p (default 1: the paper's protocol; 10: about ten times fewer slow-phase\n"
        "collisions, at the cost in phi, Z and phi_R of docs/design.md §3, \"Speed\")");
    protocol(
        "--pressure-switch", "P", [&p](auto n, auto v) { p.pressureSwitch = parseNumber(n, v); },
        "reduced pressure at which growth slows (default 1e6)");
    protocol(
        "--size-ratio", "R", [&p](auto n, auto v) { p.sizeRatio = parseNumber(n, v); },
        "a binary mixture (any p): the large ones' diameter over the small ones',\n"
        "in [1, 10] (default 1: identical particles; docs/mixtures.md); all grow by\n"
        "the same factor, as in the Lubachevsky-Stillinger code");
    protocol(
        "--large-fraction", "X", [&p](auto n, auto v) { p.largeFraction = parseNumber(n, v); },
        "the mixture's number fraction of large particles (default 0.5), the first\n"
        "round(X N) particles");
    protocol(
        "--polydispersity", "S", [&p](auto n, auto v) { p.polydispersity = parseNumber(n, v); },
        "a polydisperse mixture (any p): diameters uniformly distributed with\n"
        "standard deviation S times their mean, S in [0, 0.3] (default 0: none), as the\n"
        "N equally spaced quantiles, largest first (docs/mixtures.md)");
    protocol(
        "--window", "W", [&p](auto n, auto v) { p.collisionsPerWindow = parseNumber(n, v); },
        "collisions per particle between thermostat rescalings and pressure\n"
        "estimates (default 10)");
    protocol(
        "--force-windows", "K",
        [&p](auto n, auto v) { p.forceWindows = parseInteger(n, v, 0, 10'000); },
        "the contact forces written with the packing average over its last K to\n"
        "2K - 1 windows (default 50; 0: none; docs/jamming.md, \"Contact forces\")");
}

void GeneratorCommandLine::addFileOptions() {
    GeneratorOptions& o = options_;
    resumable("--pressure-final", "P", o.pressureFinal, o.protocol.pressureFinal,
              "reduced pressure at which the packing is jammed (default 1e12); --resume\n"
              "accepts it");
    resumable("--cost-limit", "K", o.costLimit, o.protocol.costLimit,
              "stop, written as not jammed (exit 3), after K times the expected collisions\n"
              "(the cost sbgen expects from measured runs, docs/design.md §3; default 40,\n"
              "2.6 times the most a run that jammed took; 0: no limit); --resume accepts it,\n"
              "so a run stopped there goes on with a larger K");
    resumable("--pressure-finish", "P", o.pressureFinish, o.protocol.pressureFinish,
              "from this reduced pressure on, grow --finish-speed times faster than the slow\n"
              "rate (default 0: no finish, the paper's protocol; docs/design.md §3,\n"
              "\"Finish\"); --resume accepts it");
    resumable("--finish-speed", "X", o.finishSpeed, o.protocol.finishSpeed,
              "the finish's rate over the slow rate, in [1, 1000] (default 1); --resume\n"
              "accepts it");
    app_.add_option_function<std::string>(
            "--out", [&o](const std::string& v) { o.out = v; },
            "the packing (sbpack.packing format: docs/design.md §4), written atomically")
        ->type_name("FILE.h5");
    app_.add_option_function<std::string>(
            "--checkpoint", [&o](const std::string& v) { o.checkpoint = v; },
            "write a checkpoint there every --checkpoint-interval seconds")
        ->type_name("FILE.h5");
    app_.add_option_function<std::string>(
            "--checkpoint-interval",
            [&o](const std::string& v) {
                o.checkpointInterval = parseNumber("--checkpoint-interval", v);
                if (!(o.checkpointInterval > 0.0))
                    throw std::invalid_argument("option --checkpoint-interval: must be positive");
            },
            "wall-clock seconds between checkpoints (default 600)")
        ->type_name("S");
    app_.add_option_function<std::string>(
            "--resume", [&o](const std::string& v) { o.resume = v; },
            "continue from a checkpoint (or a finished sbgen output, e.g. with a higher\n"
            "--pressure-final); the protocol options come from the file")
        ->type_name("FILE.h5");
}

/// The protocol's validation, its parameters named by their options.
void validateAsOptions(const ProtocolParameters& protocol) {
    try {
        protocol.validate();
    } catch (const ProtocolParameterError& e) {
        throw optionError(e);
    }
}

/// What the options imply together, checked once all are read.
void finish(GeneratorOptions& o, const std::set<std::string>& protocolOptions) {
    if (o.out.empty()) throw std::invalid_argument("option --out: an output file is required");
    if (o.resume) {
        if (!protocolOptions.empty())
            throw std::invalid_argument(
                "option " + *protocolOptions.begin() +
                ": the protocol comes from the --resume file and cannot "
                "change (only --pressure-final, --cost-limit, --pressure-finish and "
                "--finish-speed can)");
    } else {
        validateAsOptions(o.protocol);
    }
    checkWritable(o.out);
    if (o.checkpoint) checkWritable(*o.checkpoint);
    if (o.checkpoint && sameDestination(o.out, *o.checkpoint))
        throw std::invalid_argument("options --out and --checkpoint name the same file '" +
                                    o.out.string() + "': each write would replace the other");
    // --checkpoint may name the --resume file: it is read whole before the run starts, and each
    // checkpoint replaces it atomically with a later state of the same run.
    if (o.resume) checkNotInput(o.out, *o.resume, "--resume");
}

} // namespace

std::string generatorUsage() {
    GeneratorCommandLine commandLine;
    return commandLine.app().help();
}

std::invalid_argument optionError(const ProtocolParameterError& e) {
    static const std::map<std::string, std::string> kOption = {
        {"n_particles", "--n"},
        {"phi_init", "--phi-init"},
        {"gamma_fast", "--gamma-fast"},
        {"gamma_slow", "--gamma-slow"},
        {"speed", "--speed"},
        {"pressure_switch", "--pressure-switch"},
        {"pressure_final", "--pressure-final"},
        {"collisions_per_window", "--window"},
        {"cost_limit", "--cost-limit"},
        {"pressure_finish", "--pressure-finish"},
        {"finish_speed", "--finish-speed"},
        {"force_windows", "--force-windows"},
        {"size_ratio", "--size-ratio"},
        {"large_fraction", "--large-fraction"},
        {"polydispersity", "--polydispersity"}};
    const auto it = kOption.find(e.parameter());
    const bool shapeParameter = std::ranges::any_of(shapeFamilies(), [&](const ShapeFamily& f) {
        return findShapeParameter(f, e.parameter()) != nullptr;
    });
    const std::string option = it != kOption.end() ? it->second
                               : shapeParameter    ? "--" + e.parameter()
                                                   : e.parameter();
    return std::invalid_argument("option " + option + ": " + e.problem());
}

GeneratorOptions parseGeneratorOptions(const std::vector<std::string>& args) {
    GeneratorCommandLine commandLine;
    std::vector<const char*> argv{"sbgen"};
    for (const std::string& a : args)
        argv.push_back(a.c_str());
    try {
        commandLine.app().parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::CallForHelp&) {
        commandLine.options().help = true;
        return commandLine.options();
    } catch (const CLI::ExtrasError&) {
        const std::vector<std::string> extras = commandLine.app().remaining();
        for (const std::string& a : extras)
            if (a.rfind("--", 0) == 0)
                throw std::invalid_argument(
                    unknownOptionMessage(a, longOptionNames(commandLine.app())) +
                    " (see sbgen --help)");
        throw std::invalid_argument("unexpected argument '" + extras.front() + "'");
    } catch (const CLI::ParseError& e) {
        throw std::invalid_argument(std::string(e.what()) + " (see sbgen --help)");
    }
    refuseRepeatedOptions(commandLine.app());
    GeneratorOptions& o = commandLine.options();
    if (!o.version && !o.resume) o.protocol.shape = commandLine.shape();
    if (!o.version) finish(o, commandLine.protocolOptions());
    return o;
}

} // namespace sbpack

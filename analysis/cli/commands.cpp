#include "cli/commands.hpp"
#include "cli/option_values.hpp"

#include "info/packing_info.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"
#include "parallel/parallel.hpp"
#include "pipeline/run.hpp"
#include "progress/progress.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <thread>

namespace sbpack {

namespace {

constexpr const char* kAnalyzeUsage = R"(usage:
  sbanalyze FILE.h5... [--compute LIST] [--out RESULTS.h5] [--json FILE|-] [--threads T]
            [--voxels M] [--pore-voxels M] [--pore-points K] [--qmax X] [--tolerance T]
            [--rattler-threshold K] [--vdb DIR] [--fft-plan estimate|measure|patient] [--fft-wisdom FILE|none] [--quiet]
      Analyse stored packings. LIST names analyses, comma-separated; what they need is
      added (chi needs voxels) and nothing else runs (sq alone voxelises nothing):
)";

constexpr const char* kOptionsUsage = R"(        all       every analysis above (the default)
      --out FILE       results file (HDF5, layout in the README): for one input the layout of
                       docs/design.md §6 at the root; for several, files/0, files/1, ... and ensemble/
                       with the mean and standard deviation of every scalar and curve
      --json FILE|-    short JSON summary (peaks, scalars, runtimes); - for standard output
                       (at least one of --out and --json is required)
      --threads T      threads for TBB, FFTW and OpenMP alike (default: the hardware's, %HW%)
      --voxels M       spectral grid, M^3 voxels of the box, for chi and voxels (default 300)
      --pore-voxels M  pore grid, M^3 voxels, of pores and transport (default 500, as the
                       paper); the exact periodic distance transform needs 5 bytes per voxel
      --pore-points K  F(delta) from K random void points (seed 1), as the paper's 10^6, instead
                       of every void voxel (default 0: every void voxel)
      --qmax X         S(Q) and chi(Q) up to Q w <= X, w the mean width (default 30); chi also
                       below the grid's Nyquist limit |n| < M/2
      --tolerance T, --rattler-threshold K   contacts, as for info (defaults 1e-10, 4)
      --vdb DIR        export each voxelization as DIR/<input stem>.vdb, a float fog volume
                       "density" for Blender, Houdini or ParaView (implies voxels), and with
                       pores the pore-size map as DIR/<input stem>-pore-size.vdb (a float grid
                       "pore_size" over the void voxels, in length units)
      --fft-plan P     FFTW planning: estimate, measure (default) or patient; measured plans
                       are kept in the wisdom file, so only the first run per size pays
      --fft-wisdom F   wisdom file (default $XDG_CACHE_HOME/sbpack/fftw-wisdom, else
                       ~/.cache/sbpack/fftw-wisdom); none: no file. Failures only warn.
      --quiet          no progress lines (by default one per stage on standard error)
      Every input is read, validated and checked (at least 4 voxels across a particle, the
      memory the grids need against MemAvailable) before any analysis starts. On any error
      or interrupt (Ctrl-C) no output file is left behind and the exit status is 1.
)";

constexpr const char* kOtherUsage =
    R"(  sbanalyze info [--tolerance T] [--rattler-threshold K] FILE.h5...
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

int hardwareThreads() {
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

enum class Format { Hdf5, Text, Xyz };

Format formatOf(const std::string& name) {
    const auto dot = name.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : name.substr(dot);
    if (ext == ".h5" || ext == ".hdf5") return Format::Hdf5;
    if (ext == ".txt") return Format::Text;
    if (ext == ".xyz") return Format::Xyz;
    throw std::invalid_argument("'" + name + "': unknown extension (use .h5, .txt or .xyz)");
}

/// The options that take a value; the value is the next argument.
class Arguments {
  public:
    explicit Arguments(const std::vector<std::string>& args) : args_(args) {}
    bool done() const { return i_ == args_.size(); }
    const std::string& next() { return args_[i_++]; }
    const std::string& value(const std::string& option) {
        if (done()) throw std::invalid_argument("option " + option + " needs a value");
        return next();
    }

  private:
    const std::vector<std::string>& args_;
    std::size_t i_ = 0;
};

} // namespace

std::string usage() {
    std::string text = kAnalyzeUsage;
    for (const AnalysisInfo& info : analysisRegistry()) {
        std::string name(info.name);
        name.resize(10, ' ');
        text += "        " + name + std::string(info.description) + '\n';
    }
    std::string options = kOptionsUsage;
    options.replace(options.find("%HW%"), 4, std::to_string(hardwareThreads()));
    return text + options + kOtherUsage;
}

RunSettings parseAnalyzeArguments(const std::vector<std::string>& args) {
    RunSettings s;
    s.threads = hardwareThreads();
    s.analyses = resolveAnalyses("all");
    s.fft.wisdomFile = defaultWisdomFile();
    Arguments in(args);
    while (!in.done()) {
        const std::string a = in.next();
        if (a == "--compute") {
            s.analyses = resolveAnalyses(in.value(a));
        } else if (a == "--out") {
            s.output = in.value(a);
        } else if (a == "--json") {
            s.json = in.value(a);
        } else if (a == "--threads") {
            s.threads = static_cast<int>(parseInteger(a, in.value(a), INT32_MIN, INT32_MAX));
            if (s.threads < 1 || s.threads > ThreadBudget::maxThreads())
                throw std::invalid_argument("option --threads: " + std::to_string(s.threads) +
                                            " is not in [1, " +
                                            std::to_string(ThreadBudget::maxThreads()) +
                                            "] (4 times the hardware threads)");
        } else if (a == "--voxels" || a == "--pore-voxels") {
            const int m = static_cast<int>(parseInteger(a, in.value(a), INT32_MIN, INT32_MAX));
            if (m < 1) throw std::invalid_argument("option " + a + ": M must be positive");
            (a == "--voxels" ? s.voxels : s.poreVoxels) = m;
        } else if (a == "--pore-points") {
            s.porePoints = parseInteger(a, in.value(a), 0, std::int64_t(1) << 40);
        } else if (a == "--qmax") {
            s.maxQw = parseNumber(a, in.value(a));
            if (!(s.maxQw > 0.0) || !std::isfinite(s.maxQw))
                throw std::invalid_argument("option --qmax: must be positive and finite");
        } else if (a == "--tolerance") {
            s.contacts.tolerance = parseNumber(a, in.value(a));
        } else if (a == "--rattler-threshold") {
            s.contacts.rattlerThreshold =
                static_cast<int>(parseInteger(a, in.value(a), INT32_MIN, INT32_MAX));
        } else if (a == "--vdb") {
            s.vdbDirectory = in.value(a);
        } else if (a == "--fft-plan") {
            s.fft.planning = fftPlanningFromName(in.value(a));
        } else if (a == "--fft-wisdom") {
            const std::string file = in.value(a);
            s.fft.wisdomFile =
                file == "none" ? std::filesystem::path() : std::filesystem::path(file);
        } else if (a == "--quiet") {
            s.quiet = true;
        } else if (a.rfind("--", 0) == 0) {
            throw std::invalid_argument("unknown option " + a + " (see sbanalyze --help)");
        } else {
            s.inputs.emplace_back(a);
        }
    }
    if (!s.vdbDirectory.empty()) s.analyses.insert(Analysis::Voxels);
    static_cast<void>(ContactNetwork(s.contacts)); // throws on a bad tolerance or threshold
    return s;
}

int analyzeCommand(const std::vector<std::string>& args) {
    const RunSettings settings = parseAnalyzeArguments(args);
    installInterruptHandler();
    runAnalyses(settings, std::cerr, std::cout);
    return EXIT_SUCCESS;
}

int infoCommand(const std::vector<std::string>& args) {
    ContactParameters parameters;
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
            printPackingInfo(file, packingInfo(file, parameters), std::cout);
        } catch (const std::exception& e) {
            std::cerr << "sbanalyze: error: " << e.what() << '\n';
            ++failures;
        }
    }
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int convertCommand(const std::vector<std::string>& args) {
    if (args.size() != 2) throw std::invalid_argument("convert takes IN and OUT");
    const Format in = formatOf(args[0]), out = formatOf(args[1]);
    if (in == Format::Xyz) throw std::invalid_argument("'" + args[0] + "': XYZ is output only");
    const Packing packing = in == Format::Hdf5 ? readPacking(args[0]) : readTextPacking(args[0]);
    if (out == Format::Hdf5) writePacking(packing, args[1]);
    if (out == Format::Text) writeTextPacking(packing, args[1]);
    if (out == Format::Xyz) writeExtendedXyz(packing, args[1]);
    std::cerr << "wrote " << args[1] << " (" << packing.size() << " particles)\n";
    return EXIT_SUCCESS;
}

} // namespace sbpack

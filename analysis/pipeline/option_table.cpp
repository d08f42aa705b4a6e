#include "pipeline/option_table.hpp"

#include "cli/option_values.hpp"
#include "parallel/parallel.hpp"
#include "voxels/voxelization.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <thread>

namespace sbpack {

namespace {

using Settings = RunSettings;
using Text = const std::string&;

int parseInt(Text option, Text text, std::int64_t lo = INT32_MIN, std::int64_t hi = INT32_MAX) {
    return static_cast<int>(parseInteger(option, text, lo, hi));
}

/// A number in (0, inf), or [0, inf) where zero is allowed.
double parsePositive(Text option, Text text, bool zeroAllowed = false) {
    const double x = parseNumber(option, text);
    if (!std::isfinite(x) || x < 0.0 || (!zeroAllowed && x == 0.0))
        throw std::invalid_argument(fmt::format("option {}: must be {} and finite", option,
                                                zeroAllowed ? ">= 0" : "positive"));
    return x;
}

/// "A,B" with 0 < A < B, for --alpha-window and --spread-times.
ExponentWindow parseTimes(Text option, Text text) {
    const auto comma = text.find(',');
    if (comma == std::string::npos)
        throw std::invalid_argument(fmt::format("option {}: '{}' is not T1,T2", option, text));
    const ExponentWindow w{parseNumber(option, text.substr(0, comma)),
                           parseNumber(option, text.substr(comma + 1))};
    if (!(w.tMin > 0.0 && w.tMax > w.tMin && std::isfinite(w.tMax)))
        throw std::invalid_argument(fmt::format("option {}: needs 0 < T1 < T2", option));
    return w;
}

/// One of two words.
bool isSecondOf(Text option, Text text, const char* first, const char* second) {
    if (text != first && text != second)
        throw std::invalid_argument(
            fmt::format("option {}: '{}' is not {} or {}", option, text, first, second));
    return text == second;
}

/// A default as the help prints it: 30, 1.4, 1e-10; powers of ten from 1e3 on as 1eK.
std::string number(double x) {
    const double decade = std::round(std::log10(std::abs(x)));
    if (x > 0.0 && std::abs(decade) >= 3.0 && x == std::pow(10.0, decade))
        return fmt::format("1e{}", decade);
    return fmt::format("{}", x);
}

/// --compute's help after its own: the registry's analyses, one a line.
std::string analysisList() {
    std::string text, left;
    for (const AnalysisInfo& info : analysisRegistry()) {
        text += fmt::format("\n  {:<10}{}", info.name, info.description);
        if (!info.inAll) left += (left.empty() ? "" : ", ") + std::string(info.name);
    }
    return text + "\n  all       every analysis above" + (left.empty() ? "" : " but " + left);
}

void parseThreads(Settings& s, Text option, Text v) {
    s.threads = parseInt(option, v);
    if (s.threads < 1 || s.threads > ThreadBudget::maxThreads())
        throw std::invalid_argument(
            fmt::format("option {}: {} is not in [1, {}] (4 times the hardware threads)", option,
                        s.threads, ThreadBudget::maxThreads()));
}

void parsePlanningBudget(Settings& s, Text option, Text v) {
    if (v == "none") {
        s.fft.planningBudget = std::numeric_limits<double>::infinity();
        return;
    }
    s.fft.planningBudget = parseNumber(option, v);
    if (!(s.fft.planningBudget >= 0.0) || !std::isfinite(s.fft.planningBudget))
        throw std::invalid_argument(
            fmt::format("option {}: must be >= 0 and finite, or none", option));
}

/// A grid's M, 1 to Voxelizer::kMaxVoxels.
int parseGrid(Text option, Text v) {
    return parseInt(option, v, 1, Voxelizer::kMaxVoxels);
}

// The analysis and how it runs.
constexpr std::array kRunRows{
    OptionRow{"compute", "LIST",
              "analyses, comma-separated (default {}); what they need is added (chi\n"
              "needs voxels) and nothing else runs (sq alone voxelises nothing):",
              [](Settings& s, Text, Text v) { s.analyses = resolveAnalyses(v); },
              [](const Settings& d) {
                  const bool all = d.analyses == resolveAnalyses("all");
                  return all ? std::string("all") : analysisNames(d.analyses);
              },
              analysisList},
    OptionRow{"threads", "T",
              "threads for TBB, FFTW and OpenMP alike (default: the hardware's, {})", parseThreads,
              [](const Settings& d) { return std::to_string(d.threads); }},
    OptionRow{"device", "cpu|cuda|auto",
              "where the grids of voxels, chi, hyper and pores are computed: cpu, cuda (an\n"
              "NVIDIA GPU, builds with SBPACK_WITH_CUDA; not with --pores refined or\n"
              "--distribute grids) or auto (default {}: cuda where granted, else cpu; refined\n"
              "pore sizes on the CPU beside the GPU's grids; docs/gpu.md)",
              [](Settings& s, Text, Text v) { s.requestedDevice = computeDeviceFromName(v); },
              [](const Settings& d) { return std::string(computeDeviceName(d.requestedDevice)); }},
    OptionRow{"tolerance", "T", "contact: gap < T D (default {}, as the paper)",
              [](Settings& s, Text o, Text v) {
                  s.contacts.tolerance = parseNumber(o, v);
                  if (!(s.contacts.tolerance >= 0.0 &&
                        s.contacts.tolerance <= ContactParameters::kMaxTolerance))
                      throw std::invalid_argument(
                          fmt::format("option {}: must be in [0, {:g}] (a gap in units of D)", o,
                                      ContactParameters::kMaxTolerance));
              },
              [](const Settings& d) { return number(d.contacts.tolerance); }},
    OptionRow{"rattler-threshold", "K",
              "rattler: fewer than K contacts, removed iteratively (default {} = d + 1)",
              [](Settings& s, Text o, Text v) { s.contacts.rattlerThreshold = parseInt(o, v); },
              [](const Settings& d) { return std::to_string(d.contacts.rattlerThreshold); }},
    OptionRow{"distribute", "files|grids",
              "under mpirun (SBPACK_WITH_MPI): files shares the inputs out over the ranks;\n"
              "grids analyses each input on all ranks, each holding a slab of the --voxels\n"
              "and --pore-voxels grids (chi, voxels, pores, transport; docs/scale-out.md)\n"
              "(default {})",
              [](Settings& s, Text o, Text v) {
                  s.distribute = isSecondOf(o, v, "files", "grids") ? Distribution::Grids
                                                                    : Distribution::Files;
              },
              [](const Settings& d) {
                  return std::string(d.distribute == Distribution::Grids ? "grids" : "files");
              }},
    OptionRow{"plan", "",
              "print the memory per rank and the communication of the run, then stop\n"
              "before any analysis (no output file is needed)",
              [](Settings& s, Text, Text) { s.plan = true; }},
    OptionRow{"plan-ranks", "P", "plan for P ranks instead of this run's (implies --plan)",
              [](Settings& s, Text o, Text v) {
                  s.planRanks = parseInt(o, v, 1, 1 << 24);
                  s.plan = true;
              }},
    OptionRow{"quiet", "", "no progress lines (by default one per stage on stderr)",
              [](Settings& s, Text, Text) { s.quiet = true; }},
};

// The grids, S(Q) and the pores.
constexpr std::array kGridRows{
    OptionRow{"voxels", "M",
              "spectral grid, M^3 voxels of the box, for chi, voxels and voronoi (default {})",
              [](Settings& s, Text o, Text v) { s.voxelization.voxels = parseGrid(o, v); },
              [](const Settings& d) { return std::to_string(d.voxelization.voxels); }},
    OptionRow{"pore-voxels", "M",
              "pore grid, M^3 voxels, of pores and transport (default {}; with --pores voxel\n"
              "{}, the paper's); the exact periodic distance transform needs 5 bytes per voxel",
              [](Settings& s, Text o, Text v) { s.pores.voxels = parseGrid(o, v); },
              [](const Settings& d) { return std::to_string(d.poreVoxels()); }, nullptr,
              [] { return std::to_string(PoreSizeSettings::defaultVoxels(PoreMethod::Voxel)); }},
    OptionRow{"pores", "voxel|refined|exact",
              "pore sizes (default {}; voxel under --distribute grids): refined (each void\n"
              "voxel centre's distance to the nearest particle surface, certified; 4 more bytes\n"
              "per voxel), voxel (distance between voxel centres, as the paper) or exact (K\n"
              "random points, no voxels); their error against run time: docs/design.md §5",
              [](Settings& s, Text, Text v) { s.pores.method = poreMethodFromName(v); },
              [](const Settings& d) { return std::string(poreMethodName(d.poreMethod())); }},
    OptionRow{"pore-points", "K",
              "K random points: voxel and refined, K random void voxels instead of every\n"
              "one (default {}: every one; refused where the void is under 1e-3 of the voxels);\n"
              "exact, K points of the void (0: {}, as the paper); random samples record the\n"
              "standard errors of the moments",
              [](Settings& s, Text o, Text v) {
                  s.pores.points = parseInteger(o, v, 0, std::int64_t(1) << 40);
              },
              [](const Settings& d) { return std::to_string(d.pores.points); }, nullptr,
              [] { return number(double(PoreSizeSettings{}.exactParameters().randomPoints)); }},
    OptionRow{"pore-seed", "S", "seed of the random points of --pore-points (default {})",
              [](Settings& s, Text o, Text v) {
                  s.pores.seed = static_cast<std::uint64_t>(
                      parseInteger(o, v, 0, std::numeric_limits<std::int64_t>::max()));
              },
              [](const Settings& d) { return std::to_string(d.pores.seed); }},
    OptionRow{"qmax", "X",
              "S(Q) and chi(Q) up to Q w <= X, w the mean width (default {}); chi also below\n"
              "the grid's Nyquist limit |n| < M/2",
              [](Settings& s, Text o, Text v) { s.structureFactor.maxQw = parsePositive(o, v); },
              [](const Settings& d) { return number(d.structureFactor.maxQw); }},
};

// The hyperuniformity analysis (docs/hyperuniformity.md).
constexpr std::array kHyperuniformityRows{
    OptionRow{"chi-exact-qmax", "X",
              "hyper: chi_V without voxels at Q w <= X, where alpha, a0 and H are fitted\n"
              "(default {}; 0: voxel data alone)",
              [](Settings& s, Text o, Text v) {
                  s.hyperuniformity.chiExactQw = parsePositive(o, v, true);
              },
              [](const Settings& d) { return number(d.hyperuniformity.chiExactQw); }},
    OptionRow{"fit-qmax", "X",
              "hyper: fit chi_V = a0 + a1 Q^alpha over 0 < Q w <= X (default {}, as the paper)",
              [](Settings& s, Text o, Text v) { s.hyperuniformity.fitQmaxW = parsePositive(o, v); },
              [](const Settings& d) { return number(d.hyperuniformity.fitQmaxW); }},
    OptionRow{
        "alpha-window", "T1,T2",
        "hyper: alpha from E(t) over t D_diff / w^2 in [T1, T2] (default: from the chi_V peak's\n"
        "decay, 10 / (Q_peak w)^2, to a quarter of the box's cutoff time)",
        [](Settings& s, Text o, Text v) { s.hyperuniformity.window = parseTimes(o, v); },
        [](const Settings& d) {
            const auto& w = d.hyperuniformity.window;
            return w ? number(w->tMin) + ',' + number(w->tMax) : std::string();
        }},
    OptionRow{
        "bootstrap", "R",
        "hyper: bootstrap replicas over the wave vectors for alpha's error (default {};\n"
        "0: none, about 0.3 s less at N = 5000)",
        [](Settings& s, Text o, Text v) { s.hyperuniformity.replicas = parseInt(o, v, 0, 100000); },
        [](const Settings& d) { return std::to_string(d.hyperuniformity.replicas); }},
    OptionRow{
        "variance-windows", "K",
        "variance: random windows per radius on the voxel grid (default {}; 0: the\n"
        "spectral route alone), their error bar by 20 batch means",
        [](Settings& s, Text o, Text v) {
            s.variance.windows = parseInt(o, v, 0, 10000000);
            if (s.variance.windows > 0 && s.variance.windows < s.variance.batches)
                throw std::invalid_argument(fmt::format(
                    "option --variance-windows: {} is below {}, the batches of its error bar (0: "
                    "the spectral route alone)",
                    s.variance.windows, s.variance.batches));
        },
        [](const Settings& d) { return std::to_string(d.variance.windows); }},
    OptionRow{"spread-times", "T1,T2",
              "hyper: E(t) at t D_diff / w^2 from T1 to T2, 20 a decade (default {})",
              [](Settings& s, Text o, Text v) {
                  const ExponentWindow w = parseTimes(o, v);
                  s.hyperuniformity.tMin = w.tMin;
                  s.hyperuniformity.tMax = w.tMax;
              },
              [](const Settings& d) {
                  return number(d.hyperuniformity.tMin) + ',' + number(d.hyperuniformity.tMax);
              }},
};

// The jamming categories (docs/jamming.md).
constexpr std::array kJammingRows{
    OptionRow{
        "jamming-categories", "LIST",
        "jamming: the categories tested, of local, collective and strict\n"
        "(default {}); collective and strict solve linear\n"
        "programs over the whole packing: about 15 s each at N = 1000, minutes at\n"
        "N = 5000 (docs/jamming.md §3)",
        [](Settings& s, Text o, Text v) { s.jamming.categories = parseJammingCategories(o, v); },
        [](const Settings& d) { return jammingCategoryNames(d.jamming.categories); }},
    OptionRow{"jamming-tolerance", "T",
              "jamming: the contact network at gap < T D (default: the jam check's,\n"
              "max(1e-10, 100 / P) D at the file's reduced pressure P; --tolerance where the\n"
              "file has none)",
              [](Settings& s, Text o, Text v) { s.jamming.tolerance = parsePositive(o, v, true); },
              [](const Settings& d) {
                  return d.jamming.tolerance ? number(*d.jamming.tolerance) : std::string();
              }},
    OptionRow{"jamming-max-step", "DELTA",
              "jamming: the largest step of a motion, in units of D (default {}; with ideal\n"
              "contacts it only scales the motions)",
              [](Settings& s, Text o, Text v) { s.jamming.test.maxStep = parsePositive(o, v); },
              [](const Settings& d) { return number(d.jamming.test.maxStep); }},
    OptionRow{
        "jamming-contacts", "ideal|gaps",
        "jamming: ideal contacts (gap 0, as Donev et al. 2004) or their gaps, which a\n"
        "motion may close (default {}; docs/jamming.md §4)",
        [](Settings& s, Text o, Text v) {
            s.jamming.test.useGaps = isSecondOf(o, v, "ideal", "gaps");
        },
        [](const Settings& d) { return std::string(d.jamming.test.useGaps ? "gaps" : "ideal"); }},
    OptionRow{"jamming-unjam-distance", "X",
              "jamming: with --jamming-contacts gaps, a motion unjams only where it moves a\n"
              "particle by more than X D: Donev et al. 2004's finite-gap test (about 1, with\n"
              "--jamming-max-step 10 and --jamming-tolerance 0.25; docs/jamming.md §4.1);\n"
              "default {}: any motion",
              [](Settings& s, Text o, Text v) {
                  s.jamming.test.unjammingDistance = parsePositive(o, v, true);
              },
              [](const Settings& d) { return number(d.jamming.test.unjammingDistance); }},
    OptionRow{"jamming-second-order", "on|off",
              "jamming: the second-order stress test where collective jamming is undecided at\n"
              "first order (default {}; about 80 s at N = 1000, p = 1.5; docs/jamming.md §6)",
              [](Settings& s, Text o, Text v) {
                  s.jamming.test.secondOrder.enabled = isSecondOf(o, v, "off", "on");
              },
              [](const Settings& d) {
                  return std::string(d.jamming.test.secondOrder.enabled ? "on" : "off");
              }},
    OptionRow{"jamming-relax", "off|on|box",
              "jamming: test the nearest jammed packing instead (default {}): the particles\n"
              "inflated by a shell whose overlap energy is minimised, the smallest shell that\n"
              "stays jammed bracketed to 5 %, its network with the exact forces of the minimum\n"
              "(about 20 s at N = 100, p = 1.5; docs/jamming.md §6.7); box: the box's shape\n"
              "relaxes too, at its volume, so that the strict test has an isotropic stress (§6.8)",
              [](Settings& s, Text o, Text v) {
                  if (v != "off" && v != "on" && v != "box")
                      throw std::invalid_argument(
                          fmt::format("option {}: '{}' is not off, on or box", o, v));
                  s.jamming.relax = v != "off";
                  s.jamming.relaxation.deformBox = v == "box";
              },
              [](const Settings& d) {
                  return std::string(!d.jamming.relax                 ? "off"
                                     : d.jamming.relaxation.deformBox ? "box"
                                                                      : "on");
              }},
};

// FFTW (docs/design.md, "FFT planning").
constexpr std::array kFftRows{
    OptionRow{"fft-plan", "P",
              "FFTW planning: estimate, measure or patient (default {}); measured plans are\n"
              "kept in the wisdom file, so only the first run per size pays",
              [](Settings& s, Text, Text v) { s.fft.planning = fftPlanningFromName(v); },
              [](const Settings& d) { return std::string(fftPlanningName(d.fft.planning)); }},
    OptionRow{"fft-planning-budget", "SECONDS|none",
              "seconds measure/patient planning may take when the wisdom has no plan\n"
              "(default {}): planning predicted to take longer uses estimate; none:\n"
              "no limit (a measured 300^3 plan takes ~20 s once, then is wisdom)",
              parsePlanningBudget, [](const Settings& d) { return number(d.fft.planningBudget); }},
    OptionRow{
        "fft-precision", "double|single",
        "chi's transform on the GPU: double or single (default {}; single: cuFFT,\n"
        "--device cuda; its error against double is tabulated in docs/gpu.md)",
        [](Settings& s, Text o, Text v) { s.fftSingle = isSecondOf(o, v, "double", "single"); },
        [](const Settings& d) { return std::string(d.fftSingle ? "single" : "double"); }},
    OptionRow{"fft-wisdom", "FILE|none",
              "wisdom file; none: no file; failures only warn (default\n"
              "$XDG_CACHE_HOME/sbpack/fftw-wisdom, else ~/.cache/sbpack/fftw-wisdom)",
              [](Settings& s, Text, Text v) {
                  s.fft.wisdomFile =
                      v == "none" ? std::filesystem::path() : std::filesystem::path(v);
              }},
};

// The outputs (docs/results-schema.md).
constexpr std::array kOutputRows{
    OptionRow{"out", "FILE",
              "results file (HDF5): files/<i>/ per input, ensembles/<k>/ per (p, N) with the\n"
              "mean and standard deviation; names and units in docs/results-schema.md",
              [](Settings& s, Text, Text v) { s.output = v; }},
    OptionRow{"json", "FILE|-",
              "short JSON summary (the attributes, each curve's peak); - for standard output;\n"
              "a device or FIFO (/dev/null, a named pipe) is written in place (at least one of\n"
              "--out and --json is required)",
              [](Settings& s, Text, Text v) { s.json = v; }},
    OptionRow{"vdb", "DIR",
              "export each voxelization as DIR/<input stem>.vdb, a float fog volume \"density\"\n"
              "for Blender, Houdini or ParaView (implies voxels), and with pores the pore-size\n"
              "map as DIR/<input stem>-pore-size.vdb (float grid \"pore_size\", length units)",
              [](Settings& s, Text, Text v) { s.vdbDirectory = v; }},
};

template <std::size_t... Sizes>
constexpr auto joinRows(const std::array<OptionRow, Sizes>&... parts) {
    std::array<OptionRow, (Sizes + ...)> rows{};
    std::size_t i = 0;
    ((std::copy(parts.begin(), parts.end(), rows.begin() + i), i += parts.size()), ...);
    return rows;
}

constexpr auto kOptionTable =
    joinRows(kRunRows, kGridRows, kHyperuniformityRows, kJammingRows, kFftRows, kOutputRows);

} // namespace

std::span<const OptionRow> analysisOptionTable() {
    return kOptionTable;
}

const OptionRow& findOption(std::string_view name) {
    for (const OptionRow& row : kOptionTable)
        if (row.name == name) return row;
    throw std::logic_error(fmt::format("sbanalyze has no option --{}", name));
}

RunSettings defaultRunSettings() {
    RunSettings s;
    s.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    s.analyses = resolveAnalyses("all");
    s.fft.wisdomFile = defaultWisdomFile();
    return s;
}

std::string runOptions(const RunSettings& settings) {
    std::set<std::string_view> used;
    for (Analysis a : settings.analyses)
        for (std::string_view name : analysisOptions(analysisInfo(a)))
            used.insert(name);
    std::string text;
    for (const OptionRow& row : kOptionTable) {
        if (used.count(row.name) == 0 || row.shownValue == nullptr) continue;
        const std::string value = row.shownValue(settings);
        if (!value.empty())
            text += fmt::format("{}--{} {}", text.empty() ? "" : " ", row.name, value);
    }
    return text;
}

std::string optionHelp(const OptionRow& row, const RunSettings& defaults) {
    std::string text(row.help);
    if (row.shownValue != nullptr) // a help without a second "{}" ignores the second argument
        text = fmt::format(fmt::runtime(row.help), row.shownValue(defaults),
                           row.dependentDefault != nullptr ? row.dependentDefault() : "");
    if (row.moreHelp != nullptr) text += row.moreHelp();
    return text;
}

} // namespace sbpack

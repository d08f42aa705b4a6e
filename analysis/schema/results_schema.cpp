#include "schema/results_schema.hpp"

#include <array>
#include <deque>
#include <map>
#include <stdexcept>

namespace sbpack::schema {

namespace {

constexpr Kind A = Kind::Attribute;
constexpr Kind D = Kind::Dataset;
constexpr Type F = Type::Float;
constexpr Type I = Type::Int;
constexpr Type S = Type::String;
constexpr Reduce Mean = Reduce::MeanStd;
constexpr Reduce Curve = Reduce::Curve;
constexpr Reduce No = Reduce::None;
constexpr Reduce Pointwise = Reduce::Pointwise;
constexpr Reduce Same = Reduce::Same;
constexpr Reduce Pooled = Reduce::Pooled;

constexpr std::string_view kRuntime = "wall-clock time of this analysis";
// The figures of a distributed grid (--distribute grids; docs/scale-out.md), in each grid's group.
constexpr std::string_view kRanks = "--distribute grids only: ranks sharing the grid's x-slabs";
constexpr std::string_view kSlab = "--distribute grids only: x-planes of the largest rank's slab";
constexpr std::string_view kRankMemory =
    "--distribute grids only: the largest rank's grid memory (its allocations)";
constexpr std::string_view kCommunication =
    "--distribute grids only: bytes sent from rank to rank, all ranks together";

constexpr Field kRun[] = {
    {"format", A, S, "", "\"sbpack.results\""},
    {"format_version", A, I, "1", "2 (this layout)"},
    {"sbanalyze_version", A, S, "", "version of the sbanalyze that wrote the file"},
    {"compute", A, S, "", "the analyses run, comma-separated (--compute with what they need)"},
    {"threads", A, I, "1", "threads of the run (--threads), per rank"},
    {"device", A, S, "",
     "where the grids were computed (--device): \"cpu\", or \"cuda: \" and the GPU (docs/gpu.md)"},
    {"ranks", A, I, "1", "MPI processes of the run (1 without mpirun; docs/scale-out.md)"},
    {"distribute", A, S, "", "what the ranks shared out (--distribute): files or grids"},
    {"n_files", A, I, "1", "inputs: groups files/0 ... files/<n_files - 1>"},
    {"n_ensembles", A, I, "1", "ensembles (inputs of equal p and N): ensembles/0 ..."},
    {"runtime_s", A, F, "s", "wall-clock time of the whole run"},
};

constexpr Field kFile[] = {
    {"input", A, S, "", "the packing file, as named on the command line"},
    {"p", A, F, "1", "superball exponent"},
    {"n_particles", A, I, "1", "N"},
    {"box_length", A, F, "length", "cubic box edge L", Mean},
    {"semi_axis", A, F, "length", "semi-axis R (major-axis length D = 2 R)"},
    {"phi", A, F, "1", "packing fraction N v1 / L^3", Mean},
    {"mean_width", A, F, "length", "mean width w of one superball", Mean},
};

constexpr Field kStructureFactor[] = {
    {"qmax", A, F, "1", "shells up to Q w <= qmax (--qmax)"},
    {"max_shell", A, I, "1", "number of shells"},
    {"runtime_s", A, F, "s", kRuntime},
    {"Q", D, F, "1/length", "mean |Q| of the shell's wave vectors Q = 2 pi n / L"},
    {"S", D, F, "1", "S(Q), shell average of |sum_j exp(-i Q.r_j)|^2 / N (Eq. 4)", Curve},
    {"count", D, I, "1", "wave vectors in the shell"},
    {"Q_w", D, F, "1", "Q times the mean width"},
};

constexpr Field kSpectralDensity[] = {
    {"voxels", A, I, "1", "M of the M^3 grid (--voxels)"},
    {"phi_voxel", A, F, "1", "fraction of solid voxels", Mean},
    {"voxel_size", A, F, "length", "a = L / M"},
    {"qmax", A, F, "1", "shells up to Q w <= qmax (--qmax) and |n| < M / 2"},
    {"max_shell", A, I, "1", "number of shells"},
    {"fft_planning", A, S, "", "FFTW planning effort (--fft-plan)"},
    {"fft_plan_s", A, F, "s", "FFTW planning time (also on the \"FFT plan\" progress line)"},
    {"fft_plan_source", A, S, "",
     "where the plan came from: \"estimate\", \"wisdom\", \"estimate (measuring predicted "
     "over the budget)\", \"measured\" or \"measured within the budget\""},
    {"fft_planning_budget_s", A, F, "s",
     "--fft-planning-budget: without wisdom, measuring predicted to take longer falls back on "
     "estimate (inf: no limit)"},
    {"fft_s", A, F, "s", "filling the grid and the FFT"},
    {"fft_precision", A, S, "",
     "\"double\" (FFTW, or cuFFT), or \"single\" (cuFFT, --fft-precision single)"},
    {"shell_average_s", A, F, "s", "shell averaging"},
    {"ranks", A, I, "1", kRanks, No, true},
    {"slab", A, I, "1", kSlab, No, true},
    {"memory_per_rank_bytes", A, F, "bytes", kRankMemory, No, true},
    {"communication_bytes", A, F, "bytes", kCommunication, No, true},
    {"exact_s", A, F, "s", "spheres only: the exact path", No, true},
    {"exact_error", A, F, "1",
     "spheres only: max over shells of |chi - chi_exact| over the peak of chi_exact", Mean, true},
    {"runtime_s", A, F, "s", kRuntime},
    {"Q", D, F, "1/length", "mean |Q| of the shell's wave vectors"},
    {"chi", D, F, "length^3",
     "chi_V(Q) = |F(Q)|^2 [prod_i a sinc(Q_i a / 2)]^2 / V from the voxels (Eq. 12)", Curve},
    {"count", D, I, "1", "wave vectors in the shell"},
    {"Q_w", D, F, "1", "Q times the mean width"},
    {"chi_exact", D, F, "length^3", "spheres only: chi_V(Q) without voxels", No, true},
};

constexpr Field kVoxelization[] = {
    {"voxels", A, I, "1", "M of the M^3 grid (--voxels)"},
    {"phi_voxel", A, F, "1", "fraction of solid voxels (centre inside a particle)", Mean},
    {"phi_exact", A, F, "1", "N v1 / L^3", Mean},
    {"voxel_size", A, F, "length", "a = L / M"},
    {"solid_voxels", A, I, "1", "solid voxels"},
    {"memory_bytes", A, I, "bytes", "memory of the OpenVDB tree"},
    {"vdb_file", A, S, "", "with --vdb: the exported .vdb file", No, true},
    {"ranks", A, I, "1", kRanks, No, true},
    {"slab", A, I, "1", kSlab, No, true},
    {"memory_per_rank_bytes", A, F, "bytes", kRankMemory, No, true},
    {"communication_bytes", A, F, "bytes", kCommunication, No, true},
    {"runtime_s", A, F, "s", kRuntime},
};

constexpr Field kContacts[] = {
    {"z_mean", A, F, "1", "mean contact number Z over the non-rattlers (NaN if not resolved)",
     Mean},
    {"rattler_fraction", A, F, "1", "fraction of rattlers phi_R (NaN if not resolved)", Mean},
    {"tolerance", A, F, "D", "contact: gap < tolerance D (--tolerance)"},
    {"resolved", A, I, "1",
     "1 if tolerance >= tolerance_needed (contacts separated), 0 if not, -1 without a pressure"},
    {"tolerance_needed", A, F, "D", "100 / P: load-bearing gaps at the reduced pressure P"},
    {"rattler_threshold", A, I, "1", "rattler: fewer contacts, removed iteratively"},
    {"n_contacts", A, I, "1", "contacts (pairs)"},
    {"overlapping_pairs", A, I, "1", "pairs that overlap"},
    {"runtime_s", A, F, "s", kRuntime},
    {"counts", D, I, "1", "contacts of each particle"},
    {"rattler", D, I, "1", "1 for a rattler, else 0, per particle"},
    {"gap_edges", D, F, "D", "if not resolved: decade edges of gap / D, 1e-16 .. 1e-2", No, true},
    {"gap_counts", D, I, "1",
     "if not resolved: pairs per decade (the first bin holds every gap below 1e-15 D)", No, true},
};

constexpr Field kPoreSize[] = {
    {"mean", A, F, "length", "<delta> (Eq. 14)"},
    {"second_moment", A, F, "length^2", "<delta^2> (Eq. 15)"},
    {"max", A, F, "length",
     "largest pore size: voxel, the sample's; refined and exact, a local maximum of the distance "
     "to the nearest surface (Nelder-Mead from the 16 largest sample points)"},
    {"mean_w", A, F, "1", "<delta> / w", Mean},
    {"second_moment_w2", A, F, "1", "<delta^2> / w^2", Mean},
    {"max_w", A, F, "1", "largest pore size / w", Mean},
    {"saturated", A, I, "1", "1 if max < w / 2 (the paper's check), else 0"},
    {"voxels", A, I, "1", "M of the pore grid (--pore-voxels); 0 for exact"},
    {"voxel_size", A, F, "length", "a = L / M; 0 for exact"},
    {"samples", A, I, "1", "void voxels or random void points in the statistics"},
    {"method", A, S, "",
     "\"voxels\", \"random voxels\" (--pore-points), \"refined\", \"random voxels refined\" "
     "or \"exact\" (--pores)"},
    {"ranks", A, I, "1", kRanks, No, true},
    {"slab", A, I, "1", kSlab, No, true},
    {"memory_per_rank_bytes", A, F, "bytes", kRankMemory, No, true},
    {"communication_bytes", A, F, "bytes", kCommunication, No, true},
    {"runtime_s", A, F, "s", "wall-clock time of the statistics over the pore-size map or points"},
    {"map_s", A, F, "s",
     "voxel and refined: wall-clock time of the pore grid's voxelization and distance transform",
     No, true},
    {"max_sampled", A, F, "length", "refined and exact: the sample's largest pore size", No, true},
    {"max_upper_bound", A, F, "length",
     "refined over every void voxel: certified bound max <= max_sampled + sqrt(3)/2 a (the pore "
     "size is 1-Lipschitz)",
     No, true},
    {"error_bound", A, F, "length",
     "refined and exact: largest certified |pore size - distance to the nearest surface| of a "
     "sample point (support-function bound)",
     No, true},
    {"mean_stderr", A, F, "length",
     "random samples (exact, --pore-points): standard error of mean, sd(delta) / sqrt(K)", No,
     true},
    {"second_moment_stderr", A, F, "length^2",
     "random samples: standard error of second_moment, sd(delta^2) / sqrt(K)", No, true},
    {"bin_width", A, F, "length",
     "refined: F and P binned at a / 256 (F exact at the bin edges delta[j])", No, true},
    {"delta", D, F, "length", "pore sizes, delta[0] = 0 (refined: the bin edges and the largest)"},
    {"F", D, F, "1",
     "F(delta) (Eq. 13), right-continuous steps: fraction of the void with pore size > delta[j]"},
    {"delta_w", D, F, "1", "delta / w"},
    {"P_delta", D, F, "length", "bin centres of the density P(delta)"},
    {"P", D, F, "1/length", "P(delta), integrates to 1"},
    {"P_delta_w", D, F, "1", "P_delta / w"},
    {"P_w", D, F, "1", "P(delta) w, the density of delta / w"},
};

constexpr Field kTransport[] = {
    {"zeta2", A, F, "1", "three-point parameter zeta_2 (Sec. V A interpolation)"},
    {"formation_factor", A, F, "1", "formation factor F (Eq. 18)"},
    {"permeability", A, F, "length^2", "k ~ <delta^2> / F (Eq. 17)"},
    {"permeability_w2", A, F, "1", "k / w^2", Mean},
    {"mean_survival_time", A, F, "time", "bound tau <= <delta>^2 / D (Eq. 19)"},
    {"mean_survival_time_scaled", A, F, "1", "tau D / w^2", Mean},
    {"principal_relaxation_time", A, F, "time", "bound T1 <= <delta^2> / D (Eq. 20)"},
    {"principal_relaxation_time_scaled", A, F, "1", "T1 D / w^2", Mean},
    {"diffusion_coefficient", A, F, "length^2/time", "D"},
    {"runtime_s", A, F, "s", kRuntime},
};

constexpr Field kSpreadability[] = {
    {"source", A, S, "",
     "chi_V used: \"voxel\" (the --voxels grid) or \"exact+voxel\" (exact at Q w <= "
     "chi_exact_qmax, voxels beyond)"},
    {"chi_exact_qmax", A, F, "1", "exact chi_V up to Q w <= this (--chi-exact-qmax; 0: none)"},
    {"phi", A, F, "1", "the phi that normalises E: phi_voxel (voxel) or N v1 / V (exact+voxel)"},
    {"alpha", A, F, "1",
     "-3 - 2 ln(E(t_fit_max) / E(t_fit_min)) / ln(t_fit_max / t_fit_min) (Eq. PLF)", Mean},
    {"alpha_stderr", A, F, "1", "standard deviation of alpha over the Poisson bootstrap replicas"},
    {"bootstrap_replicas", A, I, "1", "bootstrap replicas over the wave vectors"},
    {"alpha_window_low", A, F, "1",
     "least alpha over the windows ending at t_fit_max / 2, t_fit_max, 2 t_fit_max"},
    {"alpha_window_high", A, F, "1", "largest alpha over those windows"},
    {"alpha_pooled", A, F, "1",
     "ensembles only: alpha of the mean E(t) over the mean window (ln E interpolated in ln t)",
     Pooled, true},
    {"t_fit_min", A, F, "w^2/D",
     "start of the alpha window: 10 / (Q_peak w)^2, the chi_V peak decayed (or --alpha-window)",
     Mean},
    {"t_fit_max", A, F, "w^2/D", "end of the alpha window: t_cutoff / 4 (or --alpha-window)", Mean},
    {"t_cutoff", A, F, "w^2/D", "t_c = 1 / (Q_min w)^2, the box's cutoff time"},
    {"runtime_s", A, F, "s", kRuntime},
    {"t", D, F, "w^2/D", "times t D / w^2, log-spaced (--spread-times)", Same},
    {"excess", D, F, "1",
     "E(t) = S(inf) - S(t) = (1 / (phi V)) sum_{Q != 0} chi_V(Q) exp(-Q^2 D t) (Eq. FT_spread)",
     Pointwise},
    {"local_exponent", D, F, "1",
     "nu(t) = d ln E / d ln t = -t <(Q w)^2>, weights chi_V exp(-Q^2 D t)"},
    {"local_alpha", D, F, "1", "-3 - 2 nu(t): the alpha of a power law at each time"},
    {"truncation_bound", D, F, "1",
     "bound on what the wave vectors beyond the grid's Nyquist limit add to E(t)"},
};

constexpr Field kHyperuniformity[] = {
    {"alpha", A, F, "1", "alpha of the fit, fixed from spreadability/alpha"},
    {"a0", A, F, "w^3", "chi_V(0) / w^3 of the fit chi_V = a0 + a1 Q^alpha (Eq. fit), not clamped",
     Mean},
    {"a0_stderr", A, F, "w^3", "least-squares standard error of a0"},
    {"a1", A, F, "w^(3+alpha)", "a1 of the fit, Q in units of 1 / w", Mean},
    {"a1_stderr", A, F, "w^(3+alpha)", "least-squares standard error of a1"},
    {"fit_points", A, I, "1", "wave vectors (one of each +-Q) in the fit window"},
    {"q_fit_max_w", A, F, "1", "the fit window 0 < Q w <= q_fit_max_w (--fit-qmax)"},
    {"H", A, F, "1", "hyperuniformity index a0 / chi_peak (Eq. HX)", Mean},
    {"H_stderr", A, F, "1", "a0_stderr / chi_peak"},
    {"H_min", A, F, "1", "least H over fit windows 0.8 ... 1.5 q_fit_max_w"},
    {"H_max", A, F, "1", "largest H over those windows"},
    {"chi_peak", A, F, "w^3", "chi_V(Q_peak) / w^3, the largest shell average from the voxels"},
    {"q_peak_w", A, F, "1", "Q_peak w"},
    {"alpha_free", A, F, "1", "alpha of the free three-parameter fit (scan over [0, 4])"},
    {"a0_free", A, F, "w^3", "a0 of the free fit"},
    {"alpha_free_low", A, F, "1", "least alpha within one standard deviation of the free fit"},
    {"alpha_free_high", A, F, "1", "largest such alpha"},
    {"free_fit_degenerate", A, I, "1",
     "1 when the free fit does not fix alpha (range over 0.5 or at the scan's end)"},
    {"runtime_s", A, F, "s", "wall-clock time of the exact chi_V, the fits and the bootstrap"},
};

constexpr Field kSpreadabilityDebye[] = {
    {"phi", A, F, "1", "phi of the Debye medium (the packing's)"},
    {"t", D, F, "a^2/D", "times t D / a^2, the same numbers as spreadability/t", Same},
    {"excess", D, F, "1",
     "E(t) of the Debye medium, chi_V = 8 pi phi (1 - phi) a^3 / (1 + (k a)^2)^2 (Eq. deb, "
     "normalised; docs/hyperuniformity.md)",
     Pointwise},
};

// One row per analysis group (docs/architecture.md, "Add an analysis").
constexpr std::array<Group, 9> kAnalysisGroups{{
    {"structure_factor", "files/<i>/structure_factor", "S(Q) of the centroids (sq)",
     kStructureFactor},
    {"spectral_density", "files/<i>/spectral_density", "chi_V(Q) from the voxels (chi)",
     kSpectralDensity},
    {"voxelization", "files/<i>/voxelization", "the --voxels grid (voxels)", kVoxelization},
    {"contacts", "files/<i>/contacts", "contact network (contacts)", kContacts},
    {"pore_size", "files/<i>/pore_size",
     "pore sizes (pores) by --pores: on the --pore-voxels grid (voxel, refined) or without voxels "
     "(exact)",
     kPoreSize},
    {"transport", "files/<i>/transport",
     "transport estimates, diffusion-controlled limit (transport); absent where zeta_2 leaves "
     "(0, 1]",
     kTransport},
    {"spreadability", "files/<i>/spreadability",
     "excess spreadability and alpha (hyper; docs/hyperuniformity.md)", kSpreadability},
    {"hyperuniformity", "files/<i>/hyperuniformity", "the small-Q fit of chi_V and H (hyper)",
     kHyperuniformity},
    {"spreadability_debye", "files/<i>/spreadability_debye",
     "the Debye random medium's excess spreadability on the same time axis (hyper)",
     kSpreadabilityDebye},
}};

constexpr Field kEnsembleOwn[] = {
    {"p", A, F, "1", "superball exponent, common to the members"},
    {"n_particles", A, I, "1", "N, common to the members"},
    {"n_files", A, I, "1", "members"},
    {"members", D, I, "1", "indices i of the members' groups files/<i>"},
};

constexpr Group kRunGroup{"", "/", "the run", kRun};
constexpr Group kFileGroup{"", "files/<i>", "one input", kFile};

/// The ensemble groups, derived from the fields and their Reduce, built once.
class EnsembleSchemas {
  public:
    EnsembleSchemas() {
        build("", "ensembles/<k>", "statistics over inputs of equal p and N", kEnsembleOwn,
              kFileGroup);
        for (const Group& g : kAnalysisGroups)
            build(g.name, "ensembles/<k>/" + std::string(g.name),
                  "statistics of " + std::string(g.path), {}, g);
    }
    const Group& operator[](std::string_view name) const {
        const auto it = groups_.find(std::string(name));
        if (it == groups_.end())
            throw std::logic_error("results schema: no ensemble group '" + std::string(name) + "'");
        return it->second.group;
    }

  private:
    struct Owned {
        std::vector<Field> fields;
        Group group;
    };
    std::string_view keep(std::string text) { return texts_.emplace_back(std::move(text)); }

    void addStatistics(std::vector<Field>& out, const Field& f) {
        out.push_back({f.name, f.kind, Type::Float, f.units,
                       keep("mean over the files: " + std::string(f.description)), No, f.optional});
        out.push_back({keep(std::string(f.name) + "_std"), f.kind, Type::Float, f.units,
                       keep("sample standard deviation of " + std::string(f.name) +
                            " over the files (n - 1; 0 for one file)"),
                       No, f.optional});
    }
    /// A file never has it (optional there); every ensemble with the group does.
    static void addPooled(std::vector<Field>& out, const Field& f) {
        out.push_back(f);
        out.back().optional = false;
    }
    void addCurve(std::vector<Field>& out, const Field& f) {
        const std::string v(f.name);
        out.push_back({"bin_width_Q_w", A, F, "1",
                       "bin width of the common Q w grid: the mean of the files' 2 pi w / L"});
        out.push_back({"Q_w", D, F, "1", "mean Q w of the files' shells in the bin"});
        out.push_back({"Q", D, F, "1/length", "mean Q of the files' shells in the bin"});
        out.push_back({f.name, D, F, f.units, keep("mean over the files of " + v)});
        out.push_back({keep(v + "_std"), D, F, f.units,
                       keep("sample standard deviation of " + v + " over the files in the bin")});
        out.push_back({"count", D, I, "1", "wave vectors in the bin, all files together"});
        out.push_back({"files", D, I, "1", "files with a shell in the bin"});
    }
    void build(std::string_view name, std::string path, std::string title,
               std::span<const Field> own, const Group& source) {
        Owned& o = groups_[std::string(name)];
        o.fields.assign(own.begin(), own.end());
        if (!name.empty()) o.fields.push_back({"n_files", A, I, "1", "members with this group"});
        for (const Field& f : source.fields) {
            if (f.reduce == Reduce::MeanStd) addStatistics(o.fields, f);
            if (f.reduce == Reduce::Curve) addCurve(o.fields, f);
            if (f.reduce == Reduce::Pointwise) addStatistics(o.fields, f);
            if (f.reduce == Reduce::Same) o.fields.push_back(f);
            if (f.reduce == Reduce::Pooled) addPooled(o.fields, f);
        }
        o.group = {name, keep(std::move(path)), keep(std::move(title)), o.fields};
    }

    std::deque<std::string> texts_;
    std::map<std::string, Owned> groups_;
};

const EnsembleSchemas& ensembleSchemas() {
    static const EnsembleSchemas schemas;
    return schemas;
}

} // namespace

const Group& runGroup() {
    return kRunGroup;
}
const Group& fileGroup() {
    return kFileGroup;
}
std::span<const Group> analysisGroups() {
    return kAnalysisGroups;
}

const Group* findAnalysisGroup(std::string_view name) {
    for (const Group& g : kAnalysisGroups)
        if (g.name == name) return &g;
    return nullptr;
}

const Group& ensembleRootGroup() {
    return ensembleSchemas()[""];
}

const Group& ensembleGroup(std::string_view name) {
    if (name.empty()) throw std::logic_error("results schema: the ensemble root has no name");
    return ensembleSchemas()[name];
}

const Field* findField(const Group& group, std::string_view name) {
    for (const Field& f : group.fields)
        if (f.name == name) return &f;
    return nullptr;
}

std::string unitsAttributeName(std::string_view attribute) {
    return std::string(attribute) + "_units";
}

} // namespace sbpack::schema

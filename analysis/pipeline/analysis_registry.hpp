#pragma once
// The analyses sbanalyze can run, by the names of --compute: what each needs, which results
// group it fills (schema/results_schema.hpp) and the stage that runs it (pipeline/stage.hpp).
// Adding an analysis: docs/architecture.md, "Add an analysis".

#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sbpack {

class FileContext;
struct EnsembleResults;
struct FileResults;
struct RunSettings;
struct Packing;
namespace schema {
class Record;
struct Group;
} // namespace schema

enum class Analysis {
    Contacts,        ///< contact network, Z and rattlers (common/contacts)
    StructureFactor, ///< S(Q) from the centroids
    SpectralDensity, ///< chi_V(Q) from the voxels (and exactly, for spheres)
    Voxels,          ///< the voxelization: phi_voxel against phi, optional .vdb export
    PoreSizes,       ///< pore-size distribution F(delta) from the periodic distance transform
    Transport,       ///< k, tau, T1 from the pore-size moments (diffusion-controlled limit)
    Hyperuniformity, ///< excess spreadability, alpha, the small-Q fit and H (hyperuniformity/)
    Order,           ///< g2, Q4 and Q6, T, the cubatic P4 (common/order)
    Jamming,         ///< the jamming categories at first order (common/jamming)
    Voronoi,         ///< set-Voronoi cells and local packing fractions (voronoi/)
    Variance,        ///< local volume-fraction variance sigma_V^2(R) (variance/)
};

/// Which voxel grid an analysis works on: none, the spectral grid (--voxels, default 300 as the
/// paper's chi) or the pore grid (--pore-voxels, default 500 as the paper's pore sizes).
enum class VoxelGrid { None, Spectral, Pore };

/// The largest transient allocation of a stage, for the memory check before a run.
struct StageMemory {
    double bytes = 0.0;
    std::string what;   ///< e.g. "FFT grid 300^3"
    std::string option; ///< the option that sizes it, e.g. "--voxels"
};

/// Runs one analysis on the file of `context` and fills `record` (its results group); returns
/// false when the analysis does not apply to this file (it has warned why; no group is written).
using StageRun = bool (*)(FileContext& context, schema::Record& record);
/// Estimates a stage's largest transient allocation; nullptr where it is negligible.
using StageMemoryEstimate = StageMemory (*)(const Packing& packing, const RunSettings& settings);
/// Adds to an ensemble's statistics of the analysis's groups what the generic reduction cannot
/// (the schema's Reduce::Pooled fields), from the reduced groups and the members' own records
/// (`files[m]` for m in ensemble.members). Runs once per ensemble, after every group is reduced.
using EnsembleFinish = void (*)(EnsembleResults& ensemble, std::span<const FileResults> files);

struct AnalysisInfo {
    Analysis analysis;
    std::string_view name; ///< as in --compute
    /// Its results groups, its own (the one its StageRun fills) first; each is declared beside
    /// the result it is read from (schema/field_table.hpp).
    std::span<const schema::Group* const> groups;
    std::string_view description; ///< one line for --help
    VoxelGrid grid = VoxelGrid::None;
    std::span<const Analysis> needs = {}; ///< analyses whose results it uses (they run first)
    std::string_view vdbSuffix = "";      ///< with --vdb: exports DIR/<input stem><suffix>
    StageRun run = nullptr;
    StageMemoryEstimate memory = nullptr;
    EnsembleFinish finishEnsemble = nullptr;
    /// The command-line options (without "--") that change its results, besides --threads;
    /// those of its needs add to them (analysisOptions).
    std::span<const std::string_view> options = {};
    /// Its class in Python's sbpack (python/sbpack/analyses.py makes it from this row).
    std::string_view pythonClass = "";
    /// Whether --compute all runs it; false: only when named (jamming, whose linear programs
    /// take minutes at N = 5000, more than every other analysis together; docs/jamming.md §3).
    bool inAll = true;

    const schema::Group& group() const { return *groups.front(); }
};

/// The options of `info` and of what it needs, recursively, each once, its own first.
std::vector<std::string_view> analysisOptions(const AnalysisInfo& info);

/// The results groups of every analysis, in registry order (docs/results-schema.md's order).
std::span<const schema::Group* const> resultGroups();
/// The results group called `name`; nullptr if there is none.
const schema::Group* findResultGroup(std::string_view name);

/// Every analysis, in the order they are listed (they run in this order, needs first).
std::span<const AnalysisInfo> analysisRegistry();
const AnalysisInfo& analysisInfo(Analysis analysis);

/// The analyses to run: those named and, recursively, what they need.
using AnalysisSet = std::set<Analysis>;

/// Resolves a comma-separated list of names ("all" for every analysis with inAll). Throws
/// std::invalid_argument naming an unknown or empty entry and listing the known names.
AnalysisSet resolveAnalyses(std::string_view list);

/// The names of `set`, comma-separated, in registry order.
std::string analysisNames(const AnalysisSet& set);

/// `set` in the order its stages run: registry order, each analysis after what it needs.
std::vector<Analysis> runOrder(const AnalysisSet& set);

} // namespace sbpack

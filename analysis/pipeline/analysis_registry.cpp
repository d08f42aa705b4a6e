#include "pipeline/analysis_registry.hpp"

#include "contacts/contacts_fields.hpp"
#include "hyperuniformity/hyperuniformity_fields.hpp"
#include "jamming/jamming_fields.hpp"
#include "order/order_fields.hpp"
#include "pipeline/stages/stages.hpp"
#include "pores/pore_size_fields.hpp"
#include "spectral/spectral_density_fields.hpp"
#include "structure/structure_factor_fields.hpp"
#include "transport/transport_fields.hpp"
#include "variance/variance_fields.hpp"
#include "voronoi/voronoi_fields.hpp"
#include "voxels/voxelization_fields.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

namespace sbpack {

namespace {

constexpr std::array<Analysis, 1> kSpectralNeeds{Analysis::Voxels};
constexpr std::array<Analysis, 1> kTransportNeeds{Analysis::PoreSizes};
constexpr std::array<Analysis, 1> kHyperuniformityNeeds{Analysis::SpectralDensity};
constexpr std::array<Analysis, 1> kOrderNeeds{Analysis::Contacts};
constexpr std::array<Analysis, 1> kVoronoiNeeds{Analysis::Contacts};
constexpr std::array<Analysis, 2> kVarianceNeeds{Analysis::Voxels, Analysis::SpectralDensity};

constexpr std::array<const schema::Group*, 1> kContactsGroups{&kContactsGroup};
constexpr std::array<const schema::Group*, 1> kStructureFactorGroups{&kStructureFactorGroup};
constexpr std::array<const schema::Group*, 1> kSpectralDensityGroups{&kSpectralDensityGroup};
constexpr std::array<const schema::Group*, 1> kVoxelizationGroups{&kVoxelizationGroup};
constexpr std::array<const schema::Group*, 1> kPoreSizeGroups{&kPoreSizeGroup};
constexpr std::array<const schema::Group*, 1> kTransportGroups{&kTransportGroup};
constexpr std::array<const schema::Group*, 1> kOrderGroups{&kOrderGroup};
constexpr std::array<const schema::Group*, 1> kVoronoiGroups{&kVoronoiGroup};
constexpr std::array<const schema::Group*, 1> kVarianceGroups{&kVarianceGroup};
constexpr std::array<const schema::Group*, 3> kHyperuniformityGroups{
    &kSpreadabilityGroup, &kHyperuniformityGroup, &kSpreadabilityDebyeGroup};
constexpr std::array<const schema::Group*, 4> kJammingGroups{
    &kJammingGroup, &kJammingLocalGroup, &kJammingCollectiveGroup, &kJammingStrictGroup};

using Options = std::string_view;
constexpr std::array<Options, 2> kContactOptions{"tolerance", "rattler-threshold"};
constexpr std::array<Options, 1> kStructureFactorOptions{"qmax"};
constexpr std::array<Options, 4> kSpectralOptions{"qmax", "fft-plan", "fft-planning-budget",
                                                  "fft-wisdom"};
constexpr std::array<Options, 1> kVoxelOptions{"voxels"};
constexpr std::array<Options, 4> kPoreOptions{"pore-voxels", "pores", "pore-points", "pore-seed"};
constexpr std::array<Options, 2> kVarianceOptions{"variance-windows", "chi-exact-qmax"};
constexpr std::array<Options, 5> kHyperuniformityOptions{
    "chi-exact-qmax", "fit-qmax", "alpha-window", "bootstrap", "spread-times"};
// The network's rattlers by --rattler-threshold, and its tolerance --tolerance where the file
// has no reduced pressure (docs/jamming.md §2).
constexpr std::array<Options, 9> kJammingOptions{
    "jamming-categories",     "jamming-tolerance",    "jamming-max-step", "jamming-contacts",
    "jamming-unjam-distance", "jamming-second-order", "jamming-relax",    "tolerance",
    "rattler-threshold"};

// One row per analysis (docs/architecture.md, "Add an analysis"): its results groups are
// declared beside its result, its stage in pipeline/stages/.
constexpr std::array<AnalysisInfo, 11> kRegistry{{
    {.analysis = Analysis::Contacts,
     .name = "contacts",
     .groups = kContactsGroups,
     .description = "contact network: mean contact number Z, rattler fraction, contacts per "
                    "particle",
     .run = stages::runContacts,
     .options = kContactOptions,
     .pythonClass = "Contacts"},
    {.analysis = Analysis::StructureFactor,
     .name = "sq",
     .groups = kStructureFactorGroups,
     .description = "structure factor S(Q) of the centroids (Eq. 4)",
     .run = stages::runStructureFactor,
     .memory = stages::structureFactorMemory,
     .options = kStructureFactorOptions,
     .pythonClass = "StructureFactor"},
    {.analysis = Analysis::SpectralDensity,
     .name = "chi",
     .groups = kSpectralDensityGroups,
     .description =
         "spectral density chi_V(Q) from the voxels by FFT (Eq. 12); exact too for spheres",
     .grid = VoxelGrid::Spectral,
     .needs = kSpectralNeeds,
     .run = stages::runSpectralDensity,
     .memory = stages::spectralDensityMemory,
     .options = kSpectralOptions,
     .pythonClass = "SpectralDensity"},
    {.analysis = Analysis::Voxels,
     .name = "voxels",
     .groups = kVoxelizationGroups,
     .description = "voxelization on the --voxels grid: phi_voxel against phi",
     .grid = VoxelGrid::Spectral,
     .vdbSuffix = ".vdb",
     .run = stages::runVoxels,
     .memory = stages::voxelsMemory,
     .options = kVoxelOptions,
     .pythonClass = "Voxelization"},
    {.analysis = Analysis::PoreSizes,
     .name = "pores",
     .groups = kPoreSizeGroups,
     .description =
         "pore sizes F(delta), <delta>, <delta^2> (Eqs. 13-15) by --pores: on the --pore-voxels "
         "grid by exact periodic distance transform (voxel), refined to the surfaces, or exact",
     .grid = VoxelGrid::Pore,
     .vdbSuffix = "-pore-size.vdb",
     .run = stages::runPoreSizes,
     .memory = stages::poreSizesMemory,
     .options = kPoreOptions,
     .pythonClass = "PoreSizes"},
    {.analysis = Analysis::Transport,
     .name = "transport",
     .groups = kTransportGroups,
     .description = "permeability k, survival time tau, relaxation time T1 from the pore sizes "
                    "(Eqs. 16-20)",
     .needs = kTransportNeeds,
     .run = stages::runTransport,
     .pythonClass = "Transport"},
    {.analysis = Analysis::Hyperuniformity,
     .name = "hyper",
     .groups = kHyperuniformityGroups,
     .description =
         "excess spreadability E(t), alpha from its long-time decay, the fit a0 + a1 Q^alpha and "
         "H (Eqs. 21-23, fit, HX), the Debye medium; chi_V exact at Q w <= --chi-exact-qmax",
     .grid = VoxelGrid::Spectral,
     .needs = kHyperuniformityNeeds,
     .run = stages::runHyperuniformity,
     .finishEnsemble = stages::poolHyperuniformity,
     .options = kHyperuniformityOptions,
     .pythonClass = "Hyperuniformity"},
    {.analysis = Analysis::Order,
     .name = "order",
     .groups = kOrderGroups,
     .description = "order metrics: g2(r), Q4 and Q6 (cutoff and contact bonds), the "
                    "translational order T, the cubatic P4 of the axes; warns when ordered",
     .needs = kOrderNeeds,
     .run = stages::runOrder,
     .pythonClass = "Order"},
    {.analysis = Analysis::Jamming,
     .name = "jamming",
     .groups = kJammingGroups,
     .description = "jamming categories at first order (local, collective, strict; "
                    "docs/jamming.md): the category reached, the unjamming motions; not in all",
     .run = stages::runJamming,
     .finishEnsemble = stages::countJammingCategories,
     .options = kJammingOptions,
     .pythonClass = "Jamming",
     .inAll = false},
    {.analysis = Analysis::Voronoi,
     .name = "voronoi",
     .groups = kVoronoiGroups,
     .description = "set-Voronoi cells on the --voxels grid: local packing fractions v_i / "
                    "v_cell, their moments (rattlers apart) and density",
     .grid = VoxelGrid::Spectral,
     .needs = kVoronoiNeeds,
     .run = stages::runVoronoi,
     .memory = stages::voronoiMemory,
     .options = kVoxelOptions,
     .pythonClass = "SetVoronoi"},
    {.analysis = Analysis::Variance,
     .name = "variance",
     .groups = kVarianceGroups,
     .description = "local volume-fraction variance sigma_V^2(R) of spherical windows, by random "
                    "windows on the --voxels grid and from chi_V; alpha from its tail",
     .grid = VoxelGrid::Spectral,
     .needs = kVarianceNeeds,
     .run = stages::runVariance,
     .memory = stages::varianceMemory,
     .finishEnsemble = stages::poolVariance,
     .options = kVarianceOptions,
     .pythonClass = "VolumeFractionVariance"},
}};

/// The results groups of the registry's rows, in order.
std::vector<const schema::Group*> collectGroups() {
    std::vector<const schema::Group*> groups;
    for (const AnalysisInfo& info : kRegistry)
        groups.insert(groups.end(), info.groups.begin(), info.groups.end());
    return groups;
}

} // namespace

std::vector<std::string_view> analysisOptions(const AnalysisInfo& info) {
    std::vector<std::string_view> options(info.options.begin(), info.options.end());
    for (Analysis need : info.needs)
        for (std::string_view option : analysisOptions(analysisInfo(need)))
            if (std::find(options.begin(), options.end(), option) == options.end())
                options.push_back(option);
    return options;
}

std::span<const schema::Group* const> resultGroups() {
    static const std::vector<const schema::Group*> groups = collectGroups();
    return groups;
}

const schema::Group* findResultGroup(std::string_view name) {
    for (const schema::Group* g : resultGroups())
        if (g->name == name) return g;
    return nullptr;
}

namespace {

void addWithNeeds(Analysis analysis, AnalysisSet& set) {
    if (!set.insert(analysis).second) return;
    for (Analysis need : analysisInfo(analysis).needs)
        addWithNeeds(need, set);
}

void appendInRunOrder(Analysis analysis, const AnalysisSet& set, std::vector<Analysis>& order) {
    if (set.count(analysis) == 0) return;
    for (Analysis done : order)
        if (done == analysis) return;
    for (Analysis need : analysisInfo(analysis).needs)
        appendInRunOrder(need, set, order);
    order.push_back(analysis);
}

std::string knownNames() {
    std::string names;
    for (const AnalysisInfo& info : kRegistry)
        names += std::string(info.name) + ", ";
    return names + "all";
}

const AnalysisInfo& byName(std::string_view name) {
    for (const AnalysisInfo& info : kRegistry)
        if (info.name == name) return info;
    throw std::invalid_argument("option --compute: " +
                                (name.empty() ? std::string("empty analysis name")
                                              : "unknown analysis '" + std::string(name) + "'") +
                                " (known: " + knownNames() + ")");
}

} // namespace

std::span<const AnalysisInfo> analysisRegistry() {
    return kRegistry;
}

const AnalysisInfo& analysisInfo(Analysis analysis) {
    for (const AnalysisInfo& info : kRegistry)
        if (info.analysis == analysis) return info;
    throw std::logic_error("analysis missing from the registry");
}

AnalysisSet resolveAnalyses(std::string_view list) {
    AnalysisSet set;
    std::size_t begin = 0;
    while (begin <= list.size()) {
        const std::size_t comma = std::min(list.find(',', begin), list.size());
        const std::string_view name = list.substr(begin, comma - begin);
        begin = comma + 1;
        if (name == "all") {
            for (const AnalysisInfo& info : kRegistry)
                if (info.inAll) addWithNeeds(info.analysis, set);
        } else {
            addWithNeeds(byName(name).analysis, set);
        }
    }
    return set;
}

std::string analysisNames(const AnalysisSet& set) {
    std::string names;
    for (const AnalysisInfo& info : kRegistry)
        if (set.count(info.analysis) != 0) {
            if (!names.empty()) names += ',';
            names += info.name;
        }
    return names;
}

std::vector<Analysis> runOrder(const AnalysisSet& set) {
    std::vector<Analysis> order;
    for (const AnalysisInfo& info : kRegistry)
        appendInRunOrder(info.analysis, set, order);
    return order;
}

} // namespace sbpack

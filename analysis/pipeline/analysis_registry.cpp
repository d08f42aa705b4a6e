#include "pipeline/analysis_registry.hpp"

#include "pipeline/stages/stages.hpp"

#include <array>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr std::array<Analysis, 1> kSpectralNeeds{Analysis::Voxels};
constexpr std::array<Analysis, 1> kTransportNeeds{Analysis::PoreSizes};
constexpr std::array<Analysis, 1> kHyperuniformityNeeds{Analysis::SpectralDensity};

// One row per analysis (docs/architecture.md, "Add an analysis"); its results group is declared
// in schema/results_schema.cpp, its stage in pipeline/stages/.
constexpr std::array<AnalysisInfo, 7> kRegistry{{
    {Analysis::Contacts,
     "contacts",
     "contacts",
     "contact network: mean contact number Z, rattler fraction, contacts per particle",
     VoxelGrid::None,
     {},
     "",
     stages::runContacts,
     nullptr},
    {Analysis::StructureFactor,
     "sq",
     "structure_factor",
     "structure factor S(Q) of the centroids (Eq. 4)",
     VoxelGrid::None,
     {},
     "",
     stages::runStructureFactor,
     stages::structureFactorMemory},
    {Analysis::SpectralDensity, "chi", "spectral_density",
     "spectral density chi_V(Q) from the voxels by FFT (Eq. 12); exact too for spheres",
     VoxelGrid::Spectral, kSpectralNeeds, "", stages::runSpectralDensity,
     stages::spectralDensityMemory},
    {Analysis::Voxels,
     "voxels",
     "voxelization",
     "voxelization on the --voxels grid: phi_voxel against phi",
     VoxelGrid::Spectral,
     {},
     ".vdb",
     stages::runVoxels,
     stages::voxelsMemory},
    {Analysis::PoreSizes,
     "pores",
     "pore_size",
     "pore sizes F(delta), <delta>, <delta^2> (Eqs. 13-15) by --pores: on the --pore-voxels "
     "grid by exact periodic distance transform (voxel), refined to the surfaces, or exact",
     VoxelGrid::Pore,
     {},
     "-pore-size.vdb",
     stages::runPoreSizes,
     stages::poreSizesMemory},
    {Analysis::Transport, "transport", "transport",
     "permeability k, survival time tau, relaxation time T1 from the pore sizes (Eqs. 16-20)",
     VoxelGrid::None, kTransportNeeds, "", stages::runTransport, nullptr},
    {Analysis::Hyperuniformity, "hyper", "spreadability",
     "excess spreadability E(t), alpha from its long-time decay, the fit a0 + a1 Q^alpha and H "
     "(Eqs. 21-23, fit, HX), the Debye medium; chi_V exact at Q w <= --chi-exact-qmax",
     VoxelGrid::Spectral, kHyperuniformityNeeds, "", stages::runHyperuniformity, nullptr,
     stages::poolSpreadability},
}};

} // namespace

const AnalysisInfo* analysisOfGroup(std::string_view group) {
    for (const AnalysisInfo& info : kRegistry)
        if (info.group == group) return &info;
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
                addWithNeeds(info.analysis, set);
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

#include "pipeline/analysis_registry.hpp"

#include <array>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr std::array<Analysis, 1> kSpectralNeeds{Analysis::Voxels};
constexpr std::array<Analysis, 1> kTransportNeeds{Analysis::PoreSizes};

constexpr std::array<AnalysisInfo, 6> kRegistry{{
    {Analysis::Contacts,
     "contacts",
     "contact network: mean contact number Z, rattler fraction, contacts per particle",
     VoxelGrid::None,
     {}},
    {Analysis::StructureFactor,
     "sq",
     "structure factor S(Q) of the centroids (Eq. 4)",
     VoxelGrid::None,
     {}},
    {Analysis::SpectralDensity, "chi",
     "spectral density chi_V(Q) from the voxels by FFT (Eq. 12); exact too for spheres",
     VoxelGrid::Spectral, kSpectralNeeds},
    {Analysis::Voxels,
     "voxels",
     "voxelization on the --voxels grid: phi_voxel against phi",
     VoxelGrid::Spectral,
     {}},
    {Analysis::PoreSizes,
     "pores",
     "pore sizes on the --pore-voxels grid by exact periodic distance transform: F(delta), "
     "<delta>, <delta^2> (Eqs. 13-15)",
     VoxelGrid::Pore,
     {}},
    {Analysis::Transport, "transport",
     "permeability k, survival time tau, relaxation time T1 from the pore sizes (Eqs. 16-20)",
     VoxelGrid::None, kTransportNeeds},
}};

void addWithNeeds(Analysis analysis, AnalysisSet& set) {
    if (!set.insert(analysis).second) return;
    for (Analysis need : analysisInfo(analysis).needs)
        addWithNeeds(need, set);
}

std::string knownNames() {
    std::string names;
    for (const AnalysisInfo& info : kRegistry)
        names += std::string(info.name) + ", ";
    return names + "all";
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
            continue;
        }
        const AnalysisInfo* found = nullptr;
        for (const AnalysisInfo& info : kRegistry)
            if (info.name == name) found = &info;
        if (found == nullptr)
            throw std::invalid_argument("option --compute: " +
                                        (name.empty()
                                             ? std::string("empty analysis name")
                                             : "unknown analysis '" + std::string(name) + "'") +
                                        " (known: " + knownNames() + ")");
        addWithNeeds(found->analysis, set);
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

} // namespace sbpack

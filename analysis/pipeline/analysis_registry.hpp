#pragma once
// The analyses sbanalyze can run, by the names of --compute, with what each needs.

#include <set>
#include <span>
#include <string>
#include <string_view>

namespace sbpack {

enum class Analysis {
    Contacts,        ///< contact network, Z and rattlers (common/contacts)
    StructureFactor, ///< S(Q) from the centroids
    SpectralDensity, ///< chi_V(Q) from the voxels (and exactly, for spheres)
    Voxels,          ///< the voxelization: phi_voxel against phi, optional .vdb export
    PoreSizes,       ///< pore-size distribution F(delta) from the periodic distance transform
    Transport,       ///< k, tau, T1 from the pore-size moments (diffusion-controlled limit)
};

/// Which voxel grid an analysis works on: none, the spectral grid (--voxels, default 300 as the
/// paper's chi) or the pore grid (--pore-voxels, default 500 as the paper's pore sizes).
enum class VoxelGrid { None, Spectral, Pore };

struct AnalysisInfo {
    Analysis analysis;
    std::string_view name;        ///< as in --compute
    std::string_view description; ///< one line for --help
    VoxelGrid grid;
    std::span<const Analysis> needs; ///< analyses whose results it uses
};

/// Every analysis, in the order they run and are reported.
std::span<const AnalysisInfo> analysisRegistry();
const AnalysisInfo& analysisInfo(Analysis analysis);

/// The analyses to run: those named and, recursively, what they need.
using AnalysisSet = std::set<Analysis>;

/// Resolves a comma-separated list of names ("all" for every analysis). Throws
/// std::invalid_argument naming an unknown or empty entry and listing the known names.
AnalysisSet resolveAnalyses(std::string_view list);

/// The names of `set`, comma-separated, in registry order.
std::string analysisNames(const AnalysisSet& set);

} // namespace sbpack

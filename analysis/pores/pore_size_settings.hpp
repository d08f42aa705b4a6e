#pragma once
// The pores analysis's parameters (--pores, --pore-voxels, --pore-points, --pore-seed), declared
// once with their defaults; the option table, --help, Python and the results' provenance read
// them (docs/architecture.md, "Options").

#include "pores/exact_pore_size.hpp"
#include "pores/pore_size_distribution.hpp"

#include <cstdint>
#include <optional>

namespace sbpack {

struct PoreSizeSettings {
    /// --pores; absent: kDefaultMethod, or what the run implies (RunSettings::poreMethod)
    std::optional<PoreMethod> method;
    /// --pore-voxels, M of the pore grid; absent: the method's (defaultVoxels)
    std::optional<int> voxels;
    /// --pore-points K; 0: the method's sample (every void voxel; exact: exactParameters())
    std::int64_t points = 0;
    std::uint64_t seed = PoreSizeParameters{}.seed; ///< --pore-seed, of the random points

    /// Refined: within 0.1 % of the exact pore sizes at M = 200 (docs/design.md §5).
    static constexpr PoreMethod kDefaultMethod = PoreMethod::Refined;
    /// The pore grid's M by method: the paper's 500 for voxel (Sec. III B), else 200, where
    /// refined is within 0.1 % of exact (docs/design.md §5).
    static constexpr int defaultVoxels(PoreMethod m) { return m == PoreMethod::Voxel ? 500 : 200; }

    /// M of the pore grid of `method`: --pore-voxels or the method's default.
    int gridVoxels(PoreMethod m) const { return voxels.value_or(defaultVoxels(m)); }
    /// The voxel and refined methods' sample.
    PoreSizeParameters gridParameters() const {
        PoreSizeParameters p;
        p.randomPoints = points;
        p.seed = seed;
        return p;
    }
    /// The exact method's sample: K points, the paper's 10^6 unless --pore-points.
    ExactPoreSizeParameters exactParameters() const {
        ExactPoreSizeParameters p;
        if (points > 0) p.randomPoints = points;
        p.seed = seed;
        return p;
    }
};

} // namespace sbpack

#pragma once
// The results group of pores, declared once (schema/field_table.hpp, docs/results-schema.md):
// the pore-size distribution and how its grid was made.

#include "parallel/distribution_figures.hpp"
#include "pores/pore_size_distribution.hpp"
#include "schema/field_table.hpp"

#include <optional>

namespace sbpack {

/// What the pores group records: the distribution, the time of its pore-size map (voxel and
/// refined) and the figures of a distributed grid.
struct PoreSizeFigures {
    PoreSizeDistributionResult pores;
    std::optional<double> mapSeconds;
    std::optional<DistributionFigures> distribution;
};

namespace pore_size_fields {
using namespace schema::columns;
using R = PoreSizeFigures;
using P = PoreSizeDistributionResult;
inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 11>{{
        {{"mean", A, F, "length", "<delta> (Eq. 14)"}, member<&R::pores, &P::mean>},
        {{"second_moment", A, F, "length^2", "<delta^2> (Eq. 15)"},
         member<&R::pores, &P::secondMoment>},
        {{"max", A, F, "length",
          "largest pore size: voxel, the sample's; refined and exact, a local maximum of the "
          "distance to the nearest surface (Nelder-Mead from the 16 largest sample points)"},
         member<&R::pores, &P::max>},
        {{"mean_w", A, F, "1", "<delta> / w", Mean}, member<&R::pores, &P::meanOverWidth>},
        {{"second_moment_w2", A, F, "1", "<delta^2> / w^2", Mean},
         member<&R::pores, &P::secondMomentOverWidth2>},
        {{"max_w", A, F, "1", "largest pore size / w", Mean}, member<&R::pores, &P::maxOverWidth>},
        {{"saturated", A, I, "1", "1 if max < w / 2 (the paper's check), else 0"},
         member<&R::pores, &P::saturated>},
        {{"voxels", A, I, "1", "M of the pore grid (--pore-voxels); 0 for exact"},
         member<&R::pores, &P::voxels>},
        {{"voxel_size", A, F, "length", "a = L / M; 0 for exact"},
         member<&R::pores, &P::voxelSize>},
        {{"samples", A, I, "1", "void voxels or random void points in the statistics"},
         member<&R::pores, &P::samples>},
        {{"method", A, S, "",
          "\"voxels\", \"random voxels\" (--pore-points), \"refined\", \"random voxels refined\" "
          "or \"exact\" (--pores)"},
         member<&R::pores, &P::method>},
    }},
    distributionColumns<&R::distribution>(),
    std::array<schema::Column<R>, 15>{{
        {{"runtime_s", A, F, "s",
          "wall-clock time of the statistics over the pore-size map or points"},
         member<&R::pores, &P::runtimeSeconds>},
        {{"map_s", A, F, "s",
          "voxel and refined: wall-clock time of the pore grid's voxelization and distance "
          "transform",
          No, true},
         member<&R::mapSeconds>},
        {{"max_sampled", A, F, "length", "refined and exact: the sample's largest pore size", No,
          true},
         finite<&R::pores, &P::maxSampled>},
        {{"max_upper_bound", A, F, "length",
          "refined over every void voxel: certified bound max <= max_sampled + sqrt(3)/2 a (the "
          "pore size is 1-Lipschitz)",
          No, true},
         finite<&R::pores, &P::maxUpperBound>},
        {{"error_bound", A, F, "length",
          "refined and exact: largest certified |pore size - distance to the nearest surface| of "
          "a sample point (support-function bound)",
          No, true},
         finite<&R::pores, &P::errorBound>},
        {{"mean_stderr", A, F, "length",
          "random samples (exact, --pore-points): standard error of mean, sd(delta) / sqrt(K)", No,
          true},
         finite<&R::pores, &P::meanStandardError>},
        {{"second_moment_stderr", A, F, "length^2",
          "random samples: standard error of second_moment, sd(delta^2) / sqrt(K)", No, true},
         finite<&R::pores, &P::secondMomentStandardError>},
        {{"bin_width", A, F, "length",
          "refined: F and P binned at a / 256 (F exact at the bin edges delta[j])", No, true},
         finite<&R::pores, &P::binWidth>},
        {{"delta", D, F, "length",
          "pore sizes, delta[0] = 0 (refined: the bin edges and the largest)"},
         member<&R::pores, &P::delta>},
        {{"F", D, F, "1",
          "F(delta) (Eq. 13), right-continuous steps: fraction of the void with pore size > "
          "delta[j]",
          Steps, false, "delta_w"},
         member<&R::pores, &P::F>},
        {{"delta_w", D, F, "1", "delta / w"}, member<&R::pores, &P::deltaOverWidth>},
        {{"P_delta", D, F, "length", "bin centres of the density P(delta)"},
         member<&R::pores, &P::densityDelta>},
        {{"P", D, F, "1/length", "P(delta), integrates to 1"}, member<&R::pores, &P::density>},
        {{"P_delta_w", D, F, "1", "P_delta / w"}, member<&R::pores, &P::densityDeltaOverWidth>},
        {{"P_w", D, F, "1", "P(delta) w, the density of delta / w"},
         member<&R::pores, &P::densityTimesWidth>},
    }})};
} // namespace pore_size_fields

inline constexpr schema::Group kPoreSizeGroup{
    "pore_size", "files/<i>/pore_size",
    "pore sizes (pores) by --pores: on the --pore-voxels grid (voxel, refined) or without voxels "
    "(exact)",
    pore_size_fields::kTable.fields()};

} // namespace sbpack

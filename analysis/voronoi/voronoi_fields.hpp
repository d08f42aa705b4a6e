#pragma once
// The results group of voronoi, declared once (schema/field_table.hpp, docs/results-schema.md):
// the set-Voronoi cells and local packing fractions of voronoi/set_voronoi.hpp
// (docs/local-structure.md §1).

#include "schema/field_table.hpp"
#include "voronoi/set_voronoi.hpp"

namespace sbpack {

namespace voronoi_fields {
using namespace schema::columns;
using R = SetVoronoiResult;
using L = LocalPhiMoments;

/// The moments of the local phi over one set of particles (`suffix` names it; `set` says which).
template <auto Part>
constexpr std::array<schema::Column<R>, 2> partColumns(std::string_view mean, std::string_view sd,
                                                       std::string_view set) {
    return {{
        {{mean, A, F, "1", set, Mean, true}, schema::inside<Part, &L::mean>},
        {{sd, A, F, "1", "sample standard deviation of the same local phi", Mean, true},
         schema::inside<Part, &L::sd>},
    }};
}

inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 5>{{
        {{"local_phi_mean", A, F, "1", "mean local packing fraction phi_i = v_i / v_cell(i)", Mean},
         member<&R::all, &L::mean>},
        {{"local_phi_sd", A, F, "1", "sample standard deviation of phi_i over the particles", Mean},
         member<&R::all, &L::sd>},
        {{"local_phi_harmonic_mean", A, F, "1",
          "N / sum 1 / phi_i: of identical particles N v1 / sum v_cell, the packing's phi (the "
          "cells tile the box)",
          Mean},
         member<&R::all, &L::harmonicMean>},
        {{"local_phi_min", A, F, "1", "smallest phi_i", Mean}, member<&R::all, &L::min>},
        {{"local_phi_max", A, F, "1", "largest phi_i", Mean}, member<&R::all, &L::max>},
    }},
    partColumns<&R::nonRattlers>("local_phi_mean_non_rattlers", "local_phi_sd_non_rattlers",
                                 "mean phi_i over the non-rattlers (contacts resolved only)"),
    partColumns<&R::rattlers>("local_phi_mean_rattlers", "local_phi_sd_rattlers",
                              "mean phi_i over the rattlers (where there are any)"),
    std::array<schema::Column<R>, 9>{{
        {{"voxel_error_rms", A, F, "1",
          "rms over the particles of (solid voxels a^3 / v_i - 1): the voxel rounding of the "
          "surfaces the cells are measured from (docs/local-structure.md §1)",
          Mean},
         member<&R::voxelErrorRms>},
        {{"tiling_error", A, F, "1", "sum of the cells / L^3 - 1: zero but for rounding"},
         member<&R::tilingError>},
        {{"voxels", A, I, "1", "M of the grid (--voxels)"}, member<&R::voxels>},
        {{"voxel_size", A, F, "length", "a = L / M"}, member<&R::voxelSize>},
        {{"runtime_s", A, F, "s", kRuntime}, member<&R::runtimeSeconds>},
        {{"local_phi", D, F, "1", "phi_i per particle, in the packing's order"},
         member<&R::localPhi>},
        {{"cell_volume", D, F, "length^3", "set-Voronoi cell volume v_cell(i) per particle"},
         member<&R::cellVolumes>},
        {{"phi_bins", D, F, "1", "bin centres of the density of phi_i, 200 bins over [0, 1]", Same},
         member<&R::histogramPhi>},
        {{"phi_density", D, F, "1", "density of phi_i over all particles (integrates to 1)",
          Pointwise},
         member<&R::histogramDensity>},
    }})};
} // namespace voronoi_fields

inline constexpr schema::Group kVoronoiGroup{
    "voronoi", "files/<i>/voronoi",
    "set-Voronoi cells and local packing fractions (voronoi; docs/local-structure.md)",
    voronoi_fields::kTable.fields()};

} // namespace sbpack

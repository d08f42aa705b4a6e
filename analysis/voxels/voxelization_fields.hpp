#pragma once
// The results group of voxels, declared once (schema/field_table.hpp, docs/results-schema.md):
// the spectral grid's figures, from a whole, distributed or GPU voxelization.

#include "parallel/distribution_figures.hpp"
#include "schema/field_table.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace sbpack {

/// The figures every voxelization records.
struct VoxelFigures {
    int voxels = 0;
    double phiVoxel = 0.0, phiExact = 0.0, voxelSize = 0.0;
    std::int64_t solidVoxels = 0;
    std::int64_t memoryBytes = 0;
    double runtimeSeconds = 0.0;
    std::optional<std::string> vdbFile; ///< with --vdb: the exported file
    std::optional<DistributionFigures> distribution;
};

namespace voxelization_fields {
using namespace schema::columns;
using R = VoxelFigures;
inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 7>{{
        {{"voxels", A, I, "1", "M of the M^3 grid (--voxels)"}, member<&R::voxels>},
        {{"phi_voxel", A, F, "1", "fraction of solid voxels (centre inside a particle)", Mean},
         member<&R::phiVoxel>},
        {{"phi_exact", A, F, "1", "N v1 / L^3", Mean}, member<&R::phiExact>},
        {{"voxel_size", A, F, "length", "a = L / M"}, member<&R::voxelSize>},
        {{"solid_voxels", A, I, "1", "solid voxels"}, member<&R::solidVoxels>},
        {{"memory_bytes", A, I, "bytes", "memory of the OpenVDB tree"}, member<&R::memoryBytes>},
        {{"vdb_file", A, S, "", "with --vdb: the exported .vdb file", No, true},
         member<&R::vdbFile>},
    }},
    distributionColumns<&R::distribution>(),
    std::array<schema::Column<R>, 1>{{
        {{"runtime_s", A, F, "s", kRuntime}, member<&R::runtimeSeconds>},
    }})};
} // namespace voxelization_fields

inline constexpr schema::Group kVoxelizationGroup{"voxelization", "files/<i>/voxelization",
                                                  "the --voxels grid (voxels)",
                                                  voxelization_fields::kTable.fields()};

} // namespace sbpack

#pragma once
// The figures of a grid distributed over MPI ranks (--distribute grids; docs/scale-out.md) and
// their columns, which every grid's results group has (schema/field_table.hpp).

#include "schema/field_table.hpp"

#include <array>
#include <optional>

namespace sbpack {

/// What a distributed grid computation costs per rank: the figures that transfer from one
/// machine to a cluster (docs/scale-out.md, "Plan"); wall times do not.
struct DistributionFigures {
    int ranks = 1;
    int slab = 0;                    ///< x-planes of the largest rank's slab
    double memoryPerRankBytes = 0.0; ///< the largest rank's grid memory (measured allocations)
    double communicationBytes = 0.0; ///< sent from one rank to another, all ranks together
};

/// ranks, slab, memory_per_rank_bytes and communication_bytes of the std::optional
/// DistributionFigures member `Figures`: written for a distributed grid only.
template <auto Figures>
constexpr std::array<schema::Column<schema::detail::OwnerOf<Figures>>, 4> distributionColumns() {
    using namespace schema::columns;
    using D = DistributionFigures;
    return {{
        {{"ranks", A, I, "1", "--distribute grids only: ranks sharing the grid's x-slabs", No,
          true},
         schema::inside<Figures, &D::ranks>},
        {{"slab", A, I, "1", "--distribute grids only: x-planes of the largest rank's slab", No,
          true},
         schema::inside<Figures, &D::slab>},
        {{"memory_per_rank_bytes", A, F, "bytes",
          "--distribute grids only: the largest rank's grid memory (its allocations)", No, true},
         schema::inside<Figures, &D::memoryPerRankBytes>},
        {{"communication_bytes", A, F, "bytes",
          "--distribute grids only: bytes sent from rank to rank, all ranks together", No, true},
         schema::inside<Figures, &D::communicationBytes>},
    }};
}

} // namespace sbpack

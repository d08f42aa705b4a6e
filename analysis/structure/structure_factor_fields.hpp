#pragma once
// The results group of sq, declared once (schema/field_table.hpp, docs/results-schema.md).

#include "schema/field_table.hpp"
#include "shells/shell_columns.hpp"
#include "structure/structure_factor.hpp"

namespace sbpack {

namespace structure_factor_fields {
using namespace schema::columns;
using R = StructureFactorResult;
using Partials = PartialStructureFactors;
inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 7>{{
        {{"qmax", A, F, "1", "shells up to Q w <= qmax (--qmax)"},
         schema::member<&R::parameters, &StructureFactorParameters::maxQw>},
        {{"max_shell", A, I, "1", "number of shells"}, schema::member<&R::maxShell>},
        {{"runtime_s", A, F, "s", kRuntime}, schema::member<&R::runtimeSeconds>},
        {{.name = "x_A",
          .kind = A,
          .type = F,
          .units = "1",
          .description = "a binary mixture's number fraction of large particles (docs/mixtures.md)",
          .reduce = Mean,
          .optional = true},
         schema::inside<&R::partials, &Partials::fractionA>},
        {{.name = "S_AA",
          .kind = D,
          .type = F,
          .units = "1",
          .description = "a binary mixture's partial S(Q) of the large particles, "
                         "|rho_A(Q)|^2 / N_A (Ashcroft-Langreth), on S's shells",
          .reduce = Curve,
          .optional = true},
         schema::inside<&R::partials, &Partials::aa>},
        {{.name = "S_BB",
          .kind = D,
          .type = F,
          .units = "1",
          .description =
              "a binary mixture's partial S(Q) of the small particles, |rho_B(Q)|^2 / N_B",
          .reduce = Curve,
          .optional = true},
         schema::inside<&R::partials, &Partials::bb>},
        {{.name = "S_AB",
          .kind = D,
          .type = F,
          .units = "1",
          .description = "a binary mixture's cross term Re(rho_A rho_B*) / sqrt(N_A N_B); S = "
                         "x_A S_AA + x_B S_BB + 2 sqrt(x_A x_B) S_AB",
          .reduce = Curve,
          .optional = true},
         schema::inside<&R::partials, &Partials::ab>},
    }},
    shellColumns<&R::shells>(
        {"S", D, F, "1", "S(Q), shell average of |sum_j exp(-i Q.r_j)|^2 / N (Eq. 4)", Curve}))};
} // namespace structure_factor_fields

inline constexpr schema::Group kStructureFactorGroup{
    "structure_factor", "files/<i>/structure_factor", "S(Q) of the centroids (sq)",
    structure_factor_fields::kTable.fields()};

} // namespace sbpack

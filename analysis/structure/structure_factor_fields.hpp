#pragma once
// The results group of sq, declared once (schema/field_table.hpp, docs/results-schema.md).

#include "schema/field_table.hpp"
#include "shells/shell_columns.hpp"
#include "structure/structure_factor.hpp"

namespace sbpack {

namespace structure_factor_fields {
using namespace schema::columns;
using R = StructureFactorResult;
inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 3>{{
        {{"qmax", A, F, "1", "shells up to Q w <= qmax (--qmax)"},
         schema::member<&R::parameters, &StructureFactorParameters::maxQw>},
        {{"max_shell", A, I, "1", "number of shells"}, schema::member<&R::maxShell>},
        {{"runtime_s", A, F, "s", kRuntime}, schema::member<&R::runtimeSeconds>},
    }},
    shellColumns<&R::shells>(
        {"S", D, F, "1", "S(Q), shell average of |sum_j exp(-i Q.r_j)|^2 / N (Eq. 4)", Curve}))};
} // namespace structure_factor_fields

inline constexpr schema::Group kStructureFactorGroup{
    "structure_factor", "files/<i>/structure_factor", "S(Q) of the centroids (sq)",
    structure_factor_fields::kTable.fields()};

} // namespace sbpack

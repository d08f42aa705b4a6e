#pragma once
// The columns of a shell-averaged curve in a results table (schema/field_table.hpp): Q, the
// curve's value, the wave vectors per shell and Q w, read from a ShellAverage member.

#include "schema/field_table.hpp"
#include "shells/shell_average.hpp"

#include <array>

namespace sbpack {

/// Q, `value` (the curve: its name, units, description and Reduce::Curve), count and Q_w of the
/// ShellAverage reached through `Shells`.
template <auto... Shells>
constexpr std::array<schema::Column<schema::detail::OwnerOf<Shells...>>, 4>
shellColumns(schema::Field value) {
    using namespace schema::columns;
    return {{
        {{"Q", D, F, "1/length", "mean |Q| of the shell's wave vectors Q = 2 pi n / L"},
         schema::member<Shells..., &ShellAverage::q>},
        {value, schema::member<Shells..., &ShellAverage::value>},
        {{"count", D, I, "1", "wave vectors in the shell"},
         schema::member<Shells..., &ShellAverage::count>},
        {{"Q_w", D, F, "1", "Q times the mean width"},
         schema::perWidth<-1, Shells..., &ShellAverage::q>},
    }};
}

} // namespace sbpack

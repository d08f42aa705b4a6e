#include "schema/packing_schema_docs.hpp"

#include "io/packing_schema.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sbpack::schema {

namespace {

constexpr std::string_view kIntroduction = R"(# sbpack packing file

Generated from `common/io/packing_schema.cpp` by `sbanalyze schema --packing --markdown`; do not
edit (the test `packing_schema_doc_is_current` fails when this file and the table differ).
`sbanalyze schema --packing --json` prints this table for programs.

The packing file is HDF5 (docs/design.md §4): sbgen writes its packings and checkpoints in it,
`sbanalyze convert` and Python's `Packing.write` write it too, and every tool reads it
(`common/io/packing_io.cpp`, by the names of the table). A reader refuses a file that lacks a
required entry, has another `format` or `format_version`, or holds no valid packing, with a
message that names the file and the problem; an entry marked *optional* is written only when the
packing has it. The attributes sbgen keeps in `provenance` and `resume_state` are declared in its
own table, `generator/protocol/checkpoint_entries` (docs/design.md §4).

## Units

Only the datasets of `contact_forces` carry their units, as a string attribute `units` (the
column below). `1` dimensionless; `length` the packing's length unit (that of `box_length`);
`time` sbgen's unit of time, `length sqrt(m / kT)` with `m = kT = 1` (docs/design.md §3); `kT/D`
a force in units of kT over the major-axis length `D = 2 semi_axis`, `kT` an energy (a torque),
with kT the kinetic temperature of the windows the forces average over (docs/jamming.md,
"Contact forces from the run").

## Versions

`since` is the `format_version` that introduced an entry. The version has been 1 throughout: the
entries added later (`resume_state` and its pair records, `contact_forces`) are optional, and
where an earlier file kept an entry under another name the reader moves it (the rows of "Earlier
names").
)";

std::string_view kindName(PackingKind kind) {
    if (kind == PackingKind::Group) return "group";
    return kind == PackingKind::Attribute ? "attribute" : "dataset";
}

std::string_view typeName(PackingType type) {
    switch (type) {
    case PackingType::Float64:
        return "float64";
    case PackingType::Int64:
        return "int64";
    case PackingType::UInt64:
        return "uint64";
    case PackingType::String:
        return "string";
    case PackingType::None:
        break;
    }
    return "";
}

std::string path(const PackingEntry& e) {
    return e.group.empty() ? std::string(e.name) : fmt::format("{}/{}", e.group, e.name);
}

/// "N x 3" for a dataset, "" otherwise.
std::string shape(const PackingEntry& e) {
    return e.kind == PackingKind::Dataset ? fmt::format("{} x {}", e.rows, e.columns) : "";
}

std::string code(std::string_view text) {
    return text.empty() ? "" : fmt::format("`{}`", text);
}

std::string entriesTable() {
    std::string out = "\n## Entries\n\n| name | kind | type | shape | units | description | "
                      "since |\n|---|---|---|---|---|---|---|\n";
    for (const PackingEntry& e : packingEntries())
        out += fmt::format("| `{}` | {} | {} | {} | {} | {}{} | {} |\n", path(e), kindName(e.kind),
                           typeName(e.type), code(shape(e)), code(e.units), e.description,
                           e.optional ? " (optional)" : "", e.since);
    return out;
}

std::string migrationsTable() {
    std::string out = "\n## Earlier names\n\nMoved on reading, in a file of that `format_version` "
                      "without the new group.\n\n| format_version | old name | new name | why "
                      "|\n|---|---|---|---|\n";
    for (const PackingMigration& m : packingMigrations())
        out += fmt::format("| {} | `{}/{}*` | `{}/*` | {} |\n", m.version, m.fromGroup,
                           m.fromPrefix, m.toGroup, m.description);
    return out;
}

} // namespace

std::string packingSchemaMarkdown() {
    return std::string(kIntroduction) + entriesTable() + migrationsTable();
}

std::string packingSchemaJson() {
    nlohmann::ordered_json entries = nlohmann::ordered_json::array();
    for (const PackingEntry& e : packingEntries())
        entries.push_back({{"name", path(e)},
                           {"kind", kindName(e.kind)},
                           {"type", typeName(e.type)},
                           {"shape", shape(e)},
                           {"units", e.units},
                           {"description", e.description},
                           {"optional", e.optional},
                           {"since", e.since}});
    nlohmann::ordered_json migrations = nlohmann::ordered_json::array();
    for (const PackingMigration& m : packingMigrations())
        migrations.push_back({{"format_version", m.version},
                              {"old_name", fmt::format("{}/{}*", m.fromGroup, m.fromPrefix)},
                              {"new_name", fmt::format("{}/*", m.toGroup)},
                              {"description", m.description}});
    const nlohmann::ordered_json root = {{"format", kPackingFormat},
                                         {"format_version", kPackingFormatVersion},
                                         {"entries", std::move(entries)},
                                         {"migrations", std::move(migrations)}};
    return root.dump(2) + '\n';
}

} // namespace sbpack::schema

// docs/results-schema.md and the JSON form of the schema, both generated from the table.
#include "schema/results_schema.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sbpack::schema {

namespace {

constexpr std::string_view kIntroduction = R"(# sbanalyze results file

Generated from `analysis/schema/results_schema.cpp` by `sbanalyze schema --markdown`; do not
edit (the test `results_schema_doc_is_current` fails when this file and the table differ).
The JSON summary (`--json`) has the same names: per file and per ensemble every attribute below,
and for each curve its number of `shells` and its `peak` (`Q_w`, `value`); datasets are in the
HDF5 file only. `sbanalyze schema --json` prints this table for programs.

## Layout

```
/                          the run (attributes)
files/<i>/                 input i = 0, 1, ... (attributes), in the order given
files/<i>/<group>/         one group per analysis run (attributes and datasets)
ensembles/<k>/             inputs of equal p and N (attributes, dataset members)
ensembles/<k>/<group>/     the statistics of files/<i>/<group> over the members
```

One input or many: the same layout (one input makes `files/0` and `ensembles/0`). Inputs that
differ in `p` or `N` are never averaged together: each (p, N) is its own ensemble, numbered in the
order of its first input, and sbanalyze warns when there is more than one. A group is present
only when its analysis ran (`transport` is skipped, with a warning, where the paper's `zeta_2`
interpolation leaves (0, 1]); a field marked *optional* only in the case its description gives,
every other field always (sbanalyze refuses to write a group that lacks one). The packing file's
schema is docs/packing-schema.md.

## Units

Every dataset has a string attribute `units`; every numeric attribute `NAME` has a string
attribute `NAME_units`. Units: `1` dimensionless; `length` the packing's length unit (that of
`box_length`); `1/length`, `length^2`, `length^3`; `D` the major-axis length `2 semi_axis`;
`time` the unit of the transport times (`length^2 / diffusion_coefficient`); `length^2/time`;
`s` wall-clock seconds; `bytes`.
)";

std::string_view kindName(Kind kind) {
    return kind == Kind::Attribute ? "attribute" : "dataset";
}

std::string_view typeName(const Field& f) {
    if (f.type == Type::String) return "string";
    return f.type == Type::Float ? "float64" : "int64";
}

std::string table(const Group& group) {
    std::string out = fmt::format("\n### `{}`: {}\n\n", group.path, group.title);
    out += "| name | kind | type | units | description |\n|---|---|---|---|---|\n";
    for (const Field& f : group.fields)
        out += fmt::format("| `{}` | {} | {} | {} | {}{} |\n", f.name, kindName(f.kind),
                           typeName(f), f.units.empty() ? "" : fmt::format("`{}`", f.units),
                           f.description, f.optional ? " (optional)" : "");
    return out;
}

nlohmann::ordered_json groupJson(const Group& group) {
    nlohmann::ordered_json fields = nlohmann::ordered_json::array();
    for (const Field& f : group.fields)
        fields.push_back({{"name", f.name},
                          {"kind", kindName(f.kind)},
                          {"type", typeName(f)},
                          {"units", f.units},
                          {"description", f.description},
                          {"optional", f.optional}});
    return {{"path", group.path}, {"title", group.title}, {"fields", std::move(fields)}};
}

} // namespace

std::string schemaMarkdown() {
    std::string out(kIntroduction);
    out += "\n## Groups\n";
    out += table(runGroup());
    out += table(fileGroup());
    for (const Group& g : analysisGroups())
        out += table(g);
    out += "\n## Ensembles\n\nMean and sample standard deviation over the members that have the "
           "group; curves on a common grid in `Q w`.\n";
    out += table(ensembleRootGroup());
    for (const Group& g : analysisGroups())
        if (ensembleGroup(g.name).fields.size() > 1) out += table(ensembleGroup(g.name));
    return out;
}

std::string schemaJson() {
    nlohmann::ordered_json groups = nlohmann::ordered_json::array();
    groups.push_back(groupJson(runGroup()));
    groups.push_back(groupJson(fileGroup()));
    for (const Group& g : analysisGroups())
        groups.push_back(groupJson(g));
    groups.push_back(groupJson(ensembleRootGroup()));
    for (const Group& g : analysisGroups())
        groups.push_back(groupJson(ensembleGroup(g.name)));
    const nlohmann::ordered_json root = {{"format", kFormat},
                                         {"format_version", kFormatVersion},
                                         {"units_attribute", kDatasetUnits},
                                         {"attribute_units_suffix", "_units"},
                                         {"groups", std::move(groups)}};
    return root.dump(2) + '\n';
}

} // namespace sbpack::schema

// Results groups as Python dicts: the schema's names (docs/results-schema.md), datasets as numpy
// arrays; and sbpack._sbpack.schema_json() for readers.
#include "bindings.hpp"

#include "pipeline/analysis_registry.hpp"
#include "schema/results_schema.hpp"

#include <pybind11/numpy.h>

#include <variant>

namespace sbpack::python {

namespace {

/// One dimension, or rows of `width` values (schema::Field::width: n x 3), as in the file.
template <class T> py::array_t<T> toArray(const std::vector<T>& values, int width) {
    const auto n = static_cast<py::ssize_t>(values.size());
    py::array_t<T> a =
        width > 0 ? py::array_t<T>({n / width, py::ssize_t{width}}) : py::array_t<T>(n);
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}

py::object toPython(const schema::Value& value, int width) {
    return std::visit(
        [width](const auto& v) -> py::object {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, std::vector<double>> ||
                          std::is_same_v<T, std::vector<std::int64_t>>)
                return toArray(v, width);
            else
                return py::cast(v);
        },
        value);
}

} // namespace

py::dict recordToDict(const schema::Record& record) {
    py::dict d;
    for (const schema::Entry& e : record.entries())
        d[py::str(std::string(e.field->name))] = toPython(e.value, e.field->width);
    return d;
}

void registerResults(py::module_& m) {
    m.def(
        "schema_json", [] { return schema::schemaJson(resultGroups()); },
        "The results schema (groups, names, units) as JSON, as `sbanalyze schema --json`");
}

} // namespace sbpack::python

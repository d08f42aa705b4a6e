#include "schema/shape_record.hpp"

#include <string>
#include <vector>

namespace sbpack::schema {

void setShape(Record& record, const ShapeSpec& shape) {
    const ShapeFamily& family = shape.info();
    if (family.name != shapeFamilies().front().name) record.set("shape", std::string(family.name));
    const std::vector<double> values = shape.values();
    for (std::size_t k = 0; k < values.size(); ++k)
        record.set(family.parameters[k].name, values[k]);
}

ShapeSpec shapeOf(const Record& record) {
    const std::string name =
        record.has("shape") ? record.text("shape") : std::string(shapeFamilies().front().name);
    const ShapeFamily* family = findShapeFamily(name);
    if (family == nullptr) return ShapeSpec::fromValues(name, {}); // throws, naming it
    std::vector<double> values;
    for (const ShapeParameter& parameter : family->parameters)
        values.push_back(record.number(parameter.name));
    return ShapeSpec::fromValues(name, values);
}

} // namespace sbpack::schema

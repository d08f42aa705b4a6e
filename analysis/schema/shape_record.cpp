#include "schema/shape_record.hpp"

#include <optional>
#include <string>

namespace sbpack::schema {

void setShape(Record& record, const ShapeSpec& shape) {
    if (const std::optional<std::string_view> family = shape.writtenFamily())
        record.set(kShapeFamilyKey, std::string(*family));
    for (const auto& [name, value] : shape.namedValues())
        record.set(name, value);
}

ShapeSpec shapeOf(const Record& record) {
    std::optional<std::string> family;
    if (record.has(kShapeFamilyKey)) family = record.text(kShapeFamilyKey);
    return ShapeSpec::read(family, [&](std::string_view name) { return record.number(name); });
}

} // namespace sbpack::schema

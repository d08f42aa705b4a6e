#pragma once
// The shape in a results record (files/<i>, ensembles/<k>): its family and parameters under the
// names the results schema declares from geometry/particle_shape (docs/results-schema.md).

#include "geometry/particle_shape.hpp"
#include "schema/record.hpp"

namespace sbpack::schema {

/// Sets the shape's fields: the family's name where it is not the superball, then each parameter.
void setShape(Record& record, const ShapeSpec& shape);
/// The shape those fields hold.
ShapeSpec shapeOf(const Record& record);

} // namespace sbpack::schema

#pragma once
// docs/packing-schema.md and the JSON form of the packing file's table
// (common/io/packing_schema.hpp), printed by `sbanalyze schema --packing`.

#include <string>

namespace sbpack::schema {

/// docs/packing-schema.md (`sbanalyze schema --packing --markdown`).
std::string packingSchemaMarkdown();
/// The same table as JSON (`sbanalyze schema --packing --json`).
std::string packingSchemaJson();

} // namespace sbpack::schema

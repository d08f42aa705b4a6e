// Records checked complete before they are written (schema/record.hpp; issue 45): a record
// without a field the results schema requires is refused, by the group's path and the fields'
// names, by every writer; one with every required field and no optional one is written.
#include "pipeline/analysis_registry.hpp"
#include "pipeline/results_file.hpp"
#include "pipeline/summary_json.hpp"
#include "schema/record.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {
namespace {

/// A value of the field's kind and type.
void fill(schema::Record& record, const schema::Field& f) {
    const bool scalar = f.kind == schema::Kind::Attribute;
    if (f.type == schema::Type::String)
        record.set(f.name, "x");
    else if (f.type == schema::Type::Float && scalar)
        record.set(f.name, 1.0);
    else if (scalar)
        record.set(f.name, 1);
    else if (f.type == schema::Type::Float)
        record.set(f.name, std::vector<double>{1.0});
    else
        record.set(f.name, std::vector<std::int64_t>{1});
}

/// `group` with every required field but those of `leaveOut`, and no optional field.
schema::Record required(const schema::Group& group, const std::vector<std::string>& leaveOut) {
    schema::Record record(group);
    for (const schema::Field& f : group.fields)
        if (!f.optional && std::find(leaveOut.begin(), leaveOut.end(), f.name) == leaveOut.end())
            fill(record, f);
    return record;
}

/// One input whose only analysis group is `group`.
RunResults oneFile(schema::Record group) {
    RunResults results;
    FileResults& file = results.files.emplace_back();
    file.root = required(schema::fileGroup(), {});
    file.groups.push_back(std::move(group));
    return results;
}

/// The message of the std::logic_error `write` throws ("" if none).
template <class Write> std::string refusal(Write write) {
    try {
        write();
    } catch (const std::logic_error& e) {
        return e.what();
    }
    return "";
}

const std::string kRefusal = "results schema: files/<i>/structure_factor: required fields not "
                             "set: max_shell, Q_w";

TEST(Record, AnIncompleteRecordIsRefusedByItsGroupAndTheMissingFields) {
    const schema::Group& group = *findResultGroup("structure_factor");
    const schema::Record record = required(group, {"max_shell", "Q_w"});
    EXPECT_TRUE(record.has("qmax"));
    EXPECT_EQ(refusal([&] { record.entries(); }), kRefusal);
    // Every writer: the HDF5 results file and the JSON summary (nothing written to the stream).
    const RunResults results = oneFile(record);
    const RunSettings settings;
    EXPECT_EQ(refusal([&] { resultsFileImage("r.h5", results, settings); }), kRefusal);
    std::ostringstream json;
    EXPECT_EQ(refusal([&] { writeJsonSummary(json, results, settings); }), kRefusal);
    EXPECT_TRUE(json.str().empty());
}

TEST(Record, ACompleteRecordWithoutItsOptionalFieldsIsWritten) {
    const schema::Group& group = *findResultGroup("spectral_density");
    const schema::Record record = required(group, {});
    std::size_t requiredFields = 0;
    for (const schema::Field& f : group.fields)
        requiredFields += f.optional ? 0 : 1;
    ASSERT_LT(requiredFields, group.fields.size()); // the group has optional fields
    EXPECT_EQ(record.entries().size(), requiredFields);
    const RunResults results = oneFile(record);
    const RunSettings settings;
    EXPECT_FALSE(resultsFileImage("r.h5", results, settings).empty());
    std::ostringstream json;
    writeJsonSummary(json, results, settings);
    EXPECT_NE(json.str().find("\"spectral_density\""), std::string::npos);
}

} // namespace
} // namespace sbpack

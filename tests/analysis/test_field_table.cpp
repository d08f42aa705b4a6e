// A results group declared once (schema/field_table.hpp; issue 45): a throwaway result with its
// table is found in the HDF5 results file, the JSON summary and the generated docs without any
// other declaration; the readers of a table (members, chains, accessors, w scaling, absent
// values) and the record's refusals.
#include "pipeline/analysis_registry.hpp"
#include "pipeline/results_file.hpp"
#include "pipeline/summary_json.hpp"
#include "schema/field_table.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

namespace sbpack {
namespace {

using namespace schema::columns;

struct Inner {
    double length = 3.0;
};

/// A result no analysis has: everything below is declared by its table alone.
struct ThrowawayResult {
    double answer = 42.5;
    int count = 7;
    Inner inner;
    std::vector<double> curve{1.0, 2.0, 3.0};
    std::optional<std::string> note;
    double sometimes = std::numeric_limits<double>::quiet_NaN();
    double twice() const { return 2.0 * answer; }
};

using R = ThrowawayResult;
constexpr schema::FieldTable kTable{std::array<schema::Column<R>, 8>{{
    {{"answer", A, F, "length", "the throwaway answer"}, schema::member<&R::answer>},
    {{"count", A, I, "1", "how many"}, schema::member<&R::count>},
    {{"inner_w", A, F, "1", "the inner length over w"},
     schema::perWidth<1, &R::inner, &Inner::length>},
    {{"twice", A, F, "length", "an accessor"}, schema::member<&R::twice>},
    {{"note", A, S, "", "present or not", No, true}, schema::member<&R::note>},
    {{"sometimes", A, F, "1", "finite or not written", No, true}, schema::finite<&R::sometimes>},
    {{"curve", D, F, "length", "a dataset"}, schema::member<&R::curve>},
    {{"curve_w", D, F, "1", "the dataset times w"}, schema::perWidth<-1, &R::curve>},
}}};
constexpr schema::Group kGroup{"throwaway", "files/<i>/throwaway", "a test's", kTable.fields()};

constexpr double kWidth = 0.7;

schema::Record throwawayRecord(const R& result) {
    schema::Record record(kGroup);
    kTable.fill(record, result, {kWidth});
    return record;
}

TEST(FieldTable, ReadsMembersChainsAccessorsAndScalesByTheMeanWidth) {
    const schema::Record r = throwawayRecord(R{});
    EXPECT_EQ(r.number("answer"), 42.5);
    EXPECT_EQ(r.integer("count"), 7);
    EXPECT_EQ(r.number("inner_w"), 3.0 / kWidth);
    EXPECT_EQ(r.number("twice"), 85.0);
    ASSERT_EQ(r.floats("curve_w").size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) // multiplied, bit for bit as x * w
        EXPECT_EQ(r.floats("curve_w")[i], R{}.curve[i] * kWidth);
    EXPECT_FALSE(r.has("note"));      // an empty std::optional is not written
    EXPECT_FALSE(r.has("sometimes")); // nor a NaN through finite<>
    R more;
    more.note = "here";
    more.sometimes = 0.25;
    const schema::Record full = throwawayRecord(more);
    EXPECT_EQ(full.text("note"), "here");
    EXPECT_EQ(full.number("sometimes"), 0.25);
    EXPECT_EQ(full.entries().size(), kGroup.fields.size());
}

TEST(FieldTable, ColumnsReturnToThePackingUnits) {
    // Computed on the packing in units of u = 1/4 (FileContext, docs/reliability.md "Units"):
    // lengths times u, reduced and dimensionless values as they are.
    const double u = 0.25;
    schema::Record r(kGroup);
    kTable.fill(r, R{}, {kWidth, u});
    EXPECT_EQ(r.number("answer"), 42.5 * u);
    EXPECT_EQ(r.number("twice"), 85.0 * u);
    EXPECT_EQ(r.integer("count"), 7);
    EXPECT_EQ(r.number("inner_w"), 3.0 / kWidth);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(r.floats("curve")[i], R{}.curve[i] * u);
        EXPECT_EQ(r.floats("curve_w")[i], R{}.curve[i] * kWidth);
    }
    EXPECT_EQ(schema::unitFactor("length^3", u), u * u * u);
    EXPECT_EQ(schema::unitFactor("1/length", u), 4.0);
    EXPECT_EQ(schema::unitFactor("time", u), u * u); // length^2 / diffusion_coefficient
    EXPECT_EQ(schema::unitFactor("length^2/time", u), 1.0);
    for (std::string_view reduced : {"1", "D", "w^3", "w^2/D_diff", "s", "bytes", "deg", ""})
        EXPECT_EQ(schema::unitFactor(reduced, u), 1.0) << reduced;
    EXPECT_THROW((void)schema::unitFactor("length^4", u), std::logic_error);
    // Every unit the results declare has its factor.
    for (const schema::Group* g : resultGroups())
        for (const schema::Field& f : g->fields)
            EXPECT_NO_THROW((void)schema::unitFactor(f.units, u)) << g->name << "/" << f.name;
}

TEST(FieldTable, TheRecordRefusesAFieldOfAnotherGroupAndAnIncompleteRecord) {
    schema::Record record(kGroup);
    const schema::Field copy = kGroup.fields[0]; // equal, but not the group's own
    EXPECT_THROW(record.set(copy, schema::Value(1.0)), std::logic_error);
    record.set(kGroup.fields[0], schema::Value(std::int64_t{3})); // Int into a Float field
    EXPECT_EQ(record.number("answer"), 3.0);
    EXPECT_THROW(record.set(kGroup.fields[1], schema::Value(1.5)), std::logic_error);
    try {
        (void)record.entries();
        ADD_FAILURE() << "an incomplete record was accepted";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("count, inner_w, twice, curve, curve_w"),
                  std::string::npos)
            << e.what();
    }
}

/// Reads attribute `name` of `group` in the HDF5 file `path` (NaN if absent).
double readAttribute(const std::string& path, const std::string& group, const std::string& name) {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    double value = std::numeric_limits<double>::quiet_NaN();
    if (H5Aexists_by_name(file, group.c_str(), name.c_str(), H5P_DEFAULT) > 0) {
        const hid_t a =
            H5Aopen_by_name(file, group.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
        H5Aread(a, H5T_NATIVE_DOUBLE, &value);
        H5Aclose(a);
    }
    H5Fclose(file);
    return value;
}

TEST(FieldTable, AFieldDeclaredInATableReachesTheFileTheSummaryAndTheDocs) {
    RunResults results;
    FileResults& file = results.files.emplace_back();
    file.root = schema::Record(schema::fileGroup());
    for (const schema::Field& f : schema::fileGroup().fields)
        if (f.type == schema::Type::String)
            file.root.set(f.name, "x");
        else
            file.root.set(f.name, 1);
    file.groups.push_back(throwawayRecord(R{}));
    const RunSettings settings;

    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "sbpack-field-table.h5";
    std::ofstream(path, std::ios::binary) << resultsFileImage("r.h5", results, settings);
    EXPECT_EQ(readAttribute(path, "files/0/throwaway", "answer"), 42.5);
    EXPECT_EQ(readAttribute(path, "files/0/throwaway", "count"), 7.0);
    std::filesystem::remove(path);

    std::ostringstream json;
    writeJsonSummary(json, results, settings);
    EXPECT_NE(json.str().find("\"answer\": 42.5"), std::string::npos) << json.str();

    const std::array<const schema::Group*, 1> groups{&kGroup};
    EXPECT_NE(schema::schemaMarkdown(groups).find(
                  "| `answer` | attribute | float64 | `length` | the throwaway answer |"),
              std::string::npos);
    EXPECT_NE(schema::schemaJson(groups).find("\"name\": \"curve_w\""), std::string::npos);
}

TEST(FieldTable, EveryResultsGroupHasAUniqueNameAndUniqueFields) {
    std::set<std::string_view> names;
    for (const schema::Group* g : resultGroups()) {
        EXPECT_TRUE(names.insert(g->name).second) << g->name << " declared twice";
        std::set<std::string_view> fields;
        for (const schema::Field& f : g->fields)
            EXPECT_TRUE(fields.insert(f.name).second) << g->name << "/" << f.name << " twice";
        EXPECT_EQ(findResultGroup(g->name), g);
    }
}

} // namespace
} // namespace sbpack

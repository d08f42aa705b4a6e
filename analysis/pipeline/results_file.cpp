#include "pipeline/results_file.hpp"

#include "io/hdf5_handles.hpp"
#include "pipeline/option_table.hpp"
#include "version.hpp"

#include <string>
#include <type_traits>

namespace sbpack {

namespace {

/// A dataset of `values`, one-dimensional or in rows, (float64 or int64 in the file) with its
/// units.
template <class T>
void writeVector(hid_t parent, const schema::Field& field, const std::vector<T>& values) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, std::int64_t>);
    const hid_t fileType = std::is_same_v<T, double> ? H5T_IEEE_F64LE : H5T_STD_I64LE;
    const hid_t memoryType = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64;
    const std::string name(field.name);
    // Rows of field.width values (n x 3) or one dimension (schema::Field::width).
    const auto width = static_cast<hsize_t>(field.width);
    const hsize_t dims[2] = {width > 0 ? values.size() / width : values.size(), width};
    const Hdf5Handle space(H5Screate_simple(width > 0 ? 2 : 1, dims, nullptr), H5Sclose);
    const hid_t id = H5Dcreate2(parent, name.c_str(), fileType, space.get(), H5P_DEFAULT,
                                H5P_DEFAULT, H5P_DEFAULT);
    if (id < 0) throw Hdf5Error("results file: cannot create dataset '" + name + "'");
    const Hdf5Handle dataset(id, H5Dclose);
    if (H5Dwrite(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        throw Hdf5Error("results file: cannot write dataset '" + name + "'");
    writeStringAttribute(dataset.get(), std::string(schema::kDatasetUnits),
                         std::string(field.units));
}

/// One entry: an attribute (numbers with NAME_units) or a dataset (with units).
void writeEntry(hid_t target, const schema::Entry& e) {
    const schema::Field& f = *e.field;
    const std::string name(f.name);
    if (const auto* v = std::get_if<double>(&e.value)) writeDoubleAttribute(target, name, *v);
    if (const auto* v = std::get_if<std::int64_t>(&e.value)) writeInt64Attribute(target, name, *v);
    if (const auto* v = std::get_if<std::string>(&e.value)) writeStringAttribute(target, name, *v);
    if (const auto* v = std::get_if<std::vector<double>>(&e.value)) writeVector(target, f, *v);
    if (const auto* v = std::get_if<std::vector<std::int64_t>>(&e.value))
        writeVector(target, f, *v);
    if (f.kind == schema::Kind::Attribute && f.type != schema::Type::String)
        writeStringAttribute(target, schema::unitsAttributeName(f.name), std::string(f.units));
}

void writeRecord(hid_t target, const schema::Record& record) {
    for (const schema::Entry& e : record.entries())
        writeEntry(target, e);
}

/// `parent`/<index>/ with `root`'s entries and one subgroup per record of `groups`.
void writeNumbered(hid_t parent, std::size_t index, const schema::Record& root,
                   const std::vector<schema::Record>& groups) {
    const Hdf5Handle g = createGroup(parent, std::to_string(index));
    writeRecord(g.get(), root);
    for (const schema::Record& record : groups)
        writeRecord(createGroup(g.get(), std::string(record.group().name)).get(), record);
}

} // namespace

schema::Record runRecord(const RunResults& results, const RunSettings& settings) {
    schema::Record r(schema::runGroup());
    r.set("format", schema::kFormat)
        .set("format_version", schema::kFormatVersion)
        .set("sbanalyze_version", kVersion)
        .set("compute", analysisNames(settings.analyses))
        .set("options", runOptions(settings))
        .set("threads", settings.threads)
        .set("device", settings.device.description())
        .set("ranks", results.ranks)
        .set("distribute", settings.distribute == Distribution::Grids ? "grids" : "files")
        .set("n_files", results.files.size())
        .set("n_ensembles", results.ensembles.size())
        .set("runtime_s", results.runtimeSeconds);
    return r;
}

std::string resultsFileImage(const std::string& name, const RunResults& results,
                             const RunSettings& settings) {
    Hdf5Handle h5 = createFile(name);
    writeRecord(h5.get(), runRecord(results, settings));
    {
        const Hdf5Handle files = createGroup(h5.get(), "files");
        for (std::size_t i = 0; i < results.files.size(); ++i)
            writeNumbered(files.get(), i, results.files[i].root, results.files[i].groups);
        const Hdf5Handle ensembles = createGroup(h5.get(), "ensembles");
        for (std::size_t k = 0; k < results.ensembles.size(); ++k)
            writeNumbered(ensembles.get(), k, results.ensembles[k].root,
                          results.ensembles[k].groups);
    }
    return fileImage(h5, name);
}

} // namespace sbpack

#include "pipeline/summary_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <ostream>

namespace sbpack {

namespace {

using Json = nlohmann::ordered_json;

/// The attributes of `record` (numbers and strings, not datasets), in the schema's order.
Json attributes(const schema::Record& record) {
    Json out = Json::object();
    for (const schema::Entry& e : record.entries()) {
        const std::string name(e.field->name);
        if (const auto* v = std::get_if<double>(&e.value)) out[name] = *v;
        if (const auto* v = std::get_if<std::int64_t>(&e.value)) out[name] = *v;
        if (const auto* v = std::get_if<std::string>(&e.value)) out[name] = *v;
    }
    return out;
}

/// Shells and the principal peak (largest value, at its Q w) of each curve of a file's group.
void addCurves(const schema::Record& record, Json& out) {
    for (const schema::Field& f : record.group().fields) {
        if (f.reduce != schema::Reduce::Curve || !record.has(f.name)) continue;
        const std::vector<double>& value = record.floats(f.name);
        const std::vector<double>& qw = record.floats("Q_w");
        out["shells"] = value.size();
        if (value.empty()) continue;
        const auto top = std::max_element(value.begin(), value.end()) - value.begin();
        out["peak"] = {{"Q_w", qw[top]}, {"value", value[top]}};
    }
}

Json fileSummary(const FileResults& file) {
    Json out = attributes(file.root);
    for (const schema::Record& g : file.groups) {
        Json group = attributes(g);
        addCurves(g, group);
        out[std::string(g.group().name)] = std::move(group);
    }
    return out;
}

Json ensembleSummary(const EnsembleResults& ensemble) {
    Json out = attributes(ensemble.root);
    out["members"] = ensemble.members;
    for (const schema::Record& g : ensemble.groups)
        out[std::string(g.group().name)] = attributes(g);
    return out;
}

} // namespace

void writeJsonSummary(std::ostream& out, const RunResults& results, const RunSettings& settings) {
    Json root = attributes(runRecord(results, settings));
    root["format"] = schema::kSummaryFormat;
    root["results_file"] = settings.output.empty() ? Json() : Json(settings.output.string());
    Json files = Json::array();
    for (const FileResults& f : results.files)
        files.push_back(fileSummary(f));
    root["files"] = std::move(files);
    Json ensembles = Json::array();
    for (const EnsembleResults& e : results.ensembles)
        ensembles.push_back(ensembleSummary(e));
    root["ensembles"] = std::move(ensembles);
    // File names need not be UTF-8: invalid bytes become U+FFFD instead of an exception.
    out << root.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

} // namespace sbpack

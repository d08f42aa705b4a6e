#include "pipeline/ensemble.hpp"

#include "numerics/sample_statistics.hpp"
#include "pipeline/analysis_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace sbpack {

namespace {

/// One file's count-weighted sums of Q w, Q and the value in one bin.
struct FileBin {
    double qw = 0.0, q = 0.0, value = 0.0;
    std::int64_t count = 0;
};

/// Bin index -> per file sums.
using Bins = std::map<long, std::vector<FileBin>>;

Bins binCurves(std::span<const ShellAverage> curves, std::span<const double> meanWidths,
               double binWidthQw) {
    Bins bins;
    for (std::size_t f = 0; f < curves.size(); ++f) {
        const ShellAverage& c = curves[f];
        for (std::size_t i = 0; i < c.size(); ++i) {
            const double qw = c.q[i] * meanWidths[f];
            std::vector<FileBin>& bin = bins[std::lround(qw / binWidthQw)];
            bin.resize(curves.size());
            const auto w = static_cast<double>(c.count[i]);
            bin[f].qw += w * qw;
            bin[f].q += w * c.q[i];
            bin[f].value += w * c.value[i];
            bin[f].count += c.count[i];
        }
    }
    return bins;
}

void appendBin(const std::vector<FileBin>& perFile, EnsembleCurve& out) {
    std::vector<double> values;
    double qw = 0.0, q = 0.0;
    std::int64_t count = 0;
    for (const FileBin& b : perFile) {
        if (b.count == 0) continue;
        const auto c = static_cast<double>(b.count);
        values.push_back(b.value / c);
        qw += b.qw / c;
        q += b.q / c;
        count += b.count;
    }
    const SampleStatistics s = sampleStatistics(values);
    const auto files = static_cast<double>(values.size());
    out.qw.push_back(qw / files);
    out.q.push_back(q / files);
    out.mean.push_back(s.mean);
    out.std.push_back(s.std);
    out.count.push_back(count);
    out.files.push_back(static_cast<std::int64_t>(values.size()));
}

} // namespace

EnsembleCurve ensembleCurve(std::span<const ShellAverage> curves,
                            std::span<const double> meanWidths,
                            std::span<const double> boxLengths) {
    if (curves.empty() || curves.size() != meanWidths.size() || curves.size() != boxLengths.size())
        throw std::invalid_argument("ensemble curve: one mean width and box length per curve");
    EnsembleCurve out;
    for (std::size_t f = 0; f < curves.size(); ++f)
        out.binWidthQw += 2.0 * std::numbers::pi * meanWidths[f] / boxLengths[f];
    out.binWidthQw /= static_cast<double>(curves.size());
    for (const auto& [index, perFile] : binCurves(curves, meanWidths, out.binWidthQw))
        appendBin(perFile, out);
    return out;
}

namespace {

/// The records of one group over the members that have it, with each one's file record.
struct Sources {
    std::vector<const schema::Record*> records;
    std::vector<const schema::Record*> files;
};

void reduceScalar(const schema::Field& f, const Sources& in, schema::Record& out) {
    std::vector<double> values;
    for (const schema::Record* r : in.records)
        if (r->has(f.name)) values.push_back(r->number(f.name));
    if (values.empty()) return; // an optional field no member has
    const SampleStatistics s = sampleStatistics(values);
    out.set(f.name, s.mean).set(std::string(f.name) + "_std", s.std);
}

void reduceCurve(const schema::Field& f, const Sources& in, schema::Record& out) {
    std::vector<ShellAverage> curves;
    std::vector<double> widths, lengths;
    for (std::size_t i = 0; i < in.records.size(); ++i) {
        const schema::Record& r = *in.records[i];
        curves.push_back({r.floats("Q"), r.floats(f.name), r.integers("count")});
        widths.push_back(in.files[i]->number("mean_width"));
        lengths.push_back(in.files[i]->number("box_length"));
    }
    const EnsembleCurve c = ensembleCurve(curves, widths, lengths);
    out.set("bin_width_Q_w", c.binWidthQw)
        .set("Q_w", c.qw)
        .set("Q", c.q)
        .set(f.name, c.mean)
        .set(std::string(f.name) + "_std", c.std)
        .set("count", c.count)
        .set("files", c.files);
}

/// Mean and standard deviation over `members` at each of `size` points, member i's value at
/// point j being valueAt(i, j).
template <class ValueAt>
std::pair<std::vector<double>, std::vector<double>>
pointwiseStatistics(std::size_t size, std::size_t members, ValueAt&& valueAt) {
    std::vector<double> mean(size), std(size), values(members);
    for (std::size_t j = 0; j < size; ++j) {
        for (std::size_t i = 0; i < members; ++i)
            values[i] = valueAt(i, j);
        const SampleStatistics s = sampleStatistics(values);
        mean[j] = s.mean;
        std[j] = s.std;
    }
    return {mean, std};
}

/// Element-wise mean and standard deviation of a dataset on a grid common to the members.
void reducePointwise(const schema::Field& f, const Sources& in, schema::Record& out) {
    const std::size_t size = in.records.front()->floats(f.name).size();
    for (const schema::Record* r : in.records)
        if (r->floats(f.name).size() != size)
            throw std::logic_error("ensemble: " + std::string(f.name) + " differs in length");
    const auto [mean, std] = pointwiseStatistics(
        size, in.records.size(), [&](auto i, auto j) { return in.records[i]->floats(f.name)[j]; });
    out.set(f.name, mean).set(std::string(f.name) + "_std", std);
}

/// y(at) of the right-continuous steps y[j] at x[j] (x ascending): the last j with x[j] <= at.
double stepValue(const std::vector<double>& x, const std::vector<double>& y, double at) {
    const auto j = std::upper_bound(x.begin(), x.end(), at) - x.begin();
    return j == 0 ? y.front() : y[static_cast<std::size_t>(j - 1)];
}

/// Mean and standard deviation of step functions on a common grid of f.over (Reduce::Steps).
void reduceSteps(const schema::Field& f, const Sources& in, schema::Record& out) {
    double reach = 0.0;
    for (const schema::Record* r : in.records)
        reach = std::max(reach, r->floats(f.over).back());
    std::vector<double> grid(schema::kStepsGrid + 1);
    for (std::size_t k = 0; k < grid.size(); ++k)
        grid[k] = reach * static_cast<double>(k) / schema::kStepsGrid;
    const auto [mean, std] =
        pointwiseStatistics(grid.size(), in.records.size(), [&](auto i, auto k) {
            return stepValue(in.records[i]->floats(f.over), in.records[i]->floats(f.name), grid[k]);
        });
    out.set(f.over, grid).set(f.name, mean).set(std::string(f.name) + "_std", std);
}

/// A grid every member has alike.
void copySame(const schema::Field& f, const Sources& in, schema::Record& out) {
    const std::vector<double>& first = in.records.front()->floats(f.name);
    for (const schema::Record* r : in.records)
        if (r->floats(f.name) != first)
            throw std::logic_error("ensemble: " + std::string(f.name) + " differs between files");
    out.set(f.name, first);
}

/// The members of `in` whose record has `field` (an optional field: e.g. the force distribution,
/// of the packings that store contact forces).
Sources having(const Sources& in, std::string_view field) {
    Sources out;
    for (std::size_t i = 0; i < in.records.size(); ++i)
        if (in.records[i]->has(field)) {
            out.records.push_back(in.records[i]);
            out.files.push_back(in.files[i]);
        }
    return out;
}

/// Statistics of the fields of `source` over `in` into a record of `target`; an optional field
/// over the members that have it, none where no member has.
schema::Record reduce(const schema::Group& source, const schema::Group& target, const Sources& in) {
    schema::Record out(target);
    for (const schema::Field& f : source.fields) {
        const Sources members = f.optional ? having(in, f.name) : in;
        if (members.records.empty()) continue;
        if (f.reduce == schema::Reduce::MeanStd) reduceScalar(f, members, out);
        if (f.reduce == schema::Reduce::Curve) reduceCurve(f, members, out);
        if (f.reduce == schema::Reduce::Pointwise) reducePointwise(f, members, out);
        if (f.reduce == schema::Reduce::Same) copySame(f, members, out);
        if (f.reduce == schema::Reduce::Steps) reduceSteps(f, members, out);
    }
    return out;
}

void checkSameEnsemble(const FileResults& first, const FileResults& other) {
    if (other.shape() == first.shape() && other.particles() == first.particles()) return;
    throw std::invalid_argument(fmt::format(
        "ensemble: '{}' ({} {}, N = {}) and '{}' ({} {}, N = {}) differ in shape or N and are "
        "not averaged together",
        first.input.string(), first.shape().info().name, first.shape().describe(),
        first.particles(), other.input.string(), other.shape().info().name,
        other.shape().describe(), other.particles()));
}

} // namespace

const schema::Record* EnsembleResults::group(std::string_view name) const {
    for (const schema::Record& g : groups)
        if (g.group().name == name) return &g;
    return nullptr;
}

schema::Record* EnsembleResults::group(std::string_view name) {
    return const_cast<schema::Record*>(std::as_const(*this).group(name));
}

std::vector<std::vector<std::size_t>> ensembleMembers(std::span<const FileResults> files) {
    std::vector<std::vector<std::size_t>> ensembles;
    for (std::size_t i = 0; i < files.size(); ++i) {
        auto same = [&](const std::vector<std::size_t>& e) {
            return files[e.front()].shape() == files[i].shape() &&
                   files[e.front()].particles() == files[i].particles() &&
                   files[e.front()].sizeRatio == files[i].sizeRatio;
        };
        auto it = std::find_if(ensembles.begin(), ensembles.end(), same);
        if (it == ensembles.end())
            ensembles.push_back({i});
        else
            it->push_back(i);
    }
    return ensembles;
}

EnsembleResults computeEnsemble(std::span<const FileResults> files,
                                std::vector<std::size_t> members) {
    if (members.empty()) throw std::invalid_argument("ensemble: no members");
    Sources all;
    for (std::size_t m : members) {
        if (m >= files.size()) throw std::invalid_argument(fmt::format("ensemble: no file {}", m));
        checkSameEnsemble(files[members.front()], files[m]);
        all.records.push_back(&files[m].root);
    }
    all.files = all.records;
    EnsembleResults e;
    e.root = reduce(schema::fileGroup(), schema::ensembleRootGroup(), all);
    schema::setShape(e.root, files[members.front()].shape());
    e.root.set("n_particles", files[members.front()].particles())
        .set("n_files", members.size())
        .set("members", std::vector<std::int64_t>(members.begin(), members.end()));
    for (const schema::Group* group : resultGroups()) {
        const schema::Group& g = *group;
        Sources in;
        for (std::size_t m : members)
            if (const schema::Record* r = files[m].group(g.name)) {
                in.records.push_back(r);
                in.files.push_back(&files[m].root);
            }
        if (in.records.empty()) continue;
        e.groups.push_back(reduce(g, schema::ensembleGroup(g), in));
        e.groups.back().set("n_files", in.records.size());
    }
    e.members = std::move(members);
    for (const AnalysisInfo& info : analysisRegistry())
        if (info.finishEnsemble && e.group(info.group().name)) info.finishEnsemble(e, files);
    return e;
}

std::vector<EnsembleResults> computeEnsembles(std::span<const FileResults> files) {
    std::vector<EnsembleResults> ensembles;
    for (std::vector<std::size_t>& members : ensembleMembers(files))
        ensembles.push_back(computeEnsemble(files, std::move(members)));
    return ensembles;
}

} // namespace sbpack

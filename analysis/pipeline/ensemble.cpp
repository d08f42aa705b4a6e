#include "pipeline/ensemble.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace sbpack {

EnsembleScalar ensembleScalar(std::span<const double> values) {
    EnsembleScalar s;
    s.files = static_cast<int>(values.size());
    if (values.empty()) return s;
    for (double v : values)
        s.mean += v;
    s.mean /= static_cast<double>(values.size());
    if (values.size() > 1) {
        double squares = 0.0;
        for (double v : values)
            squares += (v - s.mean) * (v - s.mean);
        s.std = std::sqrt(squares / static_cast<double>(values.size() - 1));
    }
    return s;
}

EnsembleCurve ensembleCurve(std::span<const ShellAverage> curves,
                            std::span<const double> meanWidths,
                            std::span<const double> boxLengths) {
    if (curves.empty() || curves.size() != meanWidths.size() || curves.size() != boxLengths.size())
        throw std::invalid_argument("ensemble curve: one mean width and box length per curve");
    EnsembleCurve out;
    for (std::size_t f = 0; f < curves.size(); ++f)
        out.binWidthQw += 2.0 * std::numbers::pi * meanWidths[f] / boxLengths[f];
    out.binWidthQw /= static_cast<double>(curves.size());

    // Per file and bin: count-weighted sums of Q w, Q and the value.
    struct FileBin {
        double qw = 0.0, q = 0.0, value = 0.0;
        std::int64_t count = 0;
    };
    std::map<long, std::vector<FileBin>> bins;
    for (std::size_t f = 0; f < curves.size(); ++f) {
        const ShellAverage& c = curves[f];
        for (std::size_t i = 0; i < c.size(); ++i) {
            const double qw = c.q[i] * meanWidths[f];
            std::vector<FileBin>& bin = bins[std::lround(qw / out.binWidthQw)];
            bin.resize(curves.size());
            const auto w = static_cast<double>(c.count[i]);
            bin[f].qw += w * qw;
            bin[f].q += w * c.q[i];
            bin[f].value += w * c.value[i];
            bin[f].count += c.count[i];
        }
    }
    for (const auto& [index, perFile] : bins) {
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
        const EnsembleScalar s = ensembleScalar(values);
        out.qw.push_back(qw / s.files);
        out.q.push_back(q / s.files);
        out.mean.push_back(s.mean);
        out.std.push_back(s.std);
        out.count.push_back(count);
        out.files.push_back(s.files);
    }
    return out;
}

namespace {

/// Statistics of one scalar over the files where `get` finds it.
template <class Get> EnsembleScalar over(std::span<const FileResults> files, Get get) {
    std::vector<double> values;
    for (const FileResults& f : files)
        if (const std::optional<double> v = get(f)) values.push_back(*v);
    return ensembleScalar(values);
}

} // namespace

EnsembleResults computeEnsemble(std::span<const FileResults> files) {
    EnsembleResults e;
    e.files = static_cast<int>(files.size());
    EnsembleGroup& root = e.groups[""];
    root.scalars["phi"] = over(files, [](const FileResults& f) { return std::optional(f.phi); });
    root.scalars["mean_width"] =
        over(files, [](const FileResults& f) { return std::optional(f.meanWidth); });
    root.scalars["box_length"] =
        over(files, [](const FileResults& f) { return std::optional(f.boxLength); });

    if (files.front().contacts) {
        EnsembleGroup& g = e.groups["contacts"];
        g.scalars["z_mean"] = over(files, [](const FileResults& f) {
            return std::optional(f.contacts->result.meanContactNumber);
        });
        g.scalars["rattler_fraction"] = over(files, [](const FileResults& f) {
            return std::optional(f.contacts->result.rattlerFraction);
        });
    }
    if (files.front().poreSizes) {
        EnsembleGroup& g = e.groups["pore_size"];
        g.scalars["mean_w"] = over(files, [](const FileResults& f) {
            return std::optional(f.poreSizes->meanOverWidth());
        });
        g.scalars["second_moment_w2"] = over(files, [](const FileResults& f) {
            return std::optional(f.poreSizes->secondMomentOverWidth2());
        });
        g.scalars["max_w"] = over(
            files, [](const FileResults& f) { return std::optional(f.poreSizes->maxOverWidth()); });
    }
    if (files.front().transport) {
        EnsembleGroup& g = e.groups["transport"];
        g.scalars["permeability_w2"] = over(files, [](const FileResults& f) {
            return std::optional(f.transport->permeabilityOverWidth2());
        });
        g.scalars["mean_survival_time_scaled"] = over(files, [](const FileResults& f) {
            return std::optional(f.transport->meanSurvivalTimeScaled());
        });
        g.scalars["principal_relaxation_time_scaled"] = over(files, [](const FileResults& f) {
            return std::optional(f.transport->principalRelaxationTimeScaled());
        });
    }
    if (files.front().voxelization) {
        EnsembleGroup& g = e.groups["voxelization"];
        g.scalars["phi_voxel"] = over(
            files, [](const FileResults& f) { return std::optional(f.voxelization->phiVoxel); });
        g.scalars["phi_exact"] = over(
            files, [](const FileResults& f) { return std::optional(f.voxelization->phiExact); });
    }
    // Curves: every file has the same analyses (one run, one --compute).
    std::vector<double> widths, lengths;
    for (const FileResults& f : files) {
        widths.push_back(f.meanWidth);
        lengths.push_back(f.boxLength);
    }
    if (files.front().structureFactor) {
        std::vector<ShellAverage> curves;
        for (const FileResults& f : files)
            curves.push_back(f.structureFactor->shells);
        e.groups["structure_factor"] =
            EnsembleGroup{{}, ensembleCurve(curves, widths, lengths), std::string("S")};
    }
    if (files.front().spectralDensity) {
        std::vector<ShellAverage> curves;
        for (const FileResults& f : files)
            curves.push_back(f.spectralDensity->shells);
        EnsembleGroup& g = e.groups["spectral_density"] =
            EnsembleGroup{{}, ensembleCurve(curves, widths, lengths), std::string("chi")};
        g.scalars["phi_voxel"] = over(
            files, [](const FileResults& f) { return std::optional(f.spectralDensity->phiVoxel); });
        g.scalars["exact_error"] = over(files, [](const FileResults& f) {
            return f.spectralDensity->exactSphere
                       ? std::optional(f.spectralDensity->exactSphere->maxErrorOverPeak)
                       : std::nullopt;
        });
        if (g.scalars["exact_error"].files == 0) g.scalars.erase("exact_error");
    }
    return e;
}

} // namespace sbpack

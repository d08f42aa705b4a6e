#include "pipeline/summary_json.hpp"

#include "version.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace sbpack {

namespace {

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
            out += buffer;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string number(double value) {
    if (!std::isfinite(value)) return "null";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
}

/// Builds one JSON object, members in insertion order.
class Object {
  public:
    Object& add(const std::string& key, const std::string& json) {
        members_.push_back(quoted(key) + ": " + json);
        return *this;
    }
    Object& add(const std::string& key, double value) { return add(key, number(value)); }
    std::string str(int indent = 0) const {
        const std::string pad(indent + 2, ' ');
        std::string out = "{";
        for (std::size_t i = 0; i < members_.size(); ++i)
            out += (i ? ",\n" : "\n") + pad + members_[i];
        return out + "\n" + std::string(indent, ' ') + "}";
    }

  private:
    std::vector<std::string> members_;
};

/// The largest value of a curve and its Q w: the principal peak.
Object peak(const ShellAverage& shells, double meanWidth) {
    const auto top =
        std::max_element(shells.value.begin(), shells.value.end()) - shells.value.begin();
    return std::move(
        Object().add("Q_w", shells.q[top] * meanWidth).add("value", shells.value[top]));
}

std::string fileSummary(const FileResults& f, int indent) {
    Object o;
    o.add("input", quoted(f.input.string()))
        .add("n_particles", static_cast<double>(f.particles))
        .add("p", f.p)
        .add("phi", f.phi)
        .add("mean_width", f.meanWidth);
    const int inner = indent + 2;
    if (f.contacts)
        o.add("contacts", Object()
                              .add("z_mean", f.contacts->result.meanContactNumber)
                              .add("rattler_fraction", f.contacts->result.rattlerFraction)
                              .add("runtime_s", f.contacts->runtimeSeconds)
                              .str(inner));
    if (f.structureFactor)
        o.add("structure_factor",
              Object()
                  .add("shells", static_cast<double>(f.structureFactor->shells.size()))
                  .add("peak", peak(f.structureFactor->shells, f.meanWidth).str(inner + 2))
                  .add("runtime_s", f.structureFactor->runtimeSeconds)
                  .str(inner));
    if (f.voxelization)
        o.add("voxelization",
              Object()
                  .add("voxels", f.voxelization->parameters.voxels)
                  .add("phi_voxel", f.voxelization->phiVoxel)
                  .add("phi_exact", f.voxelization->phiExact)
                  .add("memory_bytes", static_cast<double>(f.voxelization->memoryBytes))
                  .add("runtime_s", f.voxelization->runtimeSeconds)
                  .str(inner));
    if (f.spectralDensity) {
        const SpectralDensityResult& s = *f.spectralDensity;
        Object chi;
        chi.add("voxels", s.voxels)
            .add("phi_voxel", s.phiVoxel)
            .add("shells", static_cast<double>(s.shells.size()))
            .add("peak", peak(s.shells, f.meanWidth).str(inner + 2));
        if (s.exactSphere) chi.add("exact_error", s.exactSphere->maxErrorOverPeak);
        chi.add("runtime_s", s.runtimeSeconds);
        o.add("spectral_density", chi.str(inner));
    }
    if (f.poreSizes)
        o.add("pore_size", Object()
                               .add("voxels", f.poreSizes->voxels)
                               .add("mean_w", f.poreSizes->meanOverWidth())
                               .add("second_moment_w2", f.poreSizes->secondMomentOverWidth2())
                               .add("max_w", f.poreSizes->maxOverWidth())
                               .add("runtime_s", f.poreSizes->runtimeSeconds)
                               .str(inner));
    if (f.transport)
        o.add("transport",
              Object()
                  .add("permeability_w2", f.transport->permeabilityOverWidth2())
                  .add("mean_survival_time_scaled", f.transport->meanSurvivalTimeScaled())
                  .add("principal_relaxation_time_scaled",
                       f.transport->principalRelaxationTimeScaled())
                  .str(inner));
    return o.str(indent);
}

std::string statistics(const EnsembleScalar& s, int indent) {
    return Object().add("mean", s.mean).add("std", s.std).str(indent);
}

std::string ensembleSummary(const EnsembleResults& e, int indent) {
    Object o;
    o.add("n_files", e.files);
    for (const auto& [name, group] : e.groups) {
        if (name.empty()) { // the per-file root attributes
            for (const auto& [key, s] : group.scalars)
                o.add(key, statistics(s, indent + 2));
            continue;
        }
        Object scalars;
        for (const auto& [key, s] : group.scalars)
            scalars.add(key, statistics(s, indent + 4));
        o.add(name, scalars.str(indent + 2));
    }
    return o.str(indent);
}

} // namespace

void writeJsonSummary(std::ostream& out, const RunResults& results, const RunSettings& settings) {
    std::string files = "[";
    for (std::size_t i = 0; i < results.files.size(); ++i)
        files += (i ? ",\n    " : "\n    ") + fileSummary(results.files[i], 4);
    files += "\n  ]";
    Object root;
    root.add("format", quoted("sbpack.summary"))
        .add("sbanalyze_version", quoted(kVersion))
        .add("compute", quoted(analysisNames(settings.analyses)))
        .add("threads", settings.threads)
        .add("results_file", settings.output.empty() ? "null" : quoted(settings.output.string()))
        .add("files", files);
    if (results.ensemble) root.add("ensemble", ensembleSummary(*results.ensemble, 2));
    root.add("runtime_s", results.runtimeSeconds);
    out << root.str() << '\n';
}

} // namespace sbpack

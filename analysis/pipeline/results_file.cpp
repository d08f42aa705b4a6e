#include "pipeline/results_file.hpp"

#include "io/hdf5_handles.hpp"
#include "version.hpp"

#include <string>

namespace sbpack {

namespace {

/// A one-dimensional dataset of `values` (float64 or int64 in the file).
template <class T>
void writeVector(hid_t parent, const std::string& name, const std::vector<T>& values) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, std::int64_t>);
    const hid_t fileType = std::is_same_v<T, double> ? H5T_IEEE_F64LE : H5T_STD_I64LE;
    const hid_t memoryType = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64;
    const hsize_t dims[1] = {values.size()};
    const Hdf5Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose);
    const hid_t id = H5Dcreate2(parent, name.c_str(), fileType, space.get(), H5P_DEFAULT,
                                H5P_DEFAULT, H5P_DEFAULT);
    if (id < 0) throw Hdf5Error("results file: cannot create dataset '" + name + "'");
    const Hdf5Handle dataset(id, H5Dclose);
    if (H5Dwrite(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        throw Hdf5Error("results file: cannot write dataset '" + name + "'");
}

std::vector<double> times(const std::vector<double>& v, double factor) {
    std::vector<double> out(v);
    for (double& x : out)
        x *= factor;
    return out;
}

/// Q, <value name>, count, Q_w of a shell-averaged curve.
void writeShells(hid_t group, const ShellAverage& shells, const std::string& valueName,
                 double meanWidth) {
    writeVector(group, "Q", shells.q);
    writeVector(group, valueName, shells.value);
    writeVector(group, "count", shells.count);
    writeVector(group, "Q_w", times(shells.q, meanWidth));
}

void writeRunAttributes(hid_t root, const RunSettings& settings) {
    writeStringAttribute(root, "format", kResultsFormat);
    writeInt64Attribute(root, "format_version", kResultsFormatVersion);
    writeStringAttribute(root, "sbanalyze_version", kVersion);
    writeStringAttribute(root, "compute", analysisNames(settings.analyses));
    writeInt64Attribute(root, "threads", settings.threads);
}

void writePoreSizes(hid_t target, const PoreSizeDistributionResult& s) {
    const Hdf5Handle g = createGroup(target, "pore_size");
    writeVector(g.get(), "delta", s.delta);
    writeVector(g.get(), "F", s.F);
    writeVector(g.get(), "delta_w", s.deltaOverWidth());
    writeVector(g.get(), "P_delta", s.densityDelta);
    writeVector(g.get(), "P", s.density);
    writeVector(g.get(), "P_delta_w", s.densityDeltaOverWidth());
    writeVector(g.get(), "P_w", s.densityTimesWidth());
    writeDoubleAttribute(g.get(), "mean", s.mean);
    writeDoubleAttribute(g.get(), "second_moment", s.secondMoment);
    writeDoubleAttribute(g.get(), "max", s.max);
    writeDoubleAttribute(g.get(), "mean_w", s.meanOverWidth());
    writeDoubleAttribute(g.get(), "second_moment_w2", s.secondMomentOverWidth2());
    writeDoubleAttribute(g.get(), "max_w", s.maxOverWidth());
    writeInt64Attribute(g.get(), "saturated", s.saturated ? 1 : 0);
    writeInt64Attribute(g.get(), "voxels", s.voxels);
    writeDoubleAttribute(g.get(), "voxel_size", s.voxelSize);
    writeInt64Attribute(g.get(), "samples", s.samples);
    writeStringAttribute(g.get(), "method", s.method);
    writeDoubleAttribute(g.get(), "runtime_s", s.runtimeSeconds);
}

void writeTransport(hid_t target, const TransportResult& t) {
    const Hdf5Handle g = createGroup(target, "transport");
    writeDoubleAttribute(g.get(), "zeta2", t.zeta2);
    writeDoubleAttribute(g.get(), "formation_factor", t.formationFactor);
    writeDoubleAttribute(g.get(), "permeability", t.permeability);
    writeDoubleAttribute(g.get(), "permeability_w2", t.permeabilityOverWidth2());
    writeDoubleAttribute(g.get(), "mean_survival_time", t.meanSurvivalTime);
    writeDoubleAttribute(g.get(), "mean_survival_time_scaled", t.meanSurvivalTimeScaled());
    writeDoubleAttribute(g.get(), "principal_relaxation_time", t.principalRelaxationTime);
    writeDoubleAttribute(g.get(), "principal_relaxation_time_scaled",
                         t.principalRelaxationTimeScaled());
    writeDoubleAttribute(g.get(), "diffusion_coefficient", t.parameters.diffusionCoefficient);
    writeDoubleAttribute(g.get(), "runtime_s", t.runtimeSeconds);
}

void writeFileResults(hid_t target, const FileResults& f) {
    writeStringAttribute(target, "input", f.input.string());
    writeDoubleAttribute(target, "p", f.p);
    writeInt64Attribute(target, "n_particles", f.particles);
    writeDoubleAttribute(target, "box_length", f.boxLength);
    writeDoubleAttribute(target, "semi_axis", f.semiAxis);
    writeDoubleAttribute(target, "phi", f.phi);
    writeDoubleAttribute(target, "mean_width", f.meanWidth);

    if (f.contacts) {
        const ContactResult& c = f.contacts->result;
        const Hdf5Handle g = createGroup(target, "contacts");
        writeDoubleAttribute(g.get(), "z_mean", c.meanContactNumber);
        writeDoubleAttribute(g.get(), "rattler_fraction", c.rattlerFraction);
        writeDoubleAttribute(g.get(), "tolerance", c.parameters.tolerance);
        writeInt64Attribute(g.get(), "rattler_threshold", c.parameters.rattlerThreshold);
        writeInt64Attribute(g.get(), "n_contacts", static_cast<std::int64_t>(c.contacts.size()));
        writeInt64Attribute(g.get(), "overlapping_pairs", c.overlappingPairs);
        writeDoubleAttribute(g.get(), "runtime_s", f.contacts->runtimeSeconds);
        writeVector(g.get(), "counts", std::vector<std::int64_t>(c.counts.begin(), c.counts.end()));
        std::vector<std::int64_t> rattler(c.rattler.size());
        for (std::size_t i = 0; i < rattler.size(); ++i)
            rattler[i] = c.rattler[i] ? 1 : 0;
        writeVector(g.get(), "rattler", rattler);
    }
    if (f.structureFactor) {
        const StructureFactorResult& s = *f.structureFactor;
        const Hdf5Handle g = createGroup(target, "structure_factor");
        writeShells(g.get(), s.shells, "S", f.meanWidth);
        writeDoubleAttribute(g.get(), "qmax", s.parameters.maxQw);
        writeInt64Attribute(g.get(), "max_shell", s.maxShell);
        writeDoubleAttribute(g.get(), "runtime_s", s.runtimeSeconds);
    }
    if (f.voxelization) {
        const VoxelizationRecord& v = *f.voxelization;
        const Hdf5Handle g = createGroup(target, "voxelization");
        writeInt64Attribute(g.get(), "voxels", v.parameters.voxels);
        writeDoubleAttribute(g.get(), "phi_voxel", v.phiVoxel);
        writeDoubleAttribute(g.get(), "phi_exact", v.phiExact);
        writeDoubleAttribute(g.get(), "voxel_size", v.voxelSize);
        writeInt64Attribute(g.get(), "solid_voxels", v.solidCount);
        writeInt64Attribute(g.get(), "memory_bytes", static_cast<std::int64_t>(v.memoryBytes));
        if (!v.vdbFile.empty()) writeStringAttribute(g.get(), "vdb_file", v.vdbFile.string());
        writeDoubleAttribute(g.get(), "runtime_s", v.runtimeSeconds);
    }
    if (f.spectralDensity) {
        const SpectralDensityResult& s = *f.spectralDensity;
        const Hdf5Handle g = createGroup(target, "spectral_density");
        writeShells(g.get(), s.shells, "chi", f.meanWidth);
        writeInt64Attribute(g.get(), "voxels", s.voxels);
        writeDoubleAttribute(g.get(), "phi_voxel", s.phiVoxel);
        writeDoubleAttribute(g.get(), "voxel_size", s.voxelSize);
        writeDoubleAttribute(g.get(), "qmax", s.parameters.maxQw);
        writeInt64Attribute(g.get(), "max_shell", s.maxShell);
        writeStringAttribute(g.get(), "fft_planning",
                             std::string(fftPlanningName(s.parameters.fft.planning)));
        writeDoubleAttribute(g.get(), "fft_plan_s", s.planSeconds);
        writeDoubleAttribute(g.get(), "fft_s", s.fillSeconds + s.transformSeconds);
        writeDoubleAttribute(g.get(), "shell_average_s", s.shellSeconds);
        if (s.exactSphere) writeDoubleAttribute(g.get(), "exact_s", s.exactSeconds);
        writeDoubleAttribute(g.get(), "runtime_s", s.runtimeSeconds);
        if (s.exactSphere) {
            writeVector(g.get(), "chi_exact", s.exactSphere->exact.value);
            writeDoubleAttribute(g.get(), "exact_error", s.exactSphere->maxErrorOverPeak);
        }
    }
    if (f.poreSizes) writePoreSizes(target, *f.poreSizes);
    if (f.transport) writeTransport(target, *f.transport);
}

void writeEnsemble(hid_t root, const EnsembleResults& e) {
    const Hdf5Handle ensemble = createGroup(root, "ensemble");
    writeInt64Attribute(ensemble.get(), "n_files", e.files);
    for (const auto& [name, group] : e.groups) {
        const Hdf5Handle sub = name.empty() ? Hdf5Handle() : createGroup(ensemble.get(), name);
        const hid_t g = name.empty() ? ensemble.get() : sub.get();
        for (const auto& [scalar, s] : group.scalars) {
            writeDoubleAttribute(g, scalar, s.mean);
            writeDoubleAttribute(g, scalar + "_std", s.std);
        }
        if (group.curve) {
            const EnsembleCurve& c = *group.curve;
            writeVector(g, "Q_w", c.qw);
            writeVector(g, "Q", c.q);
            writeVector(g, group.curveName, c.mean);
            writeVector(g, group.curveName + "_std", c.std);
            writeVector(g, "count", c.count);
            writeVector(g, "files", std::vector<std::int64_t>(c.files.begin(), c.files.end()));
            writeDoubleAttribute(g, "bin_width_Q_w", c.binWidthQw);
        }
    }
}

} // namespace

void writeResultsFile(const std::filesystem::path& file, const RunResults& results,
                      const RunSettings& settings) {
    Hdf5Handle h5 = createFile(file);
    const hid_t root = h5.get();
    writeRunAttributes(root, settings);
    if (results.files.size() == 1) {
        writeFileResults(root, results.files.front());
    } else {
        writeInt64Attribute(root, "n_files", static_cast<std::int64_t>(results.files.size()));
        const Hdf5Handle files = createGroup(root, "files");
        for (std::size_t i = 0; i < results.files.size(); ++i) {
            const Hdf5Handle g = createGroup(files.get(), std::to_string(i));
            writeFileResults(g.get(), results.files[i]);
        }
        if (results.ensemble) writeEnsemble(root, *results.ensemble);
    }
    writeDoubleAttribute(root, "runtime_s", results.runtimeSeconds);
    h5.close();
}

} // namespace sbpack

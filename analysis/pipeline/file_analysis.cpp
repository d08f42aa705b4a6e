#include "pipeline/file_analysis.hpp"

#include "pipeline/resources.hpp"
#include "pores/distance_transform.hpp"
#include "voxels/voxelization.hpp"

#include <vector>

#include <sstream>
#include <stdexcept>

namespace sbpack {

namespace {

std::string describe(double value, int precision = 6) {
    std::ostringstream out;
    out.precision(precision);
    out << value;
    return out.str();
}

VoxelizationRecord recordOf(const Voxelization& voxels) {
    VoxelizationRecord record;
    record.parameters = voxels.parameters();
    record.voxelSize = voxels.voxelSize();
    record.phiVoxel = voxels.phiVoxel();
    record.phiExact = voxels.phiExact();
    record.solidCount = voxels.solidCount();
    record.memoryBytes = voxels.memoryBytes();
    record.runtimeSeconds = voxels.runtimeSeconds();
    return record;
}

} // namespace

FileResults analyzeFile(const Packing& packing, const std::filesystem::path& input,
                        const RunSettings& settings, const Progress& progress,
                        const std::optional<VdbExport>& vdb,
                        const std::optional<VdbExport>& poreVdb) {
    FileResults r;
    r.input = input;
    r.p = packing.p;
    r.particles = static_cast<std::int64_t>(packing.size());
    r.boxLength = packing.boxLength;
    r.semiAxis = packing.semiAxis;
    r.phi = packing.packingFraction();
    r.meanWidth = packing.shape().meanWidth();

    if (settings.runs(Analysis::Contacts)) {
        const Stopwatch clock;
        ContactsRecord record{ContactNetwork(settings.contacts).compute(packing), 0.0};
        record.runtimeSeconds = clock.seconds();
        progress.stageDone("contacts", record.runtimeSeconds,
                           "Z = " + describe(record.result.meanContactNumber) +
                               ", rattler fraction " + describe(record.result.rattlerFraction));
        r.contacts = std::move(record);
    }
    if (settings.runs(Analysis::StructureFactor)) {
        r.structureFactor = StructureFactor({settings.maxQw}).compute(packing, progress);
        progress.stageDone("structure factor", r.structureFactor->runtimeSeconds,
                           std::to_string(r.structureFactor->maxShell) +
                               " shells up to Q w = " + describe(settings.maxQw));
    }
    if (settings.grids().count(VoxelGrid::Spectral) != 0) {
        const Voxelization voxels = Voxelizer({settings.voxels}).compute(packing, progress);
        r.voxelization = recordOf(voxels);
        progress.stageDone("voxelization", voxels.runtimeSeconds(),
                           std::to_string(settings.voxels) +
                               "^3, phi_voxel = " + describe(voxels.phiVoxel()) +
                               " (phi = " + describe(voxels.phiExact()) + "), OpenVDB tree " +
                               formatBytes(static_cast<double>(voxels.memoryBytes())));
        if (vdb) {
            const Stopwatch clock;
            voxels.writeVdb(vdb->temporary);
            r.voxelization->vdbFile = vdb->destination;
            progress.stageDone("vdb export", clock.seconds(), vdb->destination.string());
        }
        if (settings.runs(Analysis::SpectralDensity)) {
            SpectralDensityParameters parameters;
            parameters.maxQw = settings.maxQw;
            parameters.fft = settings.fft;
            r.spectralDensity = SpectralDensity(parameters).compute(packing, voxels, progress);
            const SpectralDensityResult& chi = *r.spectralDensity;
            std::string detail = std::to_string(chi.maxShell) + " shells, FFT plan " +
                                 describe(chi.planSeconds, 3) + " s";
            if (chi.exactSphere)
                detail += ", exact sphere path: max error / peak " +
                          describe(chi.exactSphere->maxErrorOverPeak, 3);
            progress.stageDone("spectral density", chi.runtimeSeconds, detail);
        }
    }
    if (settings.runs(Analysis::PoreSizes)) {
        const int m = settings.poreVoxels;
        checkPoreSizeMemory(m);
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
        double voxelSize = 0.0;
        {
            const Voxelization voxels = Voxelizer({m}).compute(packing, progress);
            voxels.copySolidMask(mask);
            voxelSize = voxels.voxelSize();
            progress.stageDone("pore voxelization", voxels.runtimeSeconds(),
                               std::to_string(m) +
                                   "^3, phi_voxel = " + describe(voxels.phiVoxel()));
        }
        const Stopwatch clock;
        const PoreSizeMap map = periodicDistanceTransform(mask, m, voxelSize);
        std::vector<std::uint8_t>().swap(mask);
        progress.stageDone("distance transform", clock.seconds(),
                           std::to_string(map.voidCount()) + " void voxels");
        PoreSizeParameters poreParameters;
        poreParameters.randomPoints = settings.porePoints;
        r.poreSizes = PoreSizeDistribution(poreParameters).compute(map, r.meanWidth);
        const PoreSizeDistributionResult& pores = *r.poreSizes;
        progress.stageDone("pore sizes", pores.runtimeSeconds,
                           "<delta>/w = " + describe(pores.meanOverWidth()) +
                               ", max/w = " + describe(pores.maxOverWidth()) +
                               (pores.saturated ? " (saturated)" : " (NOT below w/2)"));
        if (poreVdb) {
            const Stopwatch exportClock;
            map.writeVdb(poreVdb->temporary);
            progress.stageDone("pore vdb export", exportClock.seconds(),
                               poreVdb->destination.string());
        }
    }
    if (settings.runs(Analysis::Transport)) {
        try {
            r.transport = Transport({}).compute(*r.poreSizes, r.p, r.phi);
            progress.stageDone("transport", r.transport->runtimeSeconds,
                               "k/w^2 = " + describe(r.transport->permeabilityOverWidth2()));
        } catch (const std::domain_error& e) {
            // Outside the fitted range of the zeta_2 interpolation: no group, a warning.
            progress.stageDone("transport", 0.0, std::string("skipped: ") + e.what());
        }
    }
    return r;
}

} // namespace sbpack

#pragma once
// Where sbanalyze computes its grids (--device, docs/gpu.md): the CPU path (TBB, FFTW, OpenVDB),
// or, in a build with SBPACK_WITH_CUDA, the GPU (voxels, chi and the voxel pore sizes).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace sbpack {

enum class ComputeDevice { Cpu, Cuda, Auto };

/// "cpu", "cuda" or "auto"; std::invalid_argument naming --device otherwise.
ComputeDevice computeDeviceFromName(std::string_view name);
/// The name computeDeviceFromName reads.
std::string_view computeDeviceName(ComputeDevice device);

/// Whether this sbanalyze was built with SBPACK_WITH_CUDA.
bool builtWithCuda();

/// The CUDA device a run would use.
struct CudaDevice {
    std::string name;
    int computeMajor = 0, computeMinor = 0;
    int multiprocessors = 0;
    std::size_t totalBytes = 0, freeBytes = 0;
    /// "NVIDIA H100 80GB HBM3 (sm_90, 132 multiprocessors, 79.1 GiB)"
    std::string describe() const;
};

/// The first CUDA device; std::nullopt and the reason (a build without CUDA, no driver, no
/// device) in `reason`.
std::optional<CudaDevice> probeCudaDevice(std::string& reason);

/// The device a run uses: cpu as asked; cuda when the build has CUDA, a device is present and
/// `cpuOnlyReason` is empty, else std::invalid_argument saying which is missing; auto: cuda
/// where it would be granted, else cpu.
struct ResolvedDevice {
    ComputeDevice device = ComputeDevice::Cpu;
    std::optional<CudaDevice> cuda; ///< the device's figures when cuda
    /// "cpu" or "cuda: " + CudaDevice::describe(), the run's provenance (results attribute device)
    std::string description() const;
};
ResolvedDevice resolveComputeDevice(ComputeDevice requested, const std::string& cpuOnlyReason);

} // namespace sbpack

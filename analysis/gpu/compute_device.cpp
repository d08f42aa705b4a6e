#include "gpu/compute_device.hpp"

#ifdef SBPACK_WITH_CUDA
#include "gpu/cuda_kernels.hpp"
#endif

#include <fmt/format.h>

#include <stdexcept>

namespace sbpack {

ComputeDevice computeDeviceFromName(std::string_view name) {
    if (name == "cpu") return ComputeDevice::Cpu;
    if (name == "cuda") return ComputeDevice::Cuda;
    if (name == "auto") return ComputeDevice::Auto;
    throw std::invalid_argument(
        fmt::format("option --device: '{}' is not cpu, cuda or auto", name));
}

std::string_view computeDeviceName(ComputeDevice device) {
    return device == ComputeDevice::Cpu ? "cpu" : device == ComputeDevice::Cuda ? "cuda" : "auto";
}

bool builtWithCuda() {
#ifdef SBPACK_WITH_CUDA
    return true;
#else
    return false;
#endif
}

std::string CudaDevice::describe() const {
    return fmt::format("{} (sm_{}{}, {} multiprocessors, {:.1f} GiB)", name, computeMajor,
                       computeMinor, multiprocessors,
                       static_cast<double>(totalBytes) / (1024.0 * 1024.0 * 1024.0));
}

std::optional<CudaDevice> probeCudaDevice(std::string& reason) {
#ifdef SBPACK_WITH_CUDA
    gpu::cuda::DeviceInfo info;
    if (!gpu::cuda::probe(info, reason)) return std::nullopt;
    return CudaDevice{info.name,       info.computeMajor, info.computeMinor, info.multiprocessors,
                      info.totalBytes, info.freeBytes};
#else
    reason = "this sbanalyze was built without CUDA (configure with -DSBPACK_WITH_CUDA=ON)";
    return std::nullopt;
#endif
}

std::string ResolvedDevice::description() const {
    return cuda ? "cuda: " + cuda->describe() : "cpu";
}

ResolvedDevice resolveComputeDevice(ComputeDevice requested, const std::string& cpuOnlyReason) {
    if (requested == ComputeDevice::Cpu) return {};
    std::string reason = cpuOnlyReason;
    std::optional<CudaDevice> cuda;
    if (reason.empty()) cuda = probeCudaDevice(reason);
    if (cuda) return {ComputeDevice::Cuda, std::move(cuda)};
    if (requested == ComputeDevice::Auto) return {};
    throw std::invalid_argument("option --device cuda: " + reason + "; use --device cpu or auto");
}

} // namespace sbpack

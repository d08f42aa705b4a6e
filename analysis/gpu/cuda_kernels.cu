// The CUDA kernels of the GPU grid analysis (docs/gpu.md): each thread runs one function of
// analysis/grid/ (voxel_rows.hpp, wave_index.hpp, distance_lines.hpp), the code that the host
// runs too and that the host tests run against the CPU path. Built with -fmad=false (CMake), so
// that the voxel test rounds as the host's does (no contracted multiply-adds).
#include "gpu/cuda_kernels.hpp"

#include "grid/distance_lines.hpp"
#include "grid/wave_index.hpp"

#include <cuda_runtime.h>
#include <cufft.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

namespace sbpack::gpu::cuda {

using grid::imageRow;
using grid::ImageRows;
using grid::imageRows;
using grid::ParticleImage;
using grid::rowDistances;
using grid::searchedMinimumAt;
using grid::signedIndex;
using grid::VoxelGeometry;
using grid::wordsPerRow;

namespace {

void check(cudaError_t status, const char* call) {
    if (status != cudaSuccess)
        throw std::runtime_error(std::string("CUDA: ") + call + ": " + cudaGetErrorString(status));
}

void checkFft(cufftResult status, const char* call) {
    if (status != CUFFT_SUCCESS)
        throw std::runtime_error(std::string("cuFFT: ") + call + " failed with error " +
                                 std::to_string(static_cast<int>(status)));
}

/// Waits for the device and throws the first error of the kernels launched before.
void synchronize(const char* what) {
    check(cudaGetLastError(), what);
    check(cudaDeviceSynchronize(), what);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

constexpr int kThreads = 256;

unsigned blocksFor(std::int64_t work) {
    return static_cast<unsigned>((work + kThreads - 1) / kThreads);
}

/// One block per particle image; its threads share the image's rows (x, y).
__global__ void voxelizeImages(const ParticleImage* images, VoxelGeometry g, std::uint32_t* words) {
    const ParticleImage image = images[blockIdx.x];
    const ImageRows rows = imageRows(image, g);
    for (int r = static_cast<int>(threadIdx.x); r < rows.count(); r += blockDim.x)
        imageRow(image, rows.xOf(r), rows.yOf(r), g,
                 [words](std::int64_t word, std::uint32_t bits) { atomicOr(words + word, bits); });
}

__global__ void largestOf(const std::uint32_t* values, std::int64_t count, unsigned* largest) {
    unsigned most = 0;
    for (std::int64_t i = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x; i < count;
         i += std::int64_t{gridDim.x} * blockDim.x)
        most = max(most, values[i]);
    for (int offset = 16; offset > 0; offset >>= 1)
        most = max(most, __shfl_down_sync(0xffffffffu, most, offset));
    if ((threadIdx.x & 31) == 0) atomicMax(largest, most);
}

__global__ void popcountWords(const std::uint32_t* words, std::int64_t count,
                              unsigned long long* total) {
    unsigned long long sum = 0;
    for (std::int64_t i = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x; i < count;
         i += std::int64_t{gridDim.x} * blockDim.x)
        sum += __popc(words[i]);
    for (int offset = 16; offset > 0; offset >>= 1)
        sum += __shfl_down_sync(0xffffffffu, sum, offset);
    if ((threadIdx.x & 31) == 0) atomicAdd(total, sum);
}

/// The indicator in cuFFT's in-place real-to-complex layout (rows of 2 (M/2 + 1) reals).
template <class Real>
__global__ void fillIndicator(const std::uint32_t* words, int m, std::int64_t rowStride,
                              Real* grid) {
    const std::int64_t v = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x;
    const std::int64_t total = std::int64_t{m} * m * m;
    if (v >= total) return;
    const std::int64_t row = v / m;
    const int z = static_cast<int>(v % m);
    const std::uint32_t word = words[row * wordsPerRow(m) + (z >> 5)];
    grid[row * rowStride + z] = static_cast<Real>((word >> (z & 31)) & 1u);
}

/// The compact cube of spectrumCube from the transform (complex (re, im) pairs, M/2 + 1 a row).
template <class Real>
__global__ void gatherCube(const Real* transform, int m, int s, double* cube) {
    const std::int64_t r = 2 * s + 1;
    const std::int64_t i = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x;
    if (i >= r * r * (s + 1)) return;
    const int kz = static_cast<int>(i % (s + 1));
    const std::int64_t oy = (i / (s + 1)) % r, ox = i / ((s + 1) * r);
    const std::int64_t nx = signedIndex(static_cast<int>(ox), static_cast<int>(r));
    const std::int64_t ny = signedIndex(static_cast<int>(oy), static_cast<int>(r));
    const std::int64_t kx = (nx + m) % m, ky = (ny + m) % m;
    const std::int64_t at = ((kx * m + ky) * (m / 2 + 1) + kz) * 2;
    cube[2 * i] = static_cast<double>(transform[at]);
    cube[2 * i + 1] = static_cast<double>(transform[at + 1]);
}

/// The sums by |n|^2 of the whole transform (complex (re, im) pairs, M/2 + 1 a row).
template <class Real>
__global__ void sumsByN2(const Real* transform, int m, const double* f, double volume,
                         double* sums) {
    const std::int64_t half = m / 2 + 1;
    const std::int64_t i = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x;
    if (i >= std::int64_t{m} * m * half) return;
    const int kz = static_cast<int>(i % half);
    const int ky = static_cast<int>((i / half) % m), kx = static_cast<int>(i / (half * m));
    const std::int64_t nx = signedIndex(kx, m), ny = signedIndex(ky, m);
    const std::int64_t n2 = nx * nx + ny * ny + std::int64_t{kz} * kz;
    if (n2 == 0) return;
    const double re = static_cast<double>(transform[2 * i]);
    const double im = static_cast<double>(transform[2 * i + 1]);
    const double weight = kz == 0 || 2 * kz == m ? 1.0 : 2.0;
    atomicAdd(sums + n2, weight * (re * re + im * im) * (f[kx] * f[ky] / volume) * f[kz]);
}

__global__ void rowPass(const std::uint32_t* words, int m, std::uint32_t* distances) {
    const std::int64_t row = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x;
    if (row >= std::int64_t{m} * m) return;
    rowDistances(words + row * wordsPerRow(m), m, distances + row * m);
}

/// One thread per voxel of the M^3 grid, consecutive threads along z (coalesced): the search of
/// searchedMinimumAt along the axis whose voxels lie `stride` apart (M: y, M^2: x), from `in`
/// into `out`.
__global__ void searchPass(const std::uint32_t* in, std::uint32_t* out, int m,
                           std::int64_t stride) {
    const std::int64_t i = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x;
    if (i >= std::int64_t{m} * m * m) return;
    out[i] = searchedMinimumAt(in, i, m, stride);
}

/// Counts of the nonzero values below `levels` (the void voxels' squared distances) into bins,
/// through the block's shared memory when `local` (levels 32-bit counters fit there).
__global__ void histogramOf(const std::uint32_t* values, std::int64_t count, int levels, bool local,
                            unsigned long long* bins) {
    extern __shared__ unsigned counts[];
    if (local) {
        for (int n = static_cast<int>(threadIdx.x); n < levels; n += blockDim.x)
            counts[n] = 0;
        __syncthreads();
    }
    for (std::int64_t i = blockIdx.x * std::int64_t{blockDim.x} + threadIdx.x; i < count;
         i += std::int64_t{gridDim.x} * blockDim.x) {
        const std::uint32_t v = values[i];
        if (v == 0) continue;
        if (local)
            atomicAdd(counts + v, 1u);
        else
            atomicAdd(bins + v, 1ull);
    }
    if (!local) return;
    __syncthreads();
    for (int n = static_cast<int>(threadIdx.x); n < levels; n += blockDim.x)
        if (counts[n] != 0) atomicAdd(bins + n, static_cast<unsigned long long>(counts[n]));
}

} // namespace

bool probe(DeviceInfo& info, std::string& reason) {
    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess) {
        reason = cudaGetErrorString(status);
        return false;
    }
    if (count == 0) {
        reason = "no CUDA device";
        return false;
    }
    cudaDeviceProp properties{};
    check(cudaGetDeviceProperties(&properties, 0), "cudaGetDeviceProperties");
    info.name = properties.name;
    info.computeMajor = properties.major;
    info.computeMinor = properties.minor;
    info.multiprocessors = properties.multiProcessorCount;
    // The context now (cudaFree(nullptr) creates it), so that no stage's time includes it.
    check(cudaFree(nullptr), "cudaFree");
    check(cudaMemGetInfo(&info.freeBytes, &info.totalBytes), "cudaMemGetInfo");
    return true;
}

DeviceBuffer::DeviceBuffer(std::size_t bytes) : bytes_(bytes) {
    check(cudaMalloc(&data_, bytes), "cudaMalloc");
}

DeviceBuffer::DeviceBuffer(DeviceBuffer&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), bytes_(std::exchange(other.bytes_, 0)) {}

DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(bytes_, other.bytes_);
    return *this;
}

DeviceBuffer::~DeviceBuffer() {
    if (data_ != nullptr) cudaFree(data_);
}

void DeviceBuffer::download(void* host) const {
    check(cudaMemcpy(host, data_, bytes_, cudaMemcpyDeviceToHost), "cudaMemcpy to the host");
}

namespace {

/// Page-locked host memory (cudaMallocHost), freed with the object.
class PinnedChunk {
  public:
    explicit PinnedChunk(std::size_t bytes) {
        check(cudaMallocHost(&data_, bytes), "cudaMallocHost");
    }
    PinnedChunk(const PinnedChunk&) = delete;
    PinnedChunk& operator=(const PinnedChunk&) = delete;
    ~PinnedChunk() { cudaFreeHost(data_); }
    void* get() const { return data_; }

  private:
    void* data_ = nullptr;
};

/// A stream of its own, with one event per staging chunk.
struct CopyStream {
    cudaStream_t stream = nullptr;
    cudaEvent_t done[2] = {nullptr, nullptr};
    CopyStream() {
        check(cudaStreamCreateWithFlags(&stream, cudaStreamNonBlocking), "cudaStreamCreate");
        for (cudaEvent_t& event : done)
            check(cudaEventCreateWithFlags(&event, cudaEventDisableTiming), "cudaEventCreate");
    }
    CopyStream(const CopyStream&) = delete;
    CopyStream& operator=(const CopyStream&) = delete;
    ~CopyStream() {
        for (cudaEvent_t event : done)
            cudaEventDestroy(event);
        cudaStreamDestroy(stream);
    }
};

} // namespace

void DeviceBuffer::downloadStaged(void* host, std::size_t chunk, const HostCopy& copyOut) const {
    const std::size_t chunks = (bytes_ + chunk - 1) / chunk;
    if (chunks <= 1) return download(host);
    const PinnedChunk stage[2] = {PinnedChunk(chunk), PinnedChunk(chunk)};
    const CopyStream copies;
    const auto* from = static_cast<const char*>(data_);
    auto* to = static_cast<char*>(host);
    const auto size = [&](std::size_t c) { return std::min(chunk, bytes_ - c * chunk); };
    // Chunk c goes to stage c % 2; the host empties chunk c - 1 while the device sends chunk c.
    for (std::size_t c = 0; c <= chunks; ++c) {
        if (c < chunks) {
            check(cudaMemcpyAsync(stage[c % 2].get(), from + c * chunk, size(c),
                                  cudaMemcpyDeviceToHost, copies.stream),
                  "cudaMemcpyAsync to the host");
            check(cudaEventRecord(copies.done[c % 2], copies.stream), "cudaEventRecord");
        }
        if (c == 0) continue;
        const std::size_t last = c - 1;
        check(cudaEventSynchronize(copies.done[last % 2]), "cudaEventSynchronize");
        copyOut(to + last * chunk, stage[last % 2].get(), size(last));
    }
}

DeviceBuffer voxelize(const std::vector<ParticleImage>& images, const VoxelGeometry& geometry) {
    const std::int64_t m = geometry.voxels;
    DeviceBuffer words(static_cast<std::size_t>(m * m * wordsPerRow(geometry.voxels)) *
                       sizeof(std::uint32_t));
    check(cudaMemset(words.get(), 0, words.bytes()), "cudaMemset");
    if (images.empty()) return words;
    DeviceBuffer onDevice(images.size() * sizeof(ParticleImage));
    check(cudaMemcpy(onDevice.get(), images.data(), onDevice.bytes(), cudaMemcpyHostToDevice),
          "cudaMemcpy to the device");
    voxelizeImages<<<static_cast<unsigned>(images.size()), 128>>>(
        static_cast<const ParticleImage*>(onDevice.get()), geometry,
        static_cast<std::uint32_t*>(words.get()));
    synchronize("voxelizeImages");
    return words;
}

std::int64_t countSolid(const DeviceBuffer& words) {
    DeviceBuffer total(sizeof(unsigned long long));
    check(cudaMemset(total.get(), 0, total.bytes()), "cudaMemset");
    const auto count = static_cast<std::int64_t>(words.bytes() / sizeof(std::uint32_t));
    popcountWords<<<1024, kThreads>>>(static_cast<const std::uint32_t*>(words.get()), count,
                                      static_cast<unsigned long long*>(total.get()));
    synchronize("popcountWords");
    unsigned long long host = 0;
    total.download(&host);
    return static_cast<std::int64_t>(host);
}

std::uint32_t largestValue(const DeviceBuffer& values) {
    DeviceBuffer largest(sizeof(unsigned));
    check(cudaMemset(largest.get(), 0, largest.bytes()), "cudaMemset");
    const auto count = static_cast<std::int64_t>(values.bytes() / sizeof(std::uint32_t));
    largestOf<<<1024, kThreads>>>(static_cast<const std::uint32_t*>(values.get()), count,
                                  static_cast<unsigned*>(largest.get()));
    synchronize("largestOf");
    unsigned host = 0;
    largest.download(&host);
    return host;
}

namespace {

/// The sums by |n|^2 (spectrumCube) of the transform in `grid`.
template <class Real>
std::vector<double> gridSums(const DeviceBuffer& grid, int voxels,
                             const std::vector<double>& axisFactors, double volume) {
    const std::int64_t m = voxels, half = m / 2;
    DeviceBuffer f(axisFactors.size() * sizeof(double));
    check(cudaMemcpy(f.get(), axisFactors.data(), f.bytes(), cudaMemcpyHostToDevice),
          "cudaMemcpy to the device");
    std::vector<double> sums(static_cast<std::size_t>(3 * half * half + 1), 0.0);
    DeviceBuffer onDevice(sums.size() * sizeof(double));
    check(cudaMemset(onDevice.get(), 0, onDevice.bytes()), "cudaMemset");
    sumsByN2<Real><<<blocksFor(m * m * (half + 1)), kThreads>>>(
        static_cast<const Real*>(grid.get()), voxels, static_cast<const double*>(f.get()), volume,
        static_cast<double*>(onDevice.get()));
    synchronize("sumsByN2");
    onDevice.download(sums.data());
    return sums;
}

template <class Real>
SpectrumCube transformAndGather(const DeviceBuffer& words, int voxels, int s, cufftType type,
                                const std::vector<double>& axisFactors, double volume) {
    const std::int64_t m = voxels, half = m / 2 + 1;
    SpectrumCube out;
    auto clock = std::chrono::steady_clock::now();
    DeviceBuffer grid(static_cast<std::size_t>(m * m * half * 2) * sizeof(Real));
    fillIndicator<Real>
        <<<blocksFor(m * m * m), kThreads>>>(static_cast<const std::uint32_t*>(words.get()), voxels,
                                             2 * half, static_cast<Real*>(grid.get()));
    synchronize("fillIndicator");
    out.fillSeconds = secondsSince(clock);
    clock = std::chrono::steady_clock::now();
    cufftHandle plan = 0;
    checkFft(cufftPlan3d(&plan, voxels, voxels, voxels, type), "cufftPlan3d");
    cufftResult status = CUFFT_SUCCESS;
    if constexpr (sizeof(Real) == sizeof(double))
        status = cufftExecD2Z(plan, static_cast<cufftDoubleReal*>(grid.get()),
                              static_cast<cufftDoubleComplex*>(grid.get()));
    else
        status = cufftExecR2C(plan, static_cast<cufftReal*>(grid.get()),
                              static_cast<cufftComplex*>(grid.get()));
    cufftDestroy(plan);
    checkFft(status, "cufftExec");
    synchronize("cufftExec");
    out.transformSeconds = secondsSince(clock);
    const std::int64_t r = 2 * std::int64_t{s} + 1, entries = r * r * (s + 1);
    DeviceBuffer cube(static_cast<std::size_t>(entries) * 2 * sizeof(double));
    gatherCube<Real><<<blocksFor(entries), kThreads>>>(static_cast<const Real*>(grid.get()), voxels,
                                                       s, static_cast<double*>(cube.get()));
    synchronize("gatherCube");
    out.data.resize(static_cast<std::size_t>(entries) * 2);
    cube.download(out.data.data());
    if (!axisFactors.empty()) out.sumByN2 = gridSums<Real>(grid, voxels, axisFactors, volume);
    return out;
}

} // namespace

SpectrumCube spectrumCube(const DeviceBuffer& words, int voxels, int s, bool single,
                          const std::vector<double>& axisFactors, double volume) {
    return single ? transformAndGather<float>(words, voxels, s, CUFFT_R2C, axisFactors, volume)
                  : transformAndGather<double>(words, voxels, s, CUFFT_D2Z, axisFactors, volume);
}

std::size_t fftWorkBytes(int voxels, bool single) {
    std::size_t bytes = 0;
    checkFft(cufftEstimate3d(voxels, voxels, voxels, single ? CUFFT_R2C : CUFFT_D2Z, &bytes),
             "cufftEstimate3d");
    return bytes;
}

DeviceBuffer squaredDistances(const DeviceBuffer& words, int voxels) {
    const std::int64_t m = voxels;
    const std::size_t bytes = static_cast<std::size_t>(m * m * m) * sizeof(std::uint32_t);
    DeviceBuffer distances(bytes);
    auto* d = static_cast<std::uint32_t*>(distances.get());
    rowPass<<<blocksFor(m * m), kThreads>>>(static_cast<const std::uint32_t*>(words.get()), voxels,
                                            d);
    synchronize("rowPass");
    const DeviceBuffer along(bytes); // the pass along y, read by the pass along x
    auto* e = static_cast<std::uint32_t*>(along.get());
    searchPass<<<blocksFor(m * m * m), kThreads>>>(d, e, voxels, m);
    searchPass<<<blocksFor(m * m * m), kThreads>>>(e, d, voxels, m * m);
    synchronize("searchPass");
    return distances;
}

std::vector<std::int64_t> histogram(const DeviceBuffer& values, std::uint32_t largest,
                                    std::int64_t zeros) {
    const int levels = static_cast<int>(largest) + 1;
    DeviceBuffer bins(static_cast<std::size_t>(levels) * sizeof(unsigned long long));
    check(cudaMemset(bins.get(), 0, bins.bytes()), "cudaMemset");
    const std::size_t localBytes = static_cast<std::size_t>(levels) * sizeof(unsigned);
    const bool local = localBytes <= 48 * 1024;
    histogramOf<<<1024, kThreads, local ? localBytes : 0>>>(
        static_cast<const std::uint32_t*>(values.get()),
        static_cast<std::int64_t>(values.bytes() / sizeof(std::uint32_t)), levels, local,
        static_cast<unsigned long long*>(bins.get()));
    synchronize("histogramOf");
    std::vector<std::int64_t> counts(static_cast<std::size_t>(levels));
    static_assert(sizeof(std::int64_t) == sizeof(unsigned long long));
    bins.download(counts.data());
    counts[0] = zeros;
    return counts;
}

} // namespace sbpack::gpu::cuda

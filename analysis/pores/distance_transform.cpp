#include "pores/distance_transform.hpp"

#include "parallel/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr std::uint32_t kInfinite = std::numeric_limits<std::uint32_t>::max();

std::string gigabytes(std::uint64_t bytes) {
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(1);
    out << static_cast<double>(bytes) / 1e9 << " GB";
    return out.str();
}

/// MemAvailable of /proc/meminfo in bytes; 0 where it cannot be read.
std::uint64_t availableMemory() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kilobytes = 0;
    std::string unit;
    while (meminfo >> key >> kilobytes >> unit)
        if (key == "MemAvailable:") return kilobytes * 1024;
    return 0;
}

/// Scratch of one periodic line: the finite sites of the lower envelope and their breakpoints.
struct LineScratch {
    explicit LineScratch(int voxels)
        : input(voxels), output(voxels), site(2 * voxels + 1), value(2 * voxels + 1),
          start(2 * voxels + 1) {}
    std::vector<std::uint32_t> input;
    std::vector<std::uint32_t> output;
    std::vector<std::int64_t> site;  ///< position q' of each envelope parabola (images included)
    std::vector<std::int64_t> value; ///< f(q' mod M) of that parabola
    std::vector<std::int64_t> start; ///< the parabola is the lowest for integers p > start
};

/// One-dimensional periodic min-plus transform (Felzenszwalb-Huttenlocher):
///   out(p) = min_q [ f(q) + (min-image |p - q|)^2 ],  p, q in [0, M),  f = kInfinite: no site.
/// The periodic images q' = q +- M of the sites enter as further parabolas; only those within
/// sqrt(max f) of the line ends can win (out(p) <= f(p)), and none farther than M / 2.
/// Breakpoints are kept as integers (the floor of the real intersection), which is exact for
/// integer p; the floor is taken of a double quotient, exact while |numerator| < 2^31 and the
/// denominator < 2^17 (the quotient's rounding error, < 2^-22, is below its distance 1 /
/// denominator from any integer it is not equal to), which M <= maxPoreSizeVoxels guarantees.
void periodicLowerEnvelope(LineScratch& s, int voxels) {
    const std::uint32_t* f = s.input.data();
    std::int64_t largest = 0;
    bool allFinite = true;
    for (int q = 0; q < voxels; ++q) {
        if (f[q] == kInfinite)
            allFinite = false;
        else
            largest = std::max<std::int64_t>(largest, f[q]);
    }
    std::int64_t pad = voxels / 2;
    if (allFinite) {
        const auto reach = static_cast<std::int64_t>(std::sqrt(static_cast<double>(largest)));
        pad = std::min<std::int64_t>(pad, reach + 1);
    }
    std::int64_t* site = s.site.data();
    std::int64_t* value = s.value.data();
    std::int64_t* start = s.start.data();
    int top = -1; // index of the last parabola of the envelope
    for (std::int64_t q = -pad; q < voxels + pad; ++q) {
        const std::int64_t wrapped = q < 0 ? q + voxels : (q >= voxels ? q - voxels : q);
        const std::uint32_t fq = f[wrapped];
        if (fq == kInfinite) continue;
        const std::int64_t height = fq + q * q; // parabola (p - q)^2 + f(q) = p^2 - 2pq + height
        std::int64_t numerator = 0, denominator = 1;
        while (top >= 0) {
            // Real intersection with the top parabola: (height - height_top) / (2 (q - q_top));
            // q wins for p above it. Pop the top if it is the lowest at no integer any more,
            // i.e. unless floor(numerator / denominator) > start (the first one never).
            numerator = height - (value[top] + site[top] * site[top]);
            denominator = 2 * (q - site[top]);
            if (top == 0 || numerator >= (start[top] + 1) * denominator) break;
            --top;
        }
        ++top;
        site[top] = q;
        value[top] = fq;
        start[top] = top == 0 ? std::numeric_limits<std::int64_t>::min()
                              : static_cast<std::int64_t>(
                                    std::floor(static_cast<double>(numerator) / denominator));
    }
    std::uint32_t* out = s.output.data();
    if (top < 0) { // no site on this line
        std::fill(out, out + voxels, kInfinite);
        return;
    }
    int j = 0;
    for (std::int64_t p = 0; p < voxels; ++p) {
        while (j < top && start[j + 1] < p)
            ++j;
        const std::int64_t d = p - site[j];
        out[p] = static_cast<std::uint32_t>(d * d + value[j]);
    }
}

/// First pass, along x (i): the 1-D periodic distance g to the nearest solid voxel of each column
/// (j, k), written as g^2, kInfinite for a column without solid. Planes i are swept forwards and
/// backwards over a block of columns, so that memory is read in contiguous runs.
void columnDistances(std::span<const std::uint8_t> mask, std::uint32_t* out, int voxels,
                     std::int64_t columnBegin, std::int64_t columnEnd) {
    const std::int64_t plane = static_cast<std::int64_t>(voxels) * voxels;
    const std::int64_t width = columnEnd - columnBegin;
    // Distance seeds across the periodic boundary: from i = -1 to the last solid (as its image
    // at last - M) and from i = M to the first solid (image at first + M).
    std::vector<std::uint32_t> before(width, kInfinite), after(width, kInfinite);
    std::int64_t missing = width;
    for (int i = voxels - 1; i >= 0 && missing > 0; --i) {
        const std::uint8_t* row = mask.data() + i * plane + columnBegin;
        for (std::int64_t c = 0; c < width; ++c)
            if (row[c] != 0 && before[c] == kInfinite) {
                before[c] = static_cast<std::uint32_t>(voxels - 1 - i);
                --missing;
            }
    }
    missing = width;
    for (int i = 0; i < voxels && missing > 0; ++i) {
        const std::uint8_t* row = mask.data() + i * plane + columnBegin;
        for (std::int64_t c = 0; c < width; ++c)
            if (row[c] != 0 && after[c] == kInfinite) {
                after[c] = static_cast<std::uint32_t>(i);
                --missing;
            }
    }
    // Forward: g(i) = 0 on solid, g(i - 1) + 1 otherwise (infinite stays infinite).
    std::vector<std::uint32_t>& previous = before; // g(i - 1), updated in place
    for (int i = 0; i < voxels; ++i) {
        const std::uint8_t* row = mask.data() + i * plane + columnBegin;
        std::uint32_t* g = out + i * plane + columnBegin;
        for (std::int64_t c = 0; c < width; ++c) {
            const std::uint32_t next = previous[c] + (previous[c] != kInfinite ? 1u : 0u);
            g[c] = row[c] != 0 ? 0u : next;
            previous[c] = g[c];
        }
    }
    // Backward: g(i) = min(g(i), g(i + 1) + 1); store g^2 for the next passes.
    std::vector<std::uint32_t>& following = after; // g(i + 1), updated in place
    for (int i = voxels - 1; i >= 0; --i) {
        std::uint32_t* g = out + i * plane + columnBegin;
        for (std::int64_t c = 0; c < width; ++c) {
            const std::uint32_t next = following[c] + (following[c] != kInfinite ? 1u : 0u);
            const std::uint32_t d = std::min(g[c], next);
            following[c] = d;
            g[c] = d == kInfinite ? kInfinite : d * d;
        }
    }
}

/// Second and third passes within one plane i: along y (j, stride M), then along z (k, contiguous).
void planeDistances(std::uint32_t* planeData, int voxels, LineScratch& scratch) {
    for (int k = 0; k < voxels; ++k) {
        for (int j = 0; j < voxels; ++j)
            scratch.input[j] = planeData[j * voxels + k];
        periodicLowerEnvelope(scratch, voxels);
        for (int j = 0; j < voxels; ++j)
            planeData[j * voxels + k] = scratch.output[j];
    }
    for (int j = 0; j < voxels; ++j) {
        std::uint32_t* line = planeData + static_cast<std::int64_t>(j) * voxels;
        std::copy(line, line + voxels, scratch.input.begin());
        periodicLowerEnvelope(scratch, voxels);
        std::copy(scratch.output.begin(), scratch.output.end(), line);
    }
}

} // namespace

std::uint64_t poreSizeMapBytes(int voxels) {
    const auto m = static_cast<std::uint64_t>(std::max(voxels, 0));
    return m * m * m * (sizeof(std::uint8_t) + sizeof(std::uint32_t));
}

void checkPoreSizeMemory(int voxels) {
    if (voxels < 1 || voxels > maxPoreSizeVoxels)
        throw std::invalid_argument("pore sizes: M = " + std::to_string(voxels) +
                                    " voxels per side is not in [1, " +
                                    std::to_string(maxPoreSizeVoxels) + "]");
    const std::uint64_t needed = poreSizeMapBytes(voxels);
    const std::uint64_t available = availableMemory();
    if (available != 0 && needed > available)
        throw std::runtime_error(
            "pore sizes at M = " + std::to_string(voxels) + " need about " + gigabytes(needed) +
            " (1-byte solid mask + 4-byte squared distance per voxel), but "
            "only " +
            gigabytes(available) + " are available (MemAvailable); choose a smaller M");
}

PoreSizeMap::PoreSizeMap(int voxels, double voxelSize, std::vector<std::uint32_t> squaredDistances)
    : voxels_(voxels), voxelSize_(voxelSize), squaredDistances_(std::move(squaredDistances)) {}

PoreSizeMap periodicDistanceTransform(std::span<const std::uint8_t> solidMask, int voxels,
                                      double voxelSize, bool serial) {
    if (voxels < 1 || voxels > maxPoreSizeVoxels)
        throw std::invalid_argument("distance transform: M = " + std::to_string(voxels) +
                                    " voxels per side is not in [1, " +
                                    std::to_string(maxPoreSizeVoxels) + "]");
    const std::int64_t plane = static_cast<std::int64_t>(voxels) * voxels;
    const std::int64_t total = plane * voxels;
    if (static_cast<std::int64_t>(solidMask.size()) != total)
        throw std::invalid_argument("distance transform: the solid mask has " +
                                    std::to_string(solidMask.size()) +
                                    " entries, not M^3 = " + std::to_string(total));
    if (!(std::isfinite(voxelSize) && voxelSize > 0.0))
        throw std::invalid_argument("distance transform: voxel size " + std::to_string(voxelSize) +
                                    " is not finite and positive");
    const std::int64_t solid =
        std::count_if(solidMask.begin(), solidMask.end(), [](std::uint8_t v) { return v != 0; });
    if (solid == 0)
        throw std::domain_error("pore sizes: no solid voxel at M = " + std::to_string(voxels) +
                                " (no particle covers a voxel centre); the pore sizes are "
                                "undefined: use a larger M or check the packing");
    if (solid == total)
        throw std::domain_error("pore sizes: no void voxel at M = " + std::to_string(voxels) +
                                " (the particles cover every voxel centre); the pore-size "
                                "distribution is undefined: use a larger M or check the packing");
    checkPoreSizeMemory(voxels);

    std::vector<std::uint32_t> squared(total);
    const std::int64_t columnGrain = std::max<std::int64_t>(1, std::min<std::int64_t>(plane, 4096));
    parallelFor(
        0, plane, columnGrain,
        [&](std::int64_t b, std::int64_t e) {
            columnDistances(solidMask, squared.data(), voxels, b, e);
        },
        serial);
    parallelFor(
        0, voxels, 1,
        [&](std::int64_t b, std::int64_t e) {
            LineScratch scratch(voxels);
            for (std::int64_t i = b; i < e; ++i)
                planeDistances(squared.data() + i * plane, voxels, scratch);
        },
        serial);

    PoreSizeMap map(voxels, voxelSize, std::move(squared));
    map.voidCount_ = total - solid;
    map.maxSquaredDistance_ =
        *std::max_element(map.squaredDistances_.begin(), map.squaredDistances_.end());
    return map;
}

} // namespace sbpack

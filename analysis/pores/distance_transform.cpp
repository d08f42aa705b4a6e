#include "pores/distance_transform.hpp"

#include "parallel/available_memory.hpp"
#include "parallel/parallel.hpp"

#include <algorithm>
#include <cmath>
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

void checkVoxels(int voxels) {
    if (voxels < 1 || voxels > maxPoreSizeVoxels)
        throw std::invalid_argument("pore sizes: M = " + std::to_string(voxels) +
                                    " voxels per side is not in [1, " +
                                    std::to_string(maxPoreSizeVoxels) + "]");
}

/// Throws std::runtime_error with the estimate when `bytes` exceed MemAvailable.
void refuseUnlessAvailable(std::uint64_t bytes, int voxels, const std::string& what) {
    const double available = availableMemoryBytes().value_or(0.0);
    if (available > 0.0 && static_cast<double>(bytes) > available)
        throw std::runtime_error("pore sizes at M = " + std::to_string(voxels) + " need about " +
                                 gigabytes(bytes) + " (" + what + "), but only " +
                                 gigabytes(static_cast<std::uint64_t>(available)) +
                                 " are available (MemAvailable); choose a smaller M");
}

} // namespace

/// Scratch of one periodic line: the line with its periodic images on either side, and the
/// sites of the lower envelope with their breakpoints.
struct detail::LineScratch {
    explicit LineScratch(int voxels)
        : voxels(voxels), extended(2 * static_cast<std::size_t>(voxels) + 1), site(2 * voxels + 1),
          value(2 * voxels + 1), startNumerator(2 * voxels + 1), startDenominator(2 * voxels + 1) {}
    /// f(q) for 0 <= q < M, with room for images at -M/2 <= q < M + M/2.
    std::uint32_t* line() { return extended.data() + voxels / 2; }

    int voxels;
    std::vector<std::uint32_t> extended;
    std::vector<std::int64_t> site;  ///< position q' of each envelope parabola (images included)
    std::vector<std::int64_t> value; ///< f(q' mod M) of that parabola
    /// The parabola is the lowest for p > startNumerator / startDenominator (exact rational).
    std::vector<std::int64_t> startNumerator;
    std::vector<std::int64_t> startDenominator;
};

namespace {

using detail::LineScratch;

/// Copies a line (stride apart) into s.line(); returns the largest finite value, or kInfinite
/// if some value is infinite.
std::uint32_t loadLine(LineScratch& s, const std::uint32_t* source, std::int64_t stride) {
    std::uint32_t* f = s.line();
    std::uint32_t largest = 0;
    for (int q = 0; q < s.voxels; ++q) {
        f[q] = source[q * stride];
        largest = std::max(largest, f[q]);
    }
    return largest;
}

/// Lines whose values are all at most this squared take the local scan (cost ~ sqrt(out(p)) per
/// voxel, small in a dense packing); others, and lines with infinite values, the envelope.
constexpr std::uint32_t kLocalScanReach = 32;

/// The line's periodic min-plus transform (below) by scanning outwards from each p:
/// out(p) = min over |r| <= M / 2 with r^2 < out(p) of f(p + r) + r^2, stopping as soon as r^2
/// reaches the best value so far (no farther site can be lower). Exact; f must be finite.
void localScan(LineScratch& s, std::uint32_t largest, std::uint32_t* out, std::int64_t stride) {
    const int voxels = s.voxels;
    const std::int64_t reach = std::min<std::int64_t>(
        voxels / 2, static_cast<std::int64_t>(std::sqrt(static_cast<double>(largest))));
    std::uint32_t* e = s.line(); // images: e[q] = f(q mod M) for -reach <= q < M + reach
    std::copy(e + voxels - reach, e + voxels, e - reach);
    std::copy(e, e + reach, e + voxels);
    for (std::int64_t p = 0; p < voxels; ++p) {
        std::uint32_t best = e[p];
        for (std::int64_t r = 1; r <= reach && static_cast<std::uint32_t>(r * r) < best; ++r)
            best = std::min(best, std::min(e[p - r], e[p + r]) + static_cast<std::uint32_t>(r * r));
        out[p * stride] = best;
    }
}

/// One-dimensional periodic min-plus transform (Felzenszwalb-Huttenlocher):
///   out(p) = min_q [ f(q) + (min-image |p - q|)^2 ],  p, q in [0, M),  f = kInfinite: no site.
/// The periodic images q' = q +- M of the sites enter as further parabolas; only those within
/// sqrt(max f) of the line ends can win (out(p) <= f(p)), and none farther than M / 2.
/// Breakpoints are exact rationals compared by integer cross-multiplication (|numerator| < 2^33,
/// denominator < 2^17 for M <= maxPoreSizeVoxels), so the envelope is exact. Sites inside a run
/// of zeros (solid voxels) are skipped: outside the run an end of it is nearer, and inside it the
/// answer is 0.
void lowerEnvelope(LineScratch& s, std::uint32_t largest, std::uint32_t* out, std::int64_t stride) {
    const int voxels = s.voxels;
    const std::uint32_t* f = s.line();
    std::int64_t pad = voxels / 2;
    if (largest != kInfinite) {
        const auto reach = static_cast<std::int64_t>(std::sqrt(static_cast<double>(largest)));
        pad = std::min<std::int64_t>(pad, reach + 1);
    }
    std::int64_t* site = s.site.data();
    std::int64_t* value = s.value.data();
    std::int64_t* startNumerator = s.startNumerator.data();
    std::int64_t* startDenominator = s.startDenominator.data();
    auto wrap = [voxels](std::int64_t q) { // for -M <= q < 2M
        return q < 0 ? q + voxels : (q >= voxels ? q - voxels : q);
    };
    int top = -1; // index of the last parabola of the envelope
    for (std::int64_t q = -pad; q < voxels + pad; ++q) {
        const std::uint32_t fq = f[wrap(q)];
        if (fq == kInfinite) continue;
        if (fq == 0 && f[wrap(q - 1)] == 0 && f[wrap(q + 1)] == 0) continue; // inside zeros
        const std::int64_t height = fq + q * q; // parabola (p - q)^2 + f(q) = p^2 - 2pq + height
        std::int64_t numerator = 0, denominator = 1;
        while (top >= 0) {
            // Real intersection with the top parabola: (height - height_top) / (2 (q - q_top));
            // q is lower above it. Pop the top if that is not above the top's own start (the
            // first parabola, starting at -infinity, stays).
            numerator = height - (value[top] + site[top] * site[top]);
            denominator = 2 * (q - site[top]);
            if (top == 0 || numerator * startDenominator[top] > startNumerator[top] * denominator)
                break;
            --top;
        }
        ++top;
        site[top] = q;
        value[top] = fq;
        startNumerator[top] = numerator;
        startDenominator[top] = denominator;
    }
    if (top < 0) { // no site (or only zeros, all skipped): infinite or solid
        for (int p = 0; p < voxels; ++p)
            out[p * stride] = f[p] == 0 ? 0u : kInfinite;
        return;
    }
    // Parabola j is the lowest on the integers [first_j, first_{j+1}), first_j = floor(start) + 1;
    // the floor of the double quotient is exact (its rounding error < 2^-20 is below the
    // distance 1 / denominator >= 2^-17 of a non-integer quotient from any integer).
    std::int64_t p = 0;
    for (int j = 0; j <= top && p < voxels; ++j) {
        std::int64_t end = voxels;
        if (j < top)
            end =
                std::min<std::int64_t>(voxels, static_cast<std::int64_t>(std::floor(
                                                   static_cast<double>(startNumerator[j + 1]) /
                                                   static_cast<double>(startDenominator[j + 1]))) +
                                                   1);
        const std::int64_t q = site[j], h = value[j];
        for (; p < end; ++p) // zeros inside a skipped run stay zero
            out[p * stride] = f[p] == 0 ? 0u : static_cast<std::uint32_t>((p - q) * (p - q) + h);
    }
}

/// out(p * stride) = min_q [ f(q) + (min-image |p - q|)^2 ] of the periodic line in s.line(),
/// whose largest value (kInfinite if any is infinite) loadLine returned.
void periodicLineTransform(LineScratch& s, std::uint32_t largest, std::uint32_t* out,
                           std::int64_t stride) {
    if (largest <= kLocalScanReach * kLocalScanReach)
        localScan(s, largest, out, stride);
    else
        lowerEnvelope(s, largest, out, stride);
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

/// Second and third passes within one plane i: along y (j, stride M), then along z (k,
/// contiguous). Returns the plane's largest squared distance.
std::uint32_t planeDistances(std::uint32_t* planeData, LineScratch& scratch) {
    const int voxels = scratch.voxels;
    for (int k = 0; k < voxels; ++k) {
        const std::uint32_t largest = loadLine(scratch, planeData + k, voxels);
        periodicLineTransform(scratch, largest, planeData + k, voxels);
    }
    std::uint32_t planeLargest = 0;
    for (int j = 0; j < voxels; ++j) {
        std::uint32_t* line = planeData + static_cast<std::int64_t>(j) * voxels;
        periodicLineTransform(scratch, loadLine(scratch, line, 1), line, 1);
        planeLargest = std::max(planeLargest, *std::max_element(line, line + voxels));
    }
    return planeLargest;
}

} // namespace

PeriodicLineTransform::PeriodicLineTransform(int voxels)
    : scratch_(std::make_unique<LineScratch>(voxels)) {}
PeriodicLineTransform::~PeriodicLineTransform() = default;

std::uint32_t PeriodicLineTransform::operator()(std::uint32_t* line, std::int64_t stride) {
    periodicLineTransform(*scratch_, loadLine(*scratch_, line, stride), line, stride);
    std::uint32_t largest = 0;
    for (int p = 0; p < scratch_->voxels; ++p)
        largest = std::max(largest, line[p * stride]);
    return largest;
}

std::uint64_t poreSizeMemoryBytes(int voxels) {
    const auto m = static_cast<std::uint64_t>(std::max(voxels, 0));
    return m * m * m * (sizeof(std::uint8_t) + sizeof(std::uint32_t));
}

void checkPoreSizeMemory(int voxels) {
    checkVoxels(voxels);
    refuseUnlessAvailable(poreSizeMemoryBytes(voxels), voxels,
                          "1-byte solid mask + 4-byte squared distance per voxel");
}

PoreSizeMap::PoreSizeMap(int voxels, double voxelSize) : voxels_(voxels), voxelSize_(voxelSize) {
    // Default-initialised (no zeroing pass): the first pass writes every entry.
    const std::int64_t m = voxels;
    squaredDistances_.reset(new std::uint32_t[m * m * m]);
}

std::span<const std::uint32_t> PoreSizeMap::squaredDistances() const {
    const std::size_t m = static_cast<std::size_t>(voxels_);
    return {squaredDistances_.get(), m * m * m};
}

PoreSizeMap periodicDistanceTransform(std::span<const std::uint8_t> solidMask, int voxels,
                                      double voxelSize, bool serial) {
    checkVoxels(voxels);
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
    refuseUnlessAvailable(static_cast<std::uint64_t>(total) * sizeof(std::uint32_t), voxels,
                          "4-byte squared distance per voxel");

    PoreSizeMap map(voxels, voxelSize);
    std::uint32_t* squared = map.squaredDistances_.get();
    const std::int64_t columnGrain = std::max<std::int64_t>(1, std::min<std::int64_t>(plane, 4096));
    parallelFor(
        0, plane, columnGrain,
        [&](std::int64_t b, std::int64_t e) { columnDistances(solidMask, squared, voxels, b, e); },
        serial);
    std::vector<std::uint32_t> planeLargest(voxels);
    parallelFor(
        0, voxels, 1,
        [&](std::int64_t b, std::int64_t e) {
            LineScratch scratch(voxels);
            for (std::int64_t i = b; i < e; ++i)
                planeLargest[i] = planeDistances(squared + i * plane, scratch);
        },
        serial);
    map.voidCount_ = total - solid;
    map.maxSquaredDistance_ = *std::max_element(planeLargest.begin(), planeLargest.end());
    return map;
}

} // namespace sbpack

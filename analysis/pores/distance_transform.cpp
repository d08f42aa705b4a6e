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
    LineScratch(int voxels, bool withFeatures)
        : voxels(voxels), extended(2 * static_cast<std::size_t>(voxels) + 1),
          features(withFeatures ? voxels : 0), site(2 * voxels + 1), value(2 * voxels + 1),
          startNumerator(2 * voxels + 1), startDenominator(2 * voxels + 1) {}
    /// f(q) for 0 <= q < M, with room for images at -M/2 <= q < M + M/2.
    std::uint32_t* line() { return extended.data() + voxels / 2; }

    int voxels;
    std::vector<std::uint32_t> extended;
    /// Feature transform only: the nearest solid voxel of each voxel of the line before the pass.
    std::vector<std::uint32_t> features;
    std::vector<std::int64_t> site;  ///< position q' of each envelope parabola (images included)
    std::vector<std::int64_t> value; ///< f(q' mod M) of that parabola
    /// The parabola is the lowest for p > startNumerator / startDenominator (exact rational).
    std::vector<std::int64_t> startNumerator;
    std::vector<std::int64_t> startDenominator;
};

namespace {

using detail::LineScratch;

/// Where a line pass writes: the squared distances and, for the feature transform, the nearest
/// solid voxels (nullptr without), `stride` apart.
struct LineOutput {
    std::uint32_t* squared;
    std::uint32_t* features;
    std::int64_t stride;
};

/// Copies a line (out.stride apart) into s.line(), and its features into s.features; returns the
/// largest finite value, or kInfinite if some value is infinite.
std::uint32_t loadLine(LineScratch& s, const LineOutput& out) {
    std::uint32_t* f = s.line();
    std::uint32_t largest = 0;
    for (int q = 0; q < s.voxels; ++q) {
        f[q] = out.squared[q * out.stride];
        largest = std::max(largest, f[q]);
    }
    if (out.features != nullptr)
        for (int q = 0; q < s.voxels; ++q)
            s.features[q] = out.features[q * out.stride];
    return largest;
}

/// Lines whose values are all at most this squared take the local scan (cost ~ sqrt(out(p)) per
/// voxel, small in a dense packing); others, and lines with infinite values, the envelope.
constexpr std::uint32_t kLocalScanReach = 32;

/// Index q mod M of a site or image, -M <= q < 2M.
inline std::int64_t wrapSite(std::int64_t q, int voxels) {
    return q < 0 ? q + voxels : (q >= voxels ? q - voxels : q);
}

/// The line's periodic min-plus transform (below) by scanning outwards from each p:
/// out(p) = min over |r| <= M / 2 with r^2 < out(p) of f(p + r) + r^2, stopping as soon as r^2
/// reaches the best value so far (no farther site can be lower). Exact; f must be finite. With
/// features, the winning site's feature (the lower r, then the lower side, on ties).
void localScan(LineScratch& s, std::uint32_t largest, const LineOutput& out) {
    const int voxels = s.voxels;
    const std::int64_t reach = std::min<std::int64_t>(
        voxels / 2, static_cast<std::int64_t>(std::sqrt(static_cast<double>(largest))));
    std::uint32_t* e = s.line(); // images: e[q] = f(q mod M) for -reach <= q < M + reach
    std::copy(e + voxels - reach, e + voxels, e - reach);
    std::copy(e, e + reach, e + voxels);
    const std::int64_t stride = out.stride;
    if (out.features == nullptr) {
        for (std::int64_t p = 0; p < voxels; ++p) {
            std::uint32_t best = e[p];
            for (std::int64_t r = 1; r <= reach && static_cast<std::uint32_t>(r * r) < best; ++r)
                best = std::min(best,
                                std::min(e[p - r], e[p + r]) + static_cast<std::uint32_t>(r * r));
            out.squared[p * stride] = best;
        }
        return;
    }
    for (std::int64_t p = 0; p < voxels; ++p) {
        std::uint32_t best = e[p];
        std::int64_t at = p;
        for (std::int64_t r = 1; r <= reach && static_cast<std::uint32_t>(r * r) < best; ++r) {
            const auto square = static_cast<std::uint32_t>(r * r);
            if (e[p - r] + square < best) best = e[p - r] + square, at = p - r;
            if (e[p + r] + square < best) best = e[p + r] + square, at = p + r;
        }
        out.squared[p * stride] = best;
        out.features[p * stride] = s.features[wrapSite(at, voxels)];
    }
}

/// Writes the lower envelope of lowerEnvelope's parabolas 0..top: parabola j is the lowest on the
/// integers [first_j, first_{j+1}), first_j = floor(start) + 1; the floor of the double quotient
/// is exact (its rounding error < 2^-20 is below the distance 1 / denominator >= 2^-17 of a
/// non-integer quotient from any integer). Zeros inside a skipped run stay zero (and their own
/// feature).
void writeEnvelope(const LineScratch& s, int top, const LineOutput& out) {
    const int voxels = s.voxels;
    const std::uint32_t* f = s.extended.data() + voxels / 2;
    const std::int64_t stride = out.stride;
    std::int64_t p = 0;
    for (int j = 0; j <= top && p < voxels; ++j) {
        std::int64_t end = voxels;
        if (j < top)
            end = std::min<std::int64_t>(
                voxels, static_cast<std::int64_t>(
                            std::floor(static_cast<double>(s.startNumerator[j + 1]) /
                                       static_cast<double>(s.startDenominator[j + 1]))) +
                            1);
        const std::int64_t q = s.site[j], h = s.value[j];
        const std::int64_t begin = p;
        for (; p < end; ++p)
            out.squared[p * stride] =
                f[p] == 0 ? 0u : static_cast<std::uint32_t>((p - q) * (p - q) + h);
        if (out.features != nullptr) {
            const std::uint32_t feature = s.features[wrapSite(q, voxels)];
            for (std::int64_t r = begin; r < end; ++r)
                if (f[r] != 0) out.features[r * stride] = feature;
        }
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
void lowerEnvelope(LineScratch& s, std::uint32_t largest, const LineOutput& out) {
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
    auto wrap = [voxels](std::int64_t q) { return wrapSite(q, voxels); };
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
    if (top < 0) { // no site (or only zeros, all skipped): infinite or solid; features stay
        for (int p = 0; p < voxels; ++p)
            out.squared[p * out.stride] = f[p] == 0 ? 0u : kInfinite;
        return;
    }
    writeEnvelope(s, top, out);
}
/// out(p * stride) = min_q [ f(q) + (min-image |p - q|)^2 ] of the periodic line in s.line(),
/// whose largest value (kInfinite if any is infinite) loadLine returned.
void periodicLineTransform(LineScratch& s, std::uint32_t largest, const LineOutput& out) {
    if (largest <= kLocalScanReach * kLocalScanReach)
        localScan(s, largest, out);
    else
        lowerEnvelope(s, largest, out);
}

/// The columns [columnBegin, columnEnd) of the first pass, with the x index of each column's
/// nearest solid voxel when the features are wanted.
struct ColumnBlock {
    std::int64_t begin, width;
    /// Distance seeds across the periodic boundary: from i = -1 to the last solid (as its image at
    /// last - M) and from i = M to the first solid (image at first + M); kInfinite without solid.
    std::vector<std::uint32_t> before, after;
    std::vector<std::uint32_t> lastSolid, firstSolid; ///< features only: those solids' i
};

ColumnBlock columnSeeds(std::span<const std::uint8_t> mask, int voxels, std::int64_t columnBegin,
                        std::int64_t columnEnd, bool withFeatures) {
    const std::int64_t plane = static_cast<std::int64_t>(voxels) * voxels;
    const std::int64_t width = columnEnd - columnBegin;
    ColumnBlock b{columnBegin,
                  width,
                  std::vector<std::uint32_t>(width, kInfinite),
                  std::vector<std::uint32_t>(width, kInfinite),
                  {},
                  {}};
    if (withFeatures) b.lastSolid.assign(width, 0), b.firstSolid.assign(width, 0);
    std::int64_t missing = width;
    for (int i = voxels - 1; i >= 0 && missing > 0; --i) {
        const std::uint8_t* row = mask.data() + i * plane + columnBegin;
        for (std::int64_t c = 0; c < width; ++c)
            if (row[c] != 0 && b.before[c] == kInfinite) {
                b.before[c] = static_cast<std::uint32_t>(voxels - 1 - i);
                if (withFeatures) b.lastSolid[c] = static_cast<std::uint32_t>(i);
                --missing;
            }
    }
    missing = width;
    for (int i = 0; i < voxels && missing > 0; ++i) {
        const std::uint8_t* row = mask.data() + i * plane + columnBegin;
        for (std::int64_t c = 0; c < width; ++c)
            if (row[c] != 0 && b.after[c] == kInfinite) {
                b.after[c] = static_cast<std::uint32_t>(i);
                if (withFeatures) b.firstSolid[c] = static_cast<std::uint32_t>(i);
                --missing;
            }
    }
    return b;
}

/// First pass, along x (i): the 1-D periodic distance g to the nearest solid voxel of each column
/// (j, k), written as g^2, kInfinite for a column without solid. Planes i are swept forwards and
/// backwards over a block of columns, so that memory is read in contiguous runs.
void columnDistances(std::span<const std::uint8_t> mask, std::uint32_t* out, int voxels,
                     std::int64_t columnBegin, std::int64_t columnEnd) {
    const std::int64_t plane = static_cast<std::int64_t>(voxels) * voxels;
    ColumnBlock b = columnSeeds(mask, voxels, columnBegin, columnEnd, false);
    const std::int64_t width = b.width;
    // Forward: g(i) = 0 on solid, g(i - 1) + 1 otherwise (infinite stays infinite).
    std::vector<std::uint32_t>& previous = b.before; // g(i - 1), updated in place
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
    std::vector<std::uint32_t>& following = b.after; // g(i + 1), updated in place
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

/// The first pass as columnDistances, with the features: features[(i * M + j) * M + k] = the
/// index (i' * M + j) * M + k of the column's nearest solid voxel (either on ties, the image
/// across the boundary counted), garbage in a column without solid (its distances are
/// infinite, so the later passes never take it).
void columnDistancesAndFeatures(std::span<const std::uint8_t> mask, std::uint32_t* out,
                                std::uint32_t* features, int voxels, std::int64_t columnBegin,
                                std::int64_t columnEnd) {
    const std::int64_t plane = static_cast<std::int64_t>(voxels) * voxels;
    ColumnBlock b = columnSeeds(mask, voxels, columnBegin, columnEnd, true);
    const std::int64_t width = b.width;
    std::vector<std::uint32_t>& previous = b.before; // g(i - 1)
    std::vector<std::uint32_t>& previousSite = b.lastSolid;
    for (int i = 0; i < voxels; ++i) {
        const std::uint8_t* row = mask.data() + i * plane + columnBegin;
        std::uint32_t* g = out + i * plane + columnBegin;
        std::uint32_t* site = features + i * plane + columnBegin; // i' for now
        for (std::int64_t c = 0; c < width; ++c) {
            const bool solid = row[c] != 0;
            g[c] = solid ? 0u : previous[c] + (previous[c] != kInfinite ? 1u : 0u);
            site[c] = solid ? static_cast<std::uint32_t>(i) : previousSite[c];
            previous[c] = g[c];
            previousSite[c] = site[c];
        }
    }
    std::vector<std::uint32_t>& following = b.after; // g(i + 1)
    std::vector<std::uint32_t>& followingSite = b.firstSolid;
    for (int i = voxels - 1; i >= 0; --i) {
        std::uint32_t* g = out + i * plane + columnBegin;
        std::uint32_t* site = features + i * plane + columnBegin;
        for (std::int64_t c = 0; c < width; ++c) {
            const std::uint32_t next = following[c] + (following[c] != kInfinite ? 1u : 0u);
            if (next < g[c]) g[c] = next, site[c] = followingSite[c];
            following[c] = g[c];
            followingSite[c] = site[c];
            g[c] = g[c] == kInfinite ? kInfinite : g[c] * g[c];
            site[c] = static_cast<std::uint32_t>(site[c] * plane + columnBegin + c);
        }
    }
}

/// Second and third passes within one plane i: along y (j, stride M), then along z (k,
/// contiguous); with the features when `planeFeatures` is not null. Returns the plane's largest
/// squared distance.
std::uint32_t planeDistances(std::uint32_t* planeData, std::uint32_t* planeFeatures,
                             LineScratch& scratch) {
    const int voxels = scratch.voxels;
    const bool withFeatures = planeFeatures != nullptr;
    for (int k = 0; k < voxels; ++k) {
        const LineOutput out{planeData + k, withFeatures ? planeFeatures + k : nullptr, voxels};
        periodicLineTransform(scratch, loadLine(scratch, out), out);
    }
    std::uint32_t planeLargest = 0;
    for (int j = 0; j < voxels; ++j) {
        const std::int64_t offset = static_cast<std::int64_t>(j) * voxels;
        const LineOutput out{planeData + offset, withFeatures ? planeFeatures + offset : nullptr,
                             1};
        periodicLineTransform(scratch, loadLine(scratch, out), out);
        planeLargest = std::max(planeLargest, *std::max_element(out.squared, out.squared + voxels));
    }
    return planeLargest;
}

} // namespace

PeriodicLineTransform::PeriodicLineTransform(int voxels)
    : scratch_(std::make_unique<LineScratch>(voxels, false)) {}
PeriodicLineTransform::~PeriodicLineTransform() = default;

std::uint32_t PeriodicLineTransform::operator()(std::uint32_t* line, std::int64_t stride) {
    const LineOutput out{line, nullptr, stride};
    periodicLineTransform(*scratch_, loadLine(*scratch_, out), out);
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

PoreSizeMap::PoreSizeMap(int voxels, double voxelSize, std::unique_ptr<std::uint32_t[]> squared)
    : voxels_(voxels), voxelSize_(voxelSize), squaredDistances_(std::move(squared)) {}

std::span<const std::uint32_t> PoreSizeMap::squaredDistances() const {
    const std::size_t m = static_cast<std::size_t>(voxels_);
    return {squaredDistances_.get(), m * m * m};
}

std::span<const std::uint32_t> PoreSizeMap::features() const {
    const std::size_t m = static_cast<std::size_t>(voxels_);
    return features_ ? std::span<const std::uint32_t>(features_.get(), m * m * m)
                     : std::span<const std::uint32_t>();
}

namespace {

/// Throws for a mask or voxel size periodicDistanceTransform refuses; returns the solid count.
std::int64_t checkMask(std::span<const std::uint8_t> solidMask, int voxels, double voxelSize) {
    checkVoxels(voxels);
    const std::int64_t total = static_cast<std::int64_t>(voxels) * voxels * voxels;
    if (static_cast<std::int64_t>(solidMask.size()) != total)
        throw std::invalid_argument("distance transform: the solid mask has " +
                                    std::to_string(solidMask.size()) +
                                    " entries, not M^3 = " + std::to_string(total));
    if (!(std::isfinite(voxelSize) && voxelSize > 0.0))
        throw std::invalid_argument("distance transform: voxel size " + std::to_string(voxelSize) +
                                    " is not finite and positive");
    const std::int64_t solid =
        std::count_if(solidMask.begin(), solidMask.end(), [](std::uint8_t v) { return v != 0; });
    checkSolidCount(solid, voxels);
    return solid;
}

} // namespace

PoreSizeMap transformMask(std::span<const std::uint8_t> solidMask, int voxels, double voxelSize,
                          const Progress& progress, bool withFeatures) {
    if (withFeatures && voxels > maxFeatureTransformVoxels)
        throw std::invalid_argument("feature transform: M = " + std::to_string(voxels) +
                                    " is above " + std::to_string(maxFeatureTransformVoxels) +
                                    " (voxel indices are 32-bit)");
    const std::int64_t solid = checkMask(solidMask, voxels, voxelSize);
    const std::int64_t plane = static_cast<std::int64_t>(voxels) * voxels;
    const std::int64_t total = plane * voxels;
    refuseUnlessAvailable(
        static_cast<std::uint64_t>(total) * sizeof(std::uint32_t) * (withFeatures ? 2 : 1), voxels,
        withFeatures ? "4-byte squared distance and 4-byte feature per voxel"
                     : "4-byte squared distance per voxel");
    PoreSizeMap map(voxels, voxelSize);
    std::uint32_t* squared = map.squaredDistances_.get();
    std::uint32_t* features = nullptr;
    if (withFeatures) {
        map.features_.reset(new std::uint32_t[total]);
        features = map.features_.get();
    }
    const std::int64_t columnGrain = std::max<std::int64_t>(1, std::min<std::int64_t>(plane, 4096));
    parallelFor(
        0, plane, columnGrain,
        [&](std::int64_t b, std::int64_t e) {
            progress.checkInterrupt(); // a stop ends the transform at its next chunk
            if (features != nullptr)
                columnDistancesAndFeatures(solidMask, squared, features, voxels, b, e);
            else
                columnDistances(solidMask, squared, voxels, b, e);
        },
        progress);
    std::vector<std::uint32_t> planeLargest(voxels);
    parallelFor(
        0, voxels, 1,
        [&](std::int64_t b, std::int64_t e) {
            progress.checkInterrupt();
            LineScratch scratch(voxels, features != nullptr);
            for (std::int64_t i = b; i < e; ++i)
                planeLargest[i] =
                    planeDistances(squared + i * plane,
                                   features != nullptr ? features + i * plane : nullptr, scratch);
        },
        progress);
    map.voidCount_ = total - solid;
    map.maxSquaredDistance_ = *std::max_element(planeLargest.begin(), planeLargest.end());
    return map;
}

void checkSolidCount(std::int64_t solid, int voxels) {
    const std::int64_t total = static_cast<std::int64_t>(voxels) * voxels * voxels;
    if (solid == 0)
        throw std::domain_error("pore sizes: no solid voxel at M = " + std::to_string(voxels) +
                                " (no particle covers a voxel centre); the pore sizes are "
                                "undefined: use a larger M or check the packing");
    if (solid == total)
        throw std::domain_error("pore sizes: no void voxel at M = " + std::to_string(voxels) +
                                " (the particles cover every voxel centre); the pore-size "
                                "distribution is undefined: use a larger M or check the packing");
}

PoreSizeMap PoreSizeMap::fromSquaredDistances(std::unique_ptr<std::uint32_t[]> squared, int voxels,
                                              double voxelSize, std::int64_t voidCount,
                                              std::uint32_t maxSquaredDistance) {
    checkVoxels(voxels);
    PoreSizeMap map(voxels, voxelSize, std::move(squared));
    map.voidCount_ = voidCount;
    map.maxSquaredDistance_ = maxSquaredDistance;
    return map;
}

PoreSizeMap periodicDistanceTransform(std::span<const std::uint8_t> solidMask, int voxels,
                                      double voxelSize, const Progress& progress) {
    return transformMask(solidMask, voxels, voxelSize, progress, false);
}

PoreSizeMap periodicFeatureTransform(std::span<const std::uint8_t> solidMask, int voxels,
                                     double voxelSize, const Progress& progress) {
    return transformMask(solidMask, voxels, voxelSize, progress, true);
}

} // namespace sbpack

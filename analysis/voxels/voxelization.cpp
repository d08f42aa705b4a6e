// The only translation unit of sbanalyze that includes OpenVDB's tree, whose headers are slow to
// build (bench/RESULTS.md, "Measurement history moved out of code comments").
#include "voxels/voxelization.hpp"

#include "grid/voxel_rows.hpp"
#include "io/atomic_file.hpp"
#include "parallel/parallel.hpp"
#include "voxels/vdb_image.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/ValueTransformer.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sbpack {

namespace {

using MaskTree = openvdb::MaskTree;
using MaskLeaf = MaskTree::LeafNodeType;

/// Output blocks are the leaves of the tree: 8^3 voxels, one 64-bit word per x-slice with bit
/// (y << 3) | z, as OpenVDB's leaf offset (x << 6) | (y << 3) | z.
constexpr int kBlock = 8;
static_assert(MaskLeaf::DIM == kBlock);
/// Blocks per task of the parallel loop (and per interrupt check).
constexpr std::int64_t kBlocksPerTask = 16;
/// Relative margin of the inscribed- and circumscribed-sphere shortcuts: voxel centres this close
/// to either sphere get the exact test, so the shortcuts agree with the shape's inside test
/// exactly.
constexpr double kSphereMargin = 1e-12;

/// A particle, or one of its periodic images, whose circumscribed sphere reaches a block.
struct Candidate {
    Vector3d centre;
    int particle;
};

using grid::voxelRange;

/// Bits z0..z1 (inclusive, within one 8-voxel row) of a block word, the row starting at `shift`.
std::uint64_t rowBits(int z0, int z1, int shift) {
    return ((std::uint64_t{1} << (z1 - z0 + 1)) - 1) << (shift + z0);
}

/// The geometry shared by all blocks.
struct BlockGeometry {
    int m;                    ///< voxels per edge
    double a;                 ///< voxel edge
    double rc, ri;            ///< circumscribed and inscribed radii, with the shortcut margin
    int x0, x1;               ///< the slab: x-planes [x0, x1)
    int blocks;               ///< blocks along y and z
    int firstBlockX, blocksX; ///< the x-blocks the slab touches

    /// A mixture's R_j / R (docs/mixtures.md); empty for identical particles.
    std::vector<double> sizes;

    std::int64_t blockCount() const { return std::int64_t{blocksX} * blocks * blocks; }
    /// Particle j's size over the largest.
    double size(int j) const { return sizes.empty() ? 1.0 : sizes[j]; }
    /// Origin (voxel indices) of block b of the slab's blocks.
    std::array<int, 3> origin(std::int64_t b) const {
        const std::int64_t plane = std::int64_t{blocks} * blocks;
        return {static_cast<int>(b / plane + firstBlockX) * kBlock,
                static_cast<int>((b / blocks) % blocks) * kBlock,
                static_cast<int>(b % blocks) * kBlock};
    }
};

/// The bits (rowBits at `shift`) of the solid voxels of one row z0..z1 of one particle: an
/// interval, the body being convex. `inner` is solid without a test (inner.first > inner.last:
/// none); the test runs from each end inwards up to the first solid voxel.
template <class Solid>
std::uint64_t rowWord(int z0, int z1, grid::IndexRange inner, int shift, const Solid& solidAt) {
    const auto [in0, in1] = inner;
    if (in0 <= in1) {
        std::uint64_t word = rowBits(in0, in1, shift);
        for (int z = z0; z < in0; ++z)
            if (solidAt(z)) {
                word |= rowBits(z, in0 - 1, shift);
                break;
            }
        for (int z = z1; z > in1; --z)
            if (solidAt(z)) {
                word |= rowBits(in1 + 1, z, shift);
                break;
            }
        return word;
    }
    int first = z0;
    while (first <= z1 && !solidAt(first))
        ++first;
    if (first > z1) return 0;
    int last = z1;
    while (last > first && !solidAt(last))
        --last;
    return rowBits(first, last, shift);
}

/// Calls row(particle, x - ox, word) with the solid voxels of each candidate in each row (x, y)
/// of block (ox, oy, oz) it reaches, as rowBits. Per row one particle's solid voxels form an
/// interval (the body is convex): the inscribed sphere's part is solid without a test, and the
/// exact test runs from each end of the circumscribed sphere's part inwards up to the first solid
/// voxel. A mixture's particle j has both spheres scaled by its size s_j, and toBody[j] carries
/// 1 / s_j, so that the largest particle's test decides for it (bodyRotations).
template <class Row>
void forEachCandidateRow(int ox, int oy, int oz, std::span<const Candidate> candidates,
                         const std::vector<Eigen::Matrix3d>& toBody,
                         const ParticleShape::InsideTest& inside, const BlockGeometry& g,
                         const Row& row) {
    const int lastX = std::min(g.x1, ox + kBlock) - 1;
    const int firstX = std::max(g.x0, ox);
    const int lastY = std::min(g.m, oy + kBlock) - 1;
    const int lastZ = std::min(g.m, oz + kBlock) - 1;
    for (const Candidate& candidate : candidates) {
        const Vector3d& c = candidate.centre;
        const Eigen::Matrix3d& rotation = toBody[candidate.particle];
        const double rc = g.rc * g.size(candidate.particle), ri = g.ri * g.size(candidate.particle);
        const double rc2 = rc * rc, ri2 = ri * ri;
        const auto [x0, x1] = voxelRange(c.x(), rc, g.a, firstX, lastX);
        const auto [y0, y1] = voxelRange(c.y(), rc, g.a, oy, lastY);
        for (int x = x0; x <= x1; ++x) {
            const double dx = (x + 0.5) * g.a - c.x();
            for (int y = y0; y <= y1; ++y) {
                const double dy = (y + 0.5) * g.a - c.y();
                const double rxy2 = dx * dx + dy * dy;
                if (rxy2 >= rc2) continue;
                const auto [z0, z1] = voxelRange(c.z(), std::sqrt(rc2 - rxy2), g.a, oz, lastZ);
                if (z0 > z1) continue;
                auto solidAt = [&](int z) {
                    return inside(rotation * Vector3d(dx, dy, (z + 0.5) * g.a - c.z()));
                };
                const grid::IndexRange inner =
                    rxy2 < ri2 ? voxelRange(c.z(), std::sqrt(ri2 - rxy2), g.a, z0, z1)
                               : grid::IndexRange{z1 + 1, z1};
                row(candidate.particle, x - ox,
                    rowWord(z0, z1, inner, (y - oy) * kBlock - oz, solidAt));
            }
        }
    }
}

/// The 8 words of block (ox, oy, oz) from its candidates.
std::array<std::uint64_t, kBlock> voxelizeBlock(int ox, int oy, int oz,
                                                std::span<const Candidate> candidates,
                                                const std::vector<Eigen::Matrix3d>& toBody,
                                                const ParticleShape::InsideTest& inside,
                                                const BlockGeometry& g) {
    std::array<std::uint64_t, kBlock> words{};
    forEachCandidateRow(ox, oy, oz, candidates, toBody, inside, g,
                        [&](int, int x, std::uint64_t word) { words[x] |= word; });
    return words;
}

/// Writes block (ox, oy, oz) of the tree into values[((x - x0) * m + y) * rowStride + z] as 0
/// or 1, for the planes x0 <= x < x1.
template <class T>
void copyBlock(const MaskTree& tree, std::int64_t ox, std::int64_t oy, std::int64_t oz,
               std::int64_t m, std::int64_t x0, std::int64_t x1, T* values,
               std::int64_t rowStride) {
    const openvdb::Coord origin(static_cast<openvdb::Int32>(ox), static_cast<openvdb::Int32>(oy),
                                static_cast<openvdb::Int32>(oz));
    const MaskLeaf* leaf = tree.probeConstLeaf(origin);
    const bool tile = leaf == nullptr && tree.isValueOn(origin);
    for (std::int64_t x = std::max(ox, x0); x < std::min(x1, ox + kBlock); ++x) {
        const std::uint64_t word =
            leaf != nullptr
                ? leaf->getValueMask().getWord<std::uint64_t>(static_cast<openvdb::Index>(x - ox))
                : (tile ? ~std::uint64_t{0} : 0);
        for (std::int64_t y = oy; y < std::min(m, oy + kBlock); ++y) {
            T* row = values + ((x - x0) * m + y) * rowStride;
            const std::int64_t shift = (y - oy) * kBlock - oz;
            for (std::int64_t z = oz; z < std::min(m, oz + kBlock); ++z)
                row[z] = static_cast<T>((word >> (shift + z)) & 1);
        }
    }
}

} // namespace

struct Voxelization::Grid {
    openvdb::MaskGrid::Ptr grid;
};

Voxelization::Voxelization(std::unique_ptr<Grid> grid, VoxelizationParameters parameters,
                           double boxLength, const ShapeSpec& shape, double phiExact,
                           std::int64_t solidCount, double runtimeSeconds)
    : grid_(std::move(grid)), parameters_(parameters), voxels_(parameters.voxels),
      boxLength_(boxLength), shape_(shape), phiExact_(phiExact), solidCount_(solidCount),
      runtimeSeconds_(runtimeSeconds), slabBegin_(parameters.slabBegin),
      slabEnd_(parameters.slabEnd) {}

Voxelization::Voxelization(Voxelization&&) noexcept = default;
Voxelization& Voxelization::operator=(Voxelization&&) noexcept = default;
Voxelization::~Voxelization() = default;

double Voxelization::phiVoxel() const {
    const auto m = static_cast<double>(voxels_);
    if (slabEnd_ == slabBegin_) return 0.0;
    return static_cast<double>(solidCount_) / (m * m * (slabEnd_ - slabBegin_));
}

std::size_t Voxelization::memoryBytes() const {
    return static_cast<std::size_t>(grid_->grid->memUsage());
}

bool Voxelization::solid(std::int64_t i, std::int64_t j, std::int64_t k) const {
    auto wrap = [m = std::int64_t{voxels_}](std::int64_t v) { return ((v % m) + m) % m; };
    return grid_->grid->tree().isValueOn(openvdb::Coord(static_cast<openvdb::Int32>(wrap(i)),
                                                        static_cast<openvdb::Int32>(wrap(j)),
                                                        static_cast<openvdb::Int32>(wrap(k))));
}

template <class T>
void Voxelization::copySolid(std::span<T> values, std::int64_t rowStride, const char* what,
                             const Progress& progress) const {
    const std::int64_t m = voxels_, x0 = slabBegin_, x1 = slabEnd_;
    if (rowStride < m || values.size() != static_cast<std::size_t>((x1 - x0) * m * rowStride))
        throw std::invalid_argument(std::string(what) + ": the destination has " +
                                    std::to_string(values.size()) + " entries, not " +
                                    std::to_string(x1 - x0) + " * M * " +
                                    std::to_string(rowStride) + " for M = " + std::to_string(m));
    const MaskTree& tree = grid_->grid->tree();
    const std::int64_t blocks = (m + kBlock - 1) / kBlock;
    // One task per slab of 8 x-planes: contiguous output, no two tasks share a cache line.
    parallelFor(
        x0 / kBlock, (x1 + kBlock - 1) / kBlock, 1,
        [&](std::int64_t begin, std::int64_t end) {
            for (std::int64_t bx = begin; bx < end; ++bx)
                for (std::int64_t by = 0; by < blocks; ++by)
                    for (std::int64_t bz = 0; bz < blocks; ++bz)
                        copyBlock(tree, bx * kBlock, by * kBlock, bz * kBlock, m, x0, x1,
                                  values.data(), rowStride);
        },
        progress);
}

void Voxelization::copySolidMask(std::span<std::uint8_t> mask, const Progress& progress) const {
    copySolid(mask, voxels_, "copySolidMask", progress);
}

void Voxelization::copySolidIndicator(std::span<double> values, std::int64_t rowStride,
                                      const Progress& progress) const {
    copySolid(values, rowStride, "copySolidIndicator", progress);
}

void Voxelization::writeVdb(const std::filesystem::path& file) const {
    AtomicOutput out(file);
    out.write(vdbImage());
    out.commit();
}

std::string Voxelization::vdbImage(double lengthUnit) const {
    openvdb::initialize();
    openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setGridClass(openvdb::GRID_FOG_VOLUME);
    density->setTransform(grid_->grid->transform().copy());
    density->tree().topologyUnion(grid_->grid->tree());
    openvdb::tools::foreach (density->beginValueOn(),
                             [](const openvdb::FloatGrid::ValueOnIter& it) { it.setValue(1.0f); });
    // The shape as the packing file names it: the family where it is not the superball, then its
    // parameters (e.g. p) under their names.
    if (const std::optional<std::string_view> family = shape_.writtenFamily())
        density->insertMeta(kShapeFamilyKey, openvdb::StringMetadata(std::string(*family)));
    for (const auto& [name, value] : shape_.namedValues())
        density->insertMeta(std::string(name), openvdb::DoubleMetadata(value));
    density->insertMeta("phi_voxel", openvdb::DoubleMetadata(phiVoxel()));
    density->insertMeta("phi_exact", openvdb::DoubleMetadata(phiExact_));
    return sbpack::vdbImage(density, boxLength_, voxels_,
                            "fog volume density: 1 in voxels whose centre is inside a particle",
                            lengthUnit);
}

Voxelizer::Voxelizer(VoxelizationParameters parameters) : parameters_(parameters) {
    if (parameters.voxels < 1 || parameters.voxels > kMaxVoxels)
        throw VoxelResolutionError("voxel grid: M = " + std::to_string(parameters.voxels) +
                                   " is not in [1, " + std::to_string(kMaxVoxels) + "]");
    if (parameters_.slabEnd == -1) parameters_.slabEnd = parameters.voxels;
    if (parameters_.slabBegin < 0 || parameters_.slabBegin > parameters_.slabEnd ||
        parameters_.slabEnd > parameters.voxels)
        throw VoxelResolutionError("voxel grid: slab [" + std::to_string(parameters.slabBegin) +
                                   ", " + std::to_string(parameters_.slabEnd) +
                                   ") is not a part of [0, " + std::to_string(parameters.voxels) +
                                   ")");
}

double Voxelizer::reach(const ParticleShape& shape) {
    return shape.circumradius() * (1.0 + kSphereMargin);
}

namespace {

/// The narrowest width of the packing's particles: twice the smallest particle's inradius.
double narrowestWidth(const Packing& packing) {
    return 2.0 * ParticleShape(packing.shapeSpec, packing.smallestSemiAxis()).inradius();
}

} // namespace

int Voxelizer::minimumVoxels(const Packing& packing) {
    const double width = narrowestWidth(packing);
    // A box of 1e100 widths (sbgen --phi-init 1e-300 wrote one) once gave "use M >= -2147483648".
    return static_cast<int>(
        std::min(std::ceil(kMinVoxelsAcross * packing.boxLength / width), kMaxVoxels + 1.0));
}

void Voxelizer::checkResolution(const Packing& packing, int voxels) {
    const ParticleShape shape = packing.shape();
    if (2.0 * shape.circumradius() > packing.boxLength) {
        std::ostringstream message; // %g: lengths in metres are not 0.000000
        message << std::setprecision(6) << "voxel grid: the particles (circumdiameter "
                << 2.0 * shape.circumradius()
                << ") are larger than the box (L = " << packing.boxLength << ")";
        throw VoxelResolutionError(message.str());
    }
    const double across = voxels * narrowestWidth(packing) / packing.boxLength;
    if (across < kMinVoxelsAcross) {
        std::ostringstream message;
        message << std::setprecision(3) << "voxel grid: M = " << voxels << " puts " << across
                << " voxels across the narrowest width of a particle (2 r_in = "
                << narrowestWidth(packing) << " in L = " << packing.boxLength << "), fewer than "
                << kMinVoxelsAcross;
        if (minimumVoxels(packing) > kMaxVoxels)
            message << "; no grid can (M <= " << kMaxVoxels << "): the box is too large";
        else
            message << "; use M >= " << minimumVoxels(packing);
        throw VoxelResolutionError(message.str());
    }
}

double Voxelizer::memoryEstimateBytes(const Packing& packing, int voxels) {
    const double m = voxels;
    const double leaves = std::pow(std::ceil(m / kBlock), 3);
    // A leaf: 64-byte mask, origin, allocation and parent-table overhead (~100 bytes in all),
    // and one pointer, tile flag and count per block during the build.
    const double tree = leaves * (100.0 + 16.0);
    const double blocksAcross =
        2.0 * packing.shape().circumradius() / (packing.boxLength / m) / kBlock + 2.0;
    const double candidates = static_cast<double>(packing.size()) * 2.0 * // periodic images
                              std::pow(blocksAcross, 3) * sizeof(Candidate);
    return tree + candidates;
}

namespace {

/// The candidates of each block of kBlock^3 voxels: every periodic image of a particle whose
/// circumscribed sphere (radius rc) reaches the block; block b's are
/// candidates[start[b] .. start[b + 1]). Counting sort: O(N + blocks).
struct BlockCandidates {
    std::vector<std::int64_t> start;
    std::vector<Candidate> candidates;
};

BlockCandidates blockCandidates(const Packing& packing, const BlockGeometry& g) {
    const double rc = g.rc, a = g.a;
    const int m = g.m, blocks = g.blocks;
    const std::int64_t blockCount = g.blockCount();
    BlockCandidates out{std::vector<std::int64_t>(blockCount + 1, 0), {}};
    auto forEachImageBlock = [&](auto&& visit) {
        forEachPeriodicImage(packing, rc, [&](const Vector3d& c, int j) {
            const auto [x0, x1] = voxelRange(c.x(), rc, a, g.x0, g.x1 - 1);
            const auto [y0, y1] = voxelRange(c.y(), rc, a, 0, m - 1);
            const auto [z0, z1] = voxelRange(c.z(), rc, a, 0, m - 1);
            if (x0 > x1 || y0 > y1 || z0 > z1) return;
            for (int bx = x0 / kBlock; bx <= x1 / kBlock; ++bx)
                for (int by = y0 / kBlock; by <= y1 / kBlock; ++by)
                    for (int bz = z0 / kBlock; bz <= z1 / kBlock; ++bz)
                        visit((std::int64_t{bx - g.firstBlockX} * blocks + by) * blocks + bz,
                              Candidate{c, j});
        });
    };
    forEachImageBlock([&](std::int64_t block, const Candidate&) { ++out.start[block + 1]; });
    for (std::int64_t b = 0; b < blockCount; ++b)
        out.start[b + 1] += out.start[b];
    out.candidates.resize(static_cast<std::size_t>(out.start.back()));
    std::vector<std::int64_t> next(out.start.begin(), out.start.end() - 1);
    forEachImageBlock(
        [&](std::int64_t block, const Candidate& c) { out.candidates[next[block]++] = c; });
    return out;
}

/// Each block voxelised: a leaf (some solid), full (all solid) or nothing, and its solid count.
struct BlockMasks {
    explicit BlockMasks(std::int64_t blocks) : leaves(blocks), full(blocks, 0), solid(blocks, 0) {}
    std::vector<std::unique_ptr<MaskLeaf>> leaves;
    std::vector<std::uint8_t> full;
    std::vector<int> solid;

    /// Stores block b's 8 words (origin ox, oy, oz): full only when the block lies wholly in the
    /// slab and the grid.
    void store(std::int64_t b, const std::array<std::uint64_t, kBlock>& words,
               const BlockGeometry& g) {
        const auto [ox, oy, oz] = g.origin(b);
        int count = 0;
        bool whole = ox >= g.x0 && ox + kBlock <= g.x1 && oy + kBlock <= g.m && oz + kBlock <= g.m;
        for (std::uint64_t w : words) {
            count += std::popcount(w);
            whole = whole && w == ~std::uint64_t{0};
        }
        solid[b] = count;
        if (whole) {
            full[b] = 1;
        } else if (count > 0) {
            auto leaf = std::make_unique<MaskLeaf>(openvdb::Coord(ox, oy, oz), false);
            for (int x = 0; x < kBlock; ++x)
                leaf->getValueMask().getWord<std::uint64_t>(x) = words[x];
            leaves[b] = std::move(leaf);
        }
    }
};

BlockMasks voxelizeBlocks(const BlockCandidates& in, const std::vector<Eigen::Matrix3d>& toBody,
                          const ParticleShape::InsideTest& inside, const BlockGeometry& geometry,
                          const Progress& progress) {
    BlockMasks out(geometry.blockCount());
    parallelFor(
        0, geometry.blockCount(), kBlocksPerTask,
        [&](std::int64_t begin, std::int64_t end) {
            progress.checkInterrupt();
            for (std::int64_t b = begin; b < end; ++b) {
                const auto [ox, oy, oz] = geometry.origin(b);
                const std::span<const Candidate> mine(in.candidates.data() + in.start[b],
                                                      in.candidates.data() + in.start[b + 1]);
                out.store(b, voxelizeBlock(ox, oy, oz, mine, toBody, inside, geometry), geometry);
            }
        },
        progress);
    return out;
}

/// The whole grid's blocks from row bits (grid/voxel_rows.hpp: M x M rows of ceil(M / 32)
/// words, bit z & 31 of word z >> 5): a block's 8 z-bits never straddle a word (8 | 32).
BlockMasks blocksFromRowBits(std::span<const std::uint32_t> rows, const BlockGeometry& g) {
    const std::int64_t m = g.m, perRow = grid::wordsPerRow(g.m);
    BlockMasks out(g.blockCount());
    parallelFor(0, g.blockCount(), kBlocksPerTask, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t b = begin; b < end; ++b) {
            const auto [ox, oy, oz] = g.origin(b);
            std::array<std::uint64_t, kBlock> words{};
            for (int x = 0; x < kBlock && ox + x < m; ++x)
                for (int y = 0; y < kBlock && oy + y < m; ++y) {
                    const std::uint32_t word = rows[((ox + x) * m + oy + y) * perRow + oz / 32];
                    words[x] |= std::uint64_t{(word >> (oz % 32)) & 0xffu} << (y * kBlock);
                }
            out.store(b, words, g);
        }
    });
    return out;
}

/// The mask grid of the blocks (serial, O(blocks)): leaves, and leaf-sized tiles of the level-1
/// nodes for full blocks; `solid` counts the solid voxels.
openvdb::MaskGrid::Ptr assembleTree(BlockMasks& masks, const BlockGeometry& g,
                                    std::int64_t& solid) {
    openvdb::MaskGrid::Ptr grid = openvdb::MaskGrid::create(false);
    grid->setName("solid");
    openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(g.a);
    transform->postTranslate(openvdb::Vec3d(0.5 * g.a)); // index (i, j, k) -> centre (i + 1/2) a
    grid->setTransform(transform);
    MaskTree& tree = grid->tree();
    solid = 0;
    for (std::int64_t b = 0; b < g.blockCount(); ++b) {
        solid += masks.solid[b];
        if (masks.leaves[b]) {
            tree.addLeaf(masks.leaves[b].release());
        } else if (masks.full[b]) {
            const auto [ox, oy, oz] = g.origin(b);
            tree.addTile(1, openvdb::Coord(ox, oy, oz), true, true);
        }
    }
    return grid;
}

} // namespace

namespace {

/// The blocks of the grid (or slab) of `parameters` over `packing`.
BlockGeometry blockGeometry(const Packing& packing, const VoxelizationParameters& parameters) {
    const int m = parameters.voxels;
    const int blocks = (m + kBlock - 1) / kBlock;
    const int x0 = parameters.slabBegin, x1 = parameters.slabEnd;
    const int firstBlockX = x0 / kBlock;
    const ParticleShape shape = packing.shape();
    return BlockGeometry{m,
                         packing.boxLength / m,
                         Voxelizer::reach(shape),
                         shape.inradius() * (1.0 - kSphereMargin),
                         x0,
                         x1,
                         blocks,
                         firstBlockX,
                         x1 > x0 ? (x1 - 1) / kBlock - firstBlockX + 1 : 0,
                         packing.relativeSizes()};
}

/// Lab-to-body rotations: x_body = R^T (x - r); of a mixture, over the particle's size, x_body
/// = R^T (x - r) / s_j, the point in the largest particle's frame (the shape is homogeneous).
std::vector<Eigen::Matrix3d> bodyRotations(const Packing& packing) {
    std::vector<Eigen::Matrix3d> toBody(packing.size());
    for (std::size_t j = 0; j < packing.size(); ++j) {
        toBody[j] = packing.orientations[j].toRotationMatrix().transpose();
        if (packing.isMixture()) toBody[j] *= packing.semiAxis / packing.semiAxes[j];
    }
    return toBody;
}

} // namespace

Voxelization Voxelizer::compute(const Packing& packing, const Progress& progress) const {
    const Stopwatch clock;
    checkResolution(packing, parameters_.voxels);
    const BlockGeometry geometry = blockGeometry(packing, parameters_);
    BlockMasks masks = voxelizeBlocks(blockCandidates(packing, geometry), bodyRotations(packing),
                                      packing.shape().insideTest(), geometry, progress);
    auto grid = std::make_unique<Voxelization::Grid>();
    std::int64_t solid = 0;
    grid->grid = assembleTree(masks, geometry, solid);
    return Voxelization(std::move(grid), parameters_, packing.boxLength, packing.shapeSpec,
                        packing.packingFraction(), solid, clock.seconds());
}

std::vector<std::uint32_t> Voxelizer::particleLabels(const Packing& packing,
                                                     const Progress& progress) const {
    const std::int64_t m = parameters_.voxels;
    if (parameters_.slabBegin != 0 || parameters_.slabEnd != m)
        throw std::invalid_argument("particle labels: of the whole grid only, not of a slab");
    checkResolution(packing, parameters_.voxels);
    const BlockGeometry g = blockGeometry(packing, parameters_);
    const BlockCandidates in = blockCandidates(packing, g);
    const std::vector<Eigen::Matrix3d> toBody = bodyRotations(packing);
    const ParticleShape::InsideTest inside = packing.shape().insideTest();
    std::vector<std::uint32_t> labels(static_cast<std::size_t>(m * m * m), 0);
    parallelFor(
        0, g.blockCount(), kBlocksPerTask,
        [&](std::int64_t begin, std::int64_t end) {
            progress.checkInterrupt();
            for (std::int64_t b = begin; b < end; ++b) {
                const std::array<int, 3> origin = g.origin(b); // captured: no structured binding
                const int ox = origin[0], oy = origin[1], oz = origin[2];
                const std::span<const Candidate> mine(in.candidates.data() + in.start[b],
                                                      in.candidates.data() + in.start[b + 1]);
                // A block's voxels are its own: no two tasks write one label.
                forEachCandidateRow(
                    ox, oy, oz, mine, toBody, inside, g, [&](int particle, int x, std::uint64_t w) {
                        for (; w != 0; w &= w - 1) {
                            const int bit = std::countr_zero(w);
                            const std::int64_t y = oy + bit / kBlock, z = oz + bit % kBlock;
                            labels[((ox + x) * m + y) * m + z] =
                                static_cast<std::uint32_t>(particle) + 1;
                        }
                    });
            }
        },
        progress);
    return labels;
}

Voxelization Voxelizer::fromRowBits(std::span<const std::uint32_t> rows, const Packing& packing,
                                    int voxels, double runtimeSeconds) {
    const std::int64_t m = voxels;
    if (voxels < 1 || voxels > kMaxVoxels ||
        rows.size() != static_cast<std::size_t>(m * m * grid::wordsPerRow(voxels)))
        throw std::invalid_argument("voxel grid from row bits: " + std::to_string(rows.size()) +
                                    " words are not the rows of a " + std::to_string(voxels) +
                                    "^3 grid");
    const int blocks = (voxels + kBlock - 1) / kBlock;
    const BlockGeometry geometry{
        voxels, packing.boxLength / voxels, 0.0, 0.0, 0, voxels, blocks, 0, blocks, {}};
    BlockMasks masks = blocksFromRowBits(rows, geometry);
    auto grid = std::make_unique<Voxelization::Grid>();
    std::int64_t solid = 0;
    grid->grid = assembleTree(masks, geometry, solid);
    return Voxelization(std::move(grid), VoxelizationParameters{voxels, 0, voxels},
                        packing.boxLength, packing.shapeSpec, packing.packingFraction(), solid,
                        runtimeSeconds);
}

} // namespace sbpack

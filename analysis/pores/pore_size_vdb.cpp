// The one translation unit of pores/ that includes OpenVDB: export of the pore-size map.
#include "pores/distance_transform.hpp"

#include "io/atomic_file.hpp"
#include "parallel/parallel.hpp"
#include "voxels/vdb_image.hpp"

#include <openvdb/openvdb.h>

#include <cmath>
#include <string>

namespace sbpack {

void PoreSizeMap::writeVdb(const std::filesystem::path& file) const {
    AtomicOutput output(file);
    output.write(vdbImage());
    output.commit();
}

std::string PoreSizeMap::vdbImage(double lengthUnit) const {
    openvdb::initialize();
    const int m = voxels_;
    const std::int64_t plane = static_cast<std::int64_t>(m) * m;
    const std::uint32_t* squared = squaredDistances_.get();
    const auto a = static_cast<float>(voxelSize_);
    using Leaf = openvdb::FloatTree::LeafNodeType;
    constexpr int edge = static_cast<int>(Leaf::DIM);
    // One tree per slab of leaf-node thickness in x, built in parallel, then merged in order.
    const int slabs = (m + edge - 1) / edge;
    std::vector<openvdb::FloatTree::Ptr> slabTrees(slabs);
    parallelFor(0, slabs, 1, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t slab = begin; slab < end; ++slab) {
            auto tree = std::make_shared<openvdb::FloatTree>(0.0f);
            const int i0 = static_cast<int>(slab) * edge;
            for (int j0 = 0; j0 < m; j0 += edge)
                for (int k0 = 0; k0 < m; k0 += edge) {
                    auto leaf = std::make_unique<Leaf>(openvdb::Coord(i0, j0, k0), 0.0f);
                    bool anyVoid = false;
                    for (int i = i0; i < std::min(m, i0 + edge); ++i)
                        for (int j = j0; j < std::min(m, j0 + edge); ++j)
                            for (int k = k0; k < std::min(m, k0 + edge); ++k) {
                                const std::uint32_t d2 = squared[i * plane + j * m + k];
                                if (d2 == 0) continue; // solid
                                leaf->setValueOn(openvdb::Coord(i, j, k),
                                                 a * std::sqrt(static_cast<float>(d2)));
                                anyVoid = true;
                            }
                    if (anyVoid) tree->addLeaf(leaf.release());
                }
            slabTrees[slab] = tree;
        }
    });
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    for (const auto& tree : slabTrees)
        grid->tree().merge(*tree, openvdb::MERGE_ACTIVE_STATES);
    grid->setName("pore_size");
    openvdb::math::Transform::Ptr transform =
        openvdb::math::Transform::createLinearTransform(voxelSize_);
    transform->postTranslate(openvdb::Vec3d(0.5 * voxelSize_)); // index (i, j, k): voxel centre
    grid->setTransform(transform);
    return sbpack::vdbImage(grid, boxLength(), m,
                            "length_unit; value = distance from the void voxel centre to the "
                            "nearest solid voxel centre (periodic)",
                            lengthUnit);
}

} // namespace sbpack

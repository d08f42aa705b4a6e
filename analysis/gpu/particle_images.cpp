#include "gpu/particle_images.hpp"

#include "voxels/voxelization.hpp"

#include <Eigen/Geometry>

namespace sbpack::gpu {

std::vector<grid::ParticleImage> particleImages(const Packing& packing) {
    std::vector<grid::ParticleImage> images;
    grid::ParticleImage image{};
    int rotated = -1; // the particle whose rotation `image` holds
    forEachPeriodicImage(packing, Voxelizer::reach(packing.shape()), [&](const Vector3d& c, int j) {
        if (j != rotated) {
            const Eigen::Matrix3d toBody = packing.orientations[j].toRotationMatrix().transpose();
            for (int row = 0; row < 3; ++row)
                for (int col = 0; col < 3; ++col)
                    image.toBody[3 * row + col] = toBody(row, col);
            rotated = j;
        }
        image.centre[0] = c.x(), image.centre[1] = c.y(), image.centre[2] = c.z();
        images.push_back(image);
    });
    return images;
}

grid::VoxelGeometry voxelGeometry(const Packing& packing, int voxels) {
    const Superball shape = packing.superball();
    return {voxels, packing.boxLength / voxels, Voxelizer::reach(packing.shape()), shape.semiAxis(),
            shape.p()};
}

} // namespace sbpack::gpu

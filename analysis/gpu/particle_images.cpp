#include "gpu/particle_images.hpp"

#include "voxels/voxelization.hpp"

#include <Eigen/Geometry>

namespace sbpack::gpu {

std::vector<ParticleImage> particleImages(const Packing& packing) {
    const double rc = Voxelizer::reach(packing.shape()), boxLength = packing.boxLength;
    std::vector<ParticleImage> images;
    for (std::size_t j = 0; j < packing.size(); ++j) {
        const Vector3d& r = packing.positions[j];
        const Eigen::Matrix3d toBody = packing.orientations[j].toRotationMatrix().transpose();
        ParticleImage image{};
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col)
                image.toBody[3 * row + col] = toBody(row, col);
        for (double sx : periodicImageShifts(r.x(), rc, boxLength))
            for (double sy : periodicImageShifts(r.y(), rc, boxLength))
                for (double sz : periodicImageShifts(r.z(), rc, boxLength)) {
                    const Vector3d c = r + Vector3d(sx, sy, sz);
                    image.centre[0] = c.x(), image.centre[1] = c.y(), image.centre[2] = c.z();
                    images.push_back(image);
                }
    }
    return images;
}

VoxelGeometry voxelGeometry(const Packing& packing, int voxels) {
    const Superball shape = packing.shape();
    return {voxels, packing.boxLength / voxels, Voxelizer::reach(shape), shape.semiAxis(),
            shape.p()};
}

} // namespace sbpack::gpu

#include "jamming/rigidity_network.hpp"

#include "jamming/gap_hessian.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

void checkSizes(const Packing& packing, const ContactResult& network) {
    const std::size_t contacts = network.contacts.size();
    if (network.rattler.size() != packing.size() || network.gaps.size() != contacts ||
        network.normals.size() != contacts || network.points.size() != contacts)
        throw std::invalid_argument(
            "rigidity network: the contact network (" + std::to_string(network.rattler.size()) +
            " particles, " + std::to_string(contacts) + " contacts) is not one of this packing (" +
            std::to_string(packing.size()) + " particles)");
}

} // namespace

RigidityNetwork backboneNetwork(const Packing& packing, const ContactResult& network,
                                const Matrix3d& cell) {
    checkSizes(packing, network);
    const double diameter = packing.shape().diameter();
    const ParticleShape shape(packing.shapeSpec, 0.5); // units of D
    RigidityNetwork result;
    result.packingSize = static_cast<int>(packing.size());
    result.rotations = !packing.shape().isSphere();
    result.boxLength = packing.boxLength / diameter;
    const Matrix3d cellInverse = cell.inverse();
    std::vector<int> backboneIndex(packing.size(), -1);
    for (int k = 0; k < result.packingSize; ++k)
        if (!network.rattler[k]) {
            backboneIndex[k] = static_cast<int>(result.backbone.size());
            result.backbone.push_back(k);
        }
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        const auto [i, j] = network.contacts[c];
        if (network.rattler[i] || network.rattler[j]) continue;
        const Vector3d inBox = (packing.positions[j] - packing.positions[i]) / diameter;
        const Vector3d separation =
            inBox + cellImageShift(inBox, cell, cellInverse, result.boxLength);
        const double gap = network.gaps[c] * packing.pairSize(i, j); // a mixture's: over R_i + R_j
        const double sizeA = packing.relativeSize(i);
        const ContactCurvature curvature = contactCurvature(
            sizeA == 1.0 ? shape : shape.scaled(sizeA), packing.orientations[i].toRotationMatrix(),
            packing.orientations[j].toRotationMatrix(), separation, network.normals[c], gap,
            packing.semiAxisOf(j) / packing.semiAxisOf(i));
        const Vector3d point = midpointLever(curvature);
        result.contacts.push_back({backboneIndex[i], backboneIndex[j], network.normals[c], point,
                                   point - separation, separation - inBox, std::max(gap, 0.0),
                                   curvature.curvatureA, curvature.curvatureB});
    }
    return result;
}

} // namespace sbpack

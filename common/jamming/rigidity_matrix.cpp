#include "jamming/rigidity_matrix.hpp"

#include <vector>

namespace sbpack {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// The entries of one body's part of ds_c in column `column`: sign n . (dr + dtheta x rho), i.e.
/// sign n on dr and sign rho x n on dtheta (n . (dtheta x rho) = dtheta . (rho x n)).
void addBody(Triplets& entries, const DegreesOfFreedom& dof, int particle, double sign,
             const Vector3d& normal, const Vector3d& lever, int column) {
    const Vector3d torqueArm = lever.cross(normal);
    for (int a = 0; a < 3; ++a) {
        entries.emplace_back(dof.translation(particle) + a, column, sign * normal[a]);
        if (dof.rotations)
            entries.emplace_back(dof.rotation(particle) + a, column, sign * torqueArm[a]);
    }
}

/// The strain's part n . (eps w) of ds_c, w the box shift (none inside the box): n_k w_k on
/// eps_kk, n_a w_b + n_b w_a on eps_ab.
void addStrain(Triplets& entries, const DegreesOfFreedom& dof, const RigidContact& contact,
               int column) {
    const Vector3d& n = contact.normal;
    const Vector3d& w = contact.boxShift;
    if (w.isZero()) return;
    const int offDiagonal[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    for (int k = 0; k < 3; ++k) {
        entries.emplace_back(dof.strainComponent(k), column, n[k] * w[k]);
        const int a = offDiagonal[k][0], b = offDiagonal[k][1];
        entries.emplace_back(dof.strainComponent(3 + k), column, n[a] * w[b] + n[b] * w[a]);
    }
}

} // namespace

DegreesOfFreedom degreesOfFreedom(const RigidityNetwork& network, JammingCategory category) {
    return {static_cast<int>(network.backbone.size()), network.rotations,
            category == JammingCategory::Strict};
}

Eigen::SparseMatrix<double> rigidityMatrix(const RigidityNetwork& network,
                                           JammingCategory category) {
    const DegreesOfFreedom dof = degreesOfFreedom(network, category);
    const bool local = category == JammingCategory::Local;
    const int contacts = static_cast<int>(network.contacts.size());
    Triplets entries;
    entries.reserve(static_cast<std::size_t>(contacts) * (dof.rotations ? 12 : 6) +
                    (dof.strain ? 6 * contacts : 0));
    for (int c = 0; c < contacts; ++c) {
        const RigidContact& contact = network.contacts[c];
        const int columnI = local ? 2 * c : c, columnJ = local ? 2 * c + 1 : c;
        addBody(entries, dof, contact.i, -1.0, contact.normal, contact.leverI, columnI);
        addBody(entries, dof, contact.j, 1.0, contact.normal, contact.leverJ, columnJ);
        if (dof.strain) addStrain(entries, dof, contact, c);
    }
    Eigen::SparseMatrix<double> a(dof.count(), local ? 2 * contacts : contacts);
    a.setFromTriplets(entries.begin(), entries.end());
    return a;
}

} // namespace sbpack

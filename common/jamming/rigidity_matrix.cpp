#include "jamming/rigidity_matrix.hpp"

#include <vector>

namespace sbpack {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// The entries of one body's part of ds_c in column `column`: `part`, the body's six entries of
/// gapGradient (translation, then rotation where the rotations are unknowns).
void addBody(Triplets& entries, const DegreesOfFreedom& dof, int particle,
             const Eigen::Matrix<double, 6, 1>& part, int column) {
    for (int a = 0; a < 3; ++a) {
        entries.emplace_back(dof.translation(particle) + a, column, part[a]);
        if (dof.rotations) entries.emplace_back(dof.rotation(particle) + a, column, part[3 + a]);
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

Eigen::Matrix<double, 12, 1> gapGradient(const Vector3d& normal, const Vector3d& leverI,
                                         const Vector3d& leverJ) {
    Eigen::Matrix<double, 12, 1> g;
    g << -normal, -leverI.cross(normal), normal, leverJ.cross(normal);
    return g;
}

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
        const Eigen::Matrix<double, 12, 1> g =
            gapGradient(contact.normal, contact.leverI, contact.leverJ);
        addBody(entries, dof, contact.i, g.head<6>(), columnI);
        addBody(entries, dof, contact.j, g.tail<6>(), columnJ);
        if (dof.strain) addStrain(entries, dof, contact, c);
    }
    Eigen::SparseMatrix<double> a(dof.count(), local ? 2 * contacts : contacts);
    a.setFromTriplets(entries.begin(), entries.end());
    return a;
}

} // namespace sbpack

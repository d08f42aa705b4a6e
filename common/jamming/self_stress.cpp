#include "jamming/self_stress.hpp"

#include "jamming/rigidity_matrix.hpp"

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

namespace {

/// f scaled to mean 1, its residual |A f|_inf and the loaded count.
SelfStress normalised(const Eigen::SparseMatrix<double>& a, Eigen::VectorXd forces,
                      double loadTolerance) {
    SelfStress stress;
    const double mean = forces.size() > 0 ? forces.mean() : 0.0;
    if (!(mean > 0.0)) return stress;
    stress.forces = forces / mean;
    stress.balanceResidual = (a * stress.forces).lpNorm<Eigen::Infinity>();
    stress.loadedContacts = static_cast<int>((stress.forces.array() > loadTolerance).count());
    return stress;
}

} // namespace

SelfStress findSelfStress(const RigidityNetwork& network, double loadTolerance,
                          const LinearProgramTolerances& tolerances) {
    const Eigen::SparseMatrix<double> a = rigidityMatrix(network, JammingCategory::Collective);
    const Eigen::Index dof = a.rows(), contacts = a.cols();
    // Columns f (contacts), then y; rows A f = 0, then y - f <= 0.
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(a.nonZeros() + 2 * contacts);
    for (Eigen::Index c = 0; c < contacts; ++c) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it)
            entries.emplace_back(it.row(), c, it.value());
        entries.emplace_back(dof + c, c, -1.0);
        entries.emplace_back(dof + c, contacts + c, 1.0);
    }
    LinearProgram program;
    program.constraints.resize(dof + contacts, 2 * contacts);
    program.constraints.setFromTriplets(entries.begin(), entries.end());
    program.objective = Eigen::VectorXd::Zero(2 * contacts);
    program.objective.tail(contacts).setOnes();
    program.columnLower = Eigen::VectorXd::Zero(2 * contacts);
    program.columnUpper =
        Eigen::VectorXd::Constant(2 * contacts, std::numeric_limits<double>::infinity());
    program.columnUpper.tail(contacts).setOnes();
    program.rowLower = Eigen::VectorXd::Zero(dof + contacts);
    program.rowLower.tail(contacts).setConstant(-std::numeric_limits<double>::infinity());
    program.rowUpper = Eigen::VectorXd::Zero(dof + contacts);
    const Eigen::VectorXd solution = maximise(program, LinearProgramMethod::Barrier, tolerances);
    return normalised(a, solution.head(contacts).cwiseMax(0.0), loadTolerance);
}

SelfStress givenSelfStress(const RigidityNetwork& network, const Eigen::VectorXd& forces,
                           double loadTolerance) {
    if (forces.size() != static_cast<Eigen::Index>(network.contacts.size()))
        throw std::invalid_argument("self-stress: " + std::to_string(forces.size()) +
                                    " forces given for " + std::to_string(network.contacts.size()) +
                                    " contacts");
    if (forces.size() == 0 || !forces.allFinite() || forces.minCoeff() < 0.0 ||
        forces.maxCoeff() <= 0.0)
        throw std::invalid_argument("self-stress: the given forces must be finite, >= 0 and not "
                                    "all 0");
    return normalised(rigidityMatrix(network, JammingCategory::Collective), forces, loadTolerance);
}

} // namespace sbpack

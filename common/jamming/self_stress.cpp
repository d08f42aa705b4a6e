#include "jamming/self_stress.hpp"

#include "jamming/rigidity_matrix.hpp"

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// f scaled to mean 1, its residual |A f| (inf and 2 norms) and the loaded count.
SelfStress normalised(const Eigen::SparseMatrix<double>& a, Eigen::VectorXd forces,
                      double loadTolerance) {
    SelfStress stress;
    const double mean = forces.size() > 0 ? forces.mean() : 0.0;
    if (!(mean > 0.0)) return stress;
    stress.forces = forces / mean;
    const Eigen::VectorXd residual = a * stress.forces;
    stress.balanceResidual = residual.lpNorm<Eigen::Infinity>();
    stress.residualNorm = residual.norm();
    stress.loadedContacts = static_cast<int>((stress.forces.array() > loadTolerance).count());
    return stress;
}

/// The exact program (docs/jamming.md §6.2): columns f (contacts), then y; rows A f = 0, then
/// y - f <= 0; maximise sum y with 0 <= y <= 1.
LinearProgram mostLoadedProgram(const Eigen::SparseMatrix<double>& a) {
    const Eigen::Index dof = a.rows(), contacts = a.cols();
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
    program.columnUpper = Eigen::VectorXd::Constant(2 * contacts, kInfinity);
    program.columnUpper.tail(contacts).setOnes();
    program.rowLower = Eigen::VectorXd::Zero(dof + contacts);
    program.rowLower.tail(contacts).setConstant(-kInfinity);
    program.rowUpper = Eigen::VectorXd::Zero(dof + contacts);
    return program;
}

/// The least-residual program (docs/jamming.md §6.6, Eq. (L)): columns f (contacts), then the
/// residual's positive and negative parts r+, r- (dof each); rows A f - r+ + r- = 0, then
/// sum f = contacts (mean 1); maximise -sum (r+ + r-), all columns >= 0.
LinearProgram leastResidualProgram(const Eigen::SparseMatrix<double>& a) {
    const Eigen::Index dof = a.rows(), contacts = a.cols(), columns = contacts + 2 * dof;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(a.nonZeros() + contacts + 2 * dof);
    for (Eigen::Index c = 0; c < contacts; ++c) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it)
            entries.emplace_back(it.row(), c, it.value());
        entries.emplace_back(dof, c, 1.0);
    }
    for (Eigen::Index k = 0; k < dof; ++k) {
        entries.emplace_back(k, contacts + k, -1.0);
        entries.emplace_back(k, contacts + dof + k, 1.0);
    }
    LinearProgram program;
    program.constraints.resize(dof + 1, columns);
    program.constraints.setFromTriplets(entries.begin(), entries.end());
    program.objective = Eigen::VectorXd::Zero(columns);
    program.objective.tail(2 * dof).setConstant(-1.0);
    program.columnLower = Eigen::VectorXd::Zero(columns);
    program.columnUpper = Eigen::VectorXd::Constant(columns, kInfinity);
    program.rowLower = Eigen::VectorXd::Zero(dof + 1);
    program.rowLower[dof] = static_cast<double>(contacts);
    program.rowUpper = program.rowLower;
    return program;
}

/// Eq. (L) (docs/jamming.md §6.6). Where its residual is at the solver's feasibility an exact
/// self-stress exists, and the least-residual vertex loads few contacts (perturbed fcc: 6 to 302
/// of 648): then §6.2's program, which loads the most.
Eigen::VectorXd leastResidualForces(const Eigen::SparseMatrix<double>& a,
                                    const LinearProgramTolerances& tolerances) {
    const Eigen::VectorXd least =
        maximise(leastResidualProgram(a), LinearProgramMethod::Barrier, tolerances)
            .head(a.cols())
            .cwiseMax(0.0);
    if ((a * least).lpNorm<Eigen::Infinity>() > tolerances.feasibility) return least;
    const Eigen::VectorXd exact =
        maximise(mostLoadedProgram(a), LinearProgramMethod::Barrier, tolerances).head(a.cols());
    return exact.maxCoeff() > 0.0 ? exact : least;
}

} // namespace

SelfStress findSelfStress(const RigidityNetwork& network, double loadTolerance,
                          const LinearProgramTolerances& tolerances, SelfStressProgram program) {
    const Eigen::SparseMatrix<double> a = rigidityMatrix(network, JammingCategory::Collective);
    const Eigen::Index contacts = a.cols();
    const bool exact = program == SelfStressProgram::Exact;
    const Eigen::VectorXd forces =
        exact ? maximise(mostLoadedProgram(a), LinearProgramMethod::Barrier, tolerances)
                    .head(contacts)
              : leastResidualForces(a, tolerances);
    return normalised(a, forces.cwiseMax(0.0), loadTolerance);
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

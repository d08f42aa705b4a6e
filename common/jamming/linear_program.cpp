#include "jamming/linear_program.hpp"

#include <ClpSimplex.hpp>
#include <ClpSolve.hpp>
#include <CoinFinite.hpp>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace sbpack {

namespace {

static_assert(std::is_same_v<CoinBigIndex, Eigen::SparseMatrix<double>::StorageIndex>,
              "CLP's column starts must be Eigen's outer indices");

/// CLP's infinity for the infinite bounds.
Eigen::VectorXd finite(const Eigen::VectorXd& bounds) {
    return bounds.cwiseMax(-COIN_DBL_MAX).cwiseMin(COIN_DBL_MAX);
}

void checkSizes(const LinearProgram& program) {
    const Eigen::Index rows = program.constraints.rows(), columns = program.constraints.cols();
    if (program.objective.size() != columns || program.columnLower.size() != columns ||
        program.columnUpper.size() != columns || program.rowLower.size() != rows ||
        program.rowUpper.size() != rows)
        throw std::invalid_argument("linear program: the objective and bounds do not match the " +
                                    std::to_string(rows) + " x " + std::to_string(columns) +
                                    " constraint matrix");
}

} // namespace

Eigen::VectorXd maximise(const LinearProgram& program, LinearProgramMethod method,
                         const LinearProgramTolerances& tolerances) {
    checkSizes(program);
    Eigen::SparseMatrix<double> matrix = program.constraints;
    matrix.makeCompressed();
    const Eigen::VectorXd columnLower = finite(program.columnLower),
                          columnUpper = finite(program.columnUpper),
                          rowLower = finite(program.rowLower), rowUpper = finite(program.rowUpper);
    ClpSimplex model;
    model.setLogLevel(0);
    model.loadProblem(static_cast<int>(matrix.cols()), static_cast<int>(matrix.rows()),
                      matrix.outerIndexPtr(), matrix.innerIndexPtr(), matrix.valuePtr(),
                      columnLower.data(), columnUpper.data(), program.objective.data(),
                      rowLower.data(), rowUpper.data());
    model.setOptimizationDirection(-1.0); // maximise
    model.setPrimalTolerance(tolerances.feasibility);
    model.setDualTolerance(tolerances.optimality);
    ClpSolve options;
    options.setPresolveType(ClpSolve::presolveOn);
    options.setSolveType(method == LinearProgramMethod::Barrier ? ClpSolve::useBarrier
                                                                : ClpSolve::useDual);
    model.initialSolve(options);
    if (!model.isProvenOptimal())
        throw std::runtime_error("linear program: CLP ended with status " +
                                 std::to_string(model.status()) +
                                 " (1 infeasible, 2 unbounded, 3 stopped, 4 numerical trouble) "
                                 "on " +
                                 std::to_string(matrix.rows()) + " rows and " +
                                 std::to_string(matrix.cols()) + " columns");
    return Eigen::Map<const Eigen::VectorXd>(model.primalColumnSolution(), matrix.cols());
}

} // namespace sbpack

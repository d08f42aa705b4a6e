#pragma once
// A linear program in bounded form and its solution by COIN-OR CLP (docs/jamming.md §3): the one
// place that knows the LP library. Why CLP: its licence (EPL-2.0, permissive enough for sbpack's
// MIT, where GLPK's GPL-3 would bind every binary that links it), its speed (its dual simplex and
// its barrier beat GLPK's by 3-6x on the jamming programs: docs/jamming.md §3) and its API (it
// takes the column-major matrix as Eigen stores it).

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace sbpack {

/// maximise objective . x  subject to  rowLower <= constraints x <= rowUpper,
///                                     columnLower <= x <= columnUpper
/// (infinite bounds allowed).
struct LinearProgram {
    Eigen::SparseMatrix<double> constraints; ///< rows x columns
    Eigen::VectorXd objective;
    Eigen::VectorXd columnLower, columnUpper;
    Eigen::VectorXd rowLower, rowUpper;
};

struct LinearProgramTolerances {
    /// How far CLP's solution may violate a bound or a row (its primal tolerance; default 1e-7).
    double feasibility = 1e-9;
    /// How far its reduced costs may have the wrong sign at the optimum (dual tolerance).
    double optimality = 1e-9;
};

/// How CLP solves a program, after its presolve.
enum class LinearProgramMethod {
    DualSimplex, ///< for block-diagonal programs, which the presolve splits (Local)
    Barrier,     ///< interior point, then crossover to a vertex: for programs coupled across
                 ///< the packing, where the simplex needs ~2 pivots per row (docs/jamming.md §3)
};

/// The maximiser x, by `method`. Throws std::invalid_argument for mismatched sizes and
/// std::runtime_error unless CLP proves its solution optimal (infeasible or unbounded programs,
/// numerical trouble).
Eigen::VectorXd maximise(const LinearProgram& program, LinearProgramMethod method,
                         const LinearProgramTolerances& tolerances);

} // namespace sbpack

#include "jamming/gordan_motion.hpp"

#include "random/random.hpp"

#include <Eigen/SparseCholesky>

#include <cmath>
#include <vector>

namespace sbpack {

namespace {

/// A's first `rows` rows: the translations and rotations.
Eigen::SparseMatrix<double> motionRowsOf(const Eigen::SparseMatrix<double>& a, int rows) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(a.nonZeros());
    for (int gap = 0; gap < a.outerSize(); ++gap)
        for (Eigen::SparseMatrix<double>::InnerIterator it(a, gap); it; ++it)
            if (it.row() < rows) entries.emplace_back(static_cast<int>(it.row()), gap, it.value());
    Eigen::SparseMatrix<double> top(rows, a.cols());
    top.setFromTriplets(entries.begin(), entries.end());
    return top;
}

/// dq with `fixed`'s translation subtracted from every particle's, scaled to |x|_inf = 1 and
/// padded with the strain's zeros to A's rows; empty where it is not finite or 0.
Eigen::VectorXd normalised(Eigen::VectorXd dq, const DegreesOfFreedom& dof, int fixed) {
    const Eigen::Vector3d shift = dq.segment<3>(dof.translation(fixed));
    for (int b = 0; b < dof.particles; ++b)
        dq.segment<3>(dof.translation(b)) -= shift;
    const double largest = dq.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(largest) || largest == 0.0) return {};
    Eigen::VectorXd x = Eigen::VectorXd::Zero(dof.count());
    x.head(dq.size()) = dq / largest;
    return x;
}

} // namespace

std::optional<GordanMotions> gordanMotions(const Eigen::SparseMatrix<double>& a,
                                           const DegreesOfFreedom& dof, int fixed,
                                           std::uint64_t seed) {
    const Eigen::SparseMatrix<double> top = motionRowsOf(a, dof.strainComponent(0));
    if (top.cols() == 0 || top.cols() > top.rows()) return std::nullopt;
    const Eigen::SparseMatrix<double> normal = top.transpose() * top; // A^T A, contacts^2
    const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor(normal);
    if (factor.info() != Eigen::Success) return std::nullopt;
    // The least-norm motion with A^T dq = 1 (every contact opens at the same rate).
    const Eigen::VectorXd opening = top * factor.solve(Eigen::VectorXd::Ones(top.cols()));
    // A random motion less its part in the range of A: its projection onto ker A^T.
    Random random(seed);
    Eigen::VectorXd c(top.rows());
    for (Eigen::Index k = 0; k < c.size(); ++k)
        c[k] = 2.0 * random.uniform() - 1.0;
    const Eigen::VectorXd flex = c - top * factor.solve(top.transpose() * c);
    return GordanMotions{normalised(opening, dof, fixed), normalised(flex, dof, fixed)};
}

} // namespace sbpack

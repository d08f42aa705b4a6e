#include "jamming/second_order.hpp"

#include "jamming/gap_hessian.hpp"
#include "jamming/rigidity_matrix.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseQR>
#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

/// Dof k with the fixed particle's (backbone 0's) translation removed, or -1 for those three.
int reduced(int k) {
    return k < 3 ? -1 : k - 3;
}

/// The reduced dof of a contact's 12 coordinates (dr_i, dtheta_i, dr_j, dtheta_j), -1 where
/// absent (the fixed translation; rotations of spheres).
std::array<int, 12> coordinatesOf(const RigidContact& c, const DegreesOfFreedom& dof) {
    std::array<int, 12> index{};
    for (int a = 0; a < 3; ++a) {
        index[a] = reduced(dof.translation(c.i) + a);
        index[6 + a] = reduced(dof.translation(c.j) + a);
        index[3 + a] = dof.rotations ? reduced(dof.rotation(c.i) + a) : -1;
        index[9 + a] = dof.rotations ? reduced(dof.rotation(c.j) + a) : -1;
    }
    return index;
}

/// S_f = -sum_c f_c Hess(s_c) on the reduced dof, at the ideal contacts (s = 0; docs/jamming.md
/// §6.3). `singular`: a loaded contact's Hessian is not finite.
Sparse stiffnessMatrix(const RigidityNetwork& network, const Eigen::VectorXd& forces,
                       const DegreesOfFreedom& dof, bool& singular) {
    std::vector<Eigen::Triplet<double>> entries;
    singular = false;
    for (std::size_t k = 0; k < network.contacts.size(); ++k) {
        const RigidContact& c = network.contacts[k];
        if (forces[k] == 0.0) continue;
        const Matrix12d hessian =
            gapHessian({c.normal, c.leverI, c.leverJ, c.curvatureI, c.curvatureJ, 0.0});
        if (!hessian.allFinite()) {
            singular = true;
            continue;
        }
        const std::array<int, 12> index = coordinatesOf(c, dof);
        for (int a = 0; a < 12; ++a)
            for (int b = 0; b < 12; ++b)
                if (index[a] >= 0 && index[b] >= 0)
                    entries.emplace_back(index[a], index[b], -forces[k] * hessian(a, b));
    }
    Sparse s(dof.count() - 3, dof.count() - 3);
    s.setFromTriplets(entries.begin(), entries.end());
    return s;
}

/// The rows of A on the reduced dof, the columns of the contacts `keep` selects.
Sparse reducedRigidity(const Sparse& a, const std::vector<char>& keep) {
    std::vector<Eigen::Triplet<double>> entries;
    int column = 0;
    for (int c = 0; c < a.cols(); ++c) {
        if (!keep[c]) continue;
        for (Sparse::InnerIterator it(a, c); it; ++it)
            if (reduced(static_cast<int>(it.row())) >= 0)
                entries.emplace_back(reduced(static_cast<int>(it.row())), column, it.value());
        ++column;
    }
    Sparse m(a.rows() - 3, column);
    m.setFromTriplets(entries.begin(), entries.end());
    return m;
}

/// rank of m by a sparse QR with COLAMD ordering, columns below `tolerance` times the largest
/// column norm treated as dependent (taller than wide: m or its transpose).
int rankOf(const Sparse& m, double tolerance) {
    if (m.cols() == 0 || m.rows() == 0) return 0;
    Sparse tall = m.rows() >= m.cols() ? m : Sparse(m.transpose());
    tall.makeCompressed();
    double largest = 0.0;
    for (int c = 0; c < tall.cols(); ++c)
        largest = std::max(largest, tall.col(c).norm());
    Eigen::SparseQR<Sparse, Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(tolerance * largest);
    qr.compute(tall);
    if (qr.info() != Eigen::Success)
        throw std::runtime_error("second-order test: the QR factorisation of A failed");
    return static_cast<int>(qr.rank());
}

/// y = (K - sigma I)^{-1} x for Spectra's shift-invert mode, by a sparse Cholesky (K - sigma I
/// positive definite: sigma below K's spectrum).
class ShiftInvert {
  public:
    using Scalar = double;
    explicit ShiftInvert(const Sparse& k) : k_(k) {}
    Eigen::Index rows() const { return k_.rows(); }
    Eigen::Index cols() const { return k_.cols(); }
    void set_shift(double sigma) {
        Sparse identity(k_.rows(), k_.cols());
        identity.setIdentity();
        cholesky_.compute(k_ - sigma * identity);
        if (cholesky_.info() != Eigen::Success)
            throw std::runtime_error("second-order test: K - sigma I is not positive definite");
    }
    void perform_op(const double* in, double* out) const {
        Eigen::Map<Eigen::VectorXd>(out, k_.rows()) =
            cholesky_.solve(Eigen::Map<const Eigen::VectorXd>(in, k_.rows()));
    }

  private:
    const Sparse& k_;
    Eigen::SimplicialLLT<Sparse> cholesky_;
};

struct Eigenpair {
    double value = 0.0;
    Eigen::VectorXd vector;
};

/// The smallest eigenpair of the symmetric k, all of whose eigenvalues exceed `below`: dense for
/// small k, else shift-invert Lanczos at `below`.
Eigenpair smallestEigenpair(const Sparse& k, double below) {
    if (k.rows() <= 100) {
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(k)};
        return {dense.eigenvalues()[0], dense.eigenvectors().col(0)};
    }
    ShiftInvert op(k);
    Spectra::SymEigsShiftSolver<ShiftInvert> lanczos(op, 1, std::min<Eigen::Index>(40, k.rows()),
                                                     below);
    lanczos.init();
    lanczos.compute(Spectra::SortRule::LargestMagn, 5000, 1e-10);
    if (lanczos.info() != Spectra::CompInfo::Successful)
        throw std::runtime_error("second-order test: Lanczos did not converge");
    return {lanczos.eigenvalues()[0], lanczos.eigenvectors().col(0)};
}

} // namespace

namespace {

/// Finsler's lemma (docs/jamming.md §6.3): the smallest eigenpair of S + mu A A^T for mu = 1e2,
/// 1e4, ... 1e8 times |S| / |A A^T|, until it is positive (S is then positive definite on
/// ker A^T) or settles. Returns |S|, the largest absolute row sum (Gershgorin: S >= -|S|).
double stiffnessOnFlexes(const Sparse& s, const Sparse& loaded,
                         const SecondOrderParameters& parameters, SecondOrderResult& result) {
    double bound = 0.0;
    for (int c = 0; c < s.outerSize(); ++c) // S is symmetric: column sums are row sums
        bound = std::max(bound, s.col(c).cwiseAbs().sum());
    const Sparse aat = loaded * loaded.transpose();
    const double aScale = aat.nonZeros() > 0 ? aat.diagonal().maxCoeff() : 1.0;
    const double scale = bound > 0.0 ? bound : 1.0;
    double previous = -std::numeric_limits<double>::infinity();
    for (double factor = 1e2; factor <= 1e8; factor *= 1e2) {
        result.penalty = factor * scale / aScale;
        const Sparse k = s + result.penalty * aat;
        const Eigenpair smallest = smallestEigenpair(k, -1.01 * bound - 1e-12 * scale);
        result.smallestStiffness = smallest.value;
        result.softestMode = smallest.vector;
        if (smallest.value > parameters.stiffnessTolerance * scale ||
            std::abs(smallest.value - previous) <= parameters.penaltyConvergence * scale)
            break;
        previous = smallest.value;
    }
    return scale;
}

/// A self-stress to test: not empty; given forces only where the network has a self-stress for
/// them to approximate (dim ker A > 0: sbgen's stored forces on a network without one proved
/// "not jammed" of nothing, bench/RESULTS.md "p = 1.1") or where they balance within
/// residualAcceptance themselves (the relaxation's forces, docs/jamming.md §6.7, whose
/// rounding may hide the kernel from the rank's tolerance); the program's least-residual forces
/// within residualAcceptance of balance (docs/jamming.md §6.6).
bool accepted(const SecondOrderResult& result, const SecondOrderParameters& parameters) {
    if (result.stress.forces.size() == 0) return false;
    const bool balanced = result.stress.balanceResidual <= parameters.residualAcceptance;
    if (result.forcesGiven) return result.selfStresses > 0 || balanced;
    return parameters.selfStress == SelfStressProgram::Exact || balanced;
}

/// The reduced vector v as a full dof vector, the fixed particle's translation 0.
Eigen::VectorXd fullMode(const Eigen::VectorXd& v) {
    Eigen::VectorXd mode = Eigen::VectorXd::Zero(v.size() + 3);
    mode.tail(v.size()) = v;
    return mode;
}

} // namespace

SecondOrderTest::SecondOrderTest(SecondOrderParameters parameters) : parameters_(parameters) {
    for (const double tolerance :
         {parameters_.loadTolerance, parameters_.stiffnessTolerance, parameters_.penaltyConvergence,
          parameters_.rankTolerance, parameters_.residualAcceptance})
        if (!(tolerance > 0.0 && tolerance < 1.0))
            throw std::invalid_argument("second-order test: tolerance " +
                                        std::to_string(tolerance) + " must lie in (0, 1)");
}

SecondOrderResult SecondOrderTest::compute(const RigidityNetwork& network,
                                           const std::optional<Eigen::VectorXd>& forces) const {
    if (network.backbone.empty())
        throw std::invalid_argument("second-order test: the packing has no backbone");
    const auto start = std::chrono::steady_clock::now();
    const SecondOrderParameters& p = parameters_;
    SecondOrderResult result;
    result.forcesGiven = forces.has_value();
    result.stress = forces ? givenSelfStress(network, *forces, p.loadTolerance)
                           : findSelfStress(network, p.loadTolerance, p.solver, p.selfStress);
    const DegreesOfFreedom dof = degreesOfFreedom(network, JammingCategory::Collective);
    const Sparse a = rigidityMatrix(network, JammingCategory::Collective);
    const int contacts = static_cast<int>(a.cols()), motions = dof.count() - 3;
    const int rank = rankOf(reducedRigidity(a, std::vector<char>(contacts, 1)), p.rankTolerance);
    result.floppyModes = motions - rank;
    result.selfStresses = contacts - rank;
    const auto finish = [&](SecondOrderVerdict verdict) {
        result.verdict = verdict;
        result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return result;
    };
    if (!accepted(result, p)) return finish(SecondOrderVerdict::NoSelfStress);
    std::vector<char> loaded(contacts);
    Eigen::VectorXd f = result.stress.forces;
    for (int c = 0; c < contacts; ++c) {
        loaded[c] = f[c] > p.loadTolerance;
        if (!loaded[c]) f[c] = 0.0;
    }
    bool singular = false;
    const Sparse s = stiffnessMatrix(network, f, dof, singular);
    if (singular) return finish(SecondOrderVerdict::SingularCurvature);
    const Sparse loadedRigidity = reducedRigidity(a, loaded);
    result.testedModes = motions - rankOf(loadedRigidity, p.rankTolerance);
    if (motions == 0) return finish(SecondOrderVerdict::Jammed);
    const double scale = stiffnessOnFlexes(s, loadedRigidity, p, result);
    result.flexResidual = (loadedRigidity.transpose() * result.softestMode).norm();
    result.softestMode = fullMode(result.softestMode);
    if (result.smallestStiffness > 0.0) // Eq. (R) of docs/jamming.md §6.6
        result.curvatureRadius = result.stress.residualNorm / result.smallestStiffness;
    return finish(result.smallestStiffness > p.stiffnessTolerance * scale
                      ? SecondOrderVerdict::Jammed
                      : SecondOrderVerdict::NotJammed);
}

} // namespace sbpack

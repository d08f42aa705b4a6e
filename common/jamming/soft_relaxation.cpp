#include "jamming/soft_relaxation.hpp"

#include "contacts/contact_network.hpp"
#include "jamming/gap_hessian.hpp"
#include "jamming/rigidity_matrix.hpp"
#include "pair/pair_geometry.hpp"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

namespace sbpack {

namespace {

using Vector12d = Eigen::Matrix<double, 12, 1>;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// The i-th of the five traceless strains of BoxStrain.
Matrix3d strainBasis(int k) {
    Matrix3d e = Matrix3d::Zero();
    if (k < 2) {
        e(k, k) = 1.0;
        e(2, 2) = -1.0;
        return e;
    }
    const int pairs[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    e(pairs[k - 2][0], pairs[k - 2][1]) = e(pairs[k - 2][1], pairs[k - 2][0]) = 1.0;
    return e;
}

/// A particle configuration in its periodic cell (F, det F = 1; the identity for the cubic box).
struct State {
    Packing packing;
    Matrix3d cell = Matrix3d::Identity();
};

/// The separation of j from i by the minimum image of the cubic reference lattice, d = F
/// minimumImage(F^-1 (r_j - r_i)), and the lattice vector F L m it adds (docs/jamming.md §6.8).
struct PairImage {
    Vector3d separation;
    Vector3d shift;
};
PairImage pairImage(const State& state, const Matrix3d& cellInverse, int i, int j) {
    const Vector3d inBox = state.packing.positions[j] - state.packing.positions[i];
    const Vector3d shift = cellImageShift(inBox, state.cell, cellInverse, state.packing.boxLength);
    return {inBox + shift, shift};
}

/// `state`'s packing in the cubic reference frame: F^-1 r, wrapped into the cube.
Packing referencePacking(const State& state) {
    const Matrix3d cellInverse = state.cell.inverse();
    Packing reference = state.packing;
    for (Vector3d& r : reference.positions)
        r = wrapIntoBox(cellInverse * r, state.packing.boxLength);
    return reference;
}

/// The pairs of `state` within `range` D (ContactNetwork with `rattlerThreshold`), found in the
/// cubic reference frame F^-1 r, the range widened by what F can shorten a separation: a superset
/// of the pairs within `range` in the cell.
ContactResult referencePairs(const State& state, double range, int rattlerThreshold) {
    const Matrix3d cellInverse = state.cell.inverse();
    const ParticleShape shape = state.packing.shape();
    const double distortion = (cellInverse - Matrix3d::Identity()).norm() *
                              (2.0 * shape.circumradius() / shape.diameter() + range);
    return ContactNetwork(
               {std::min(range + distortion, ContactParameters::kMaxTolerance), rattlerThreshold})
        .compute(referencePacking(state));
}

/// What one evaluation of E gives.
struct EnergyTerms {
    double energy = 0.0;
    Eigen::VectorXd gradient;
    Triplets hessian;
    int contacts = 0;
    double forceSum = 0.0;                                        ///< sum of f_c, length units
    double smallestGap = std::numeric_limits<double>::infinity(); ///< min s_c, length units
    /// |grad E|_inf with the strains' entries over L: forces, not forces times a box length.
    double imbalance = 0.0;
    double meanForce() const { return contacts > 0 ? forceSum / contacts : 0.0; }
};

/// E at one shell, in the packing's length units (forces f_c = shell - s_c are lengths): the
/// candidate pairs and their last normals (warm starts of the pair solver), translations then
/// rotations (p != 1) per particle as in jamming/rigidity_matrix.hpp, then the box's strains.
class OverlapEnergy {
  public:
    OverlapEnergy(const Packing& packing, double shell, double margin, bool deformBox)
        : shape_(packing.shape()), shell_(shell * packing.shape().diameter()),
          margin_(margin * packing.shape().diameter()), boxLength_(packing.boxLength),
          rotations_(!shape_.isSphere()), deformBox_(deformBox),
          particles_(static_cast<int>(packing.size())) {}

    int particleUnknowns() const { return (rotations_ ? 6 : 3) * particles_; }
    int unknowns() const { return particleUnknowns() + (deformBox_ ? kBoxStrains : 0); }
    bool rotations() const { return rotations_; }
    double shell() const { return shell_; }
    double boxLength() const { return boxLength_; }

    EnergyTerms evaluate(const State& state, bool hessian) {
        if (built_.empty() || movedSinceBuilt(state) > 0.25 * margin_) findCandidates(state);
        EnergyTerms terms;
        terms.gradient = Eigen::VectorXd::Zero(unknowns());
        const Matrix3d cellInverse = state.cell.inverse();
        for (std::size_t k = 0; k < candidates_.size(); ++k)
            addPair(state, cellInverse, k, hessian, terms);
        terms.imbalance = terms.gradient.head(particleUnknowns()).lpNorm<Eigen::Infinity>();
        if (deformBox_)
            terms.imbalance =
                std::max(terms.imbalance,
                         terms.gradient.tail<kBoxStrains>().lpNorm<Eigen::Infinity>() / boxLength_);
        return terms;
    }

    /// The state moved by dq: r += dr, R = exp([dtheta]) R (as gap_hessian.hpp's chart), F =
    /// strainedCell(F, strains).
    State moved(const State& state, const Eigen::VectorXd& dq) const {
        State next = state;
        for (int i = 0; i < particles_; ++i) {
            next.packing.positions[i] = state.packing.positions[i] + dq.segment<3>(3 * i);
            if (!rotations_) continue;
            const Vector3d turn = dq.segment<3>(3 * (particles_ + i));
            const double angle = turn.norm();
            if (angle > 0.0)
                next.packing.orientations[i] =
                    (Quaterniond(Eigen::AngleAxisd(angle, turn / angle)) *
                     state.packing.orientations[i])
                        .normalized();
        }
        if (deformBox_) next.cell = strainedCell(state.cell, dq.tail<kBoxStrains>());
        return next;
    }

  private:
    /// The largest change of a candidate's separation since the candidates were found: the
    /// particles' translations plus the circumradius times the angle turned, and the cell's
    /// change times the longest lattice vector a minimum image adds (sqrt(3) L).
    double movedSinceBuilt(const State& state) const {
        double largest = 0.0;
        for (int i = 0; i < particles_; ++i)
            largest = std::max(largest,
                               (state.packing.positions[i] - built_[i]).norm() +
                                   shape_.circumradius() *
                                       state.packing.orientations[i].angularDistance(turned_[i]));
        return largest + (state.cell - builtCell_).norm() * std::sqrt(3.0) * boxLength_;
    }

    /// The pairs within the shell and the margin (referencePairs).
    void findCandidates(const State& state) {
        const ContactResult pairs =
            referencePairs(state, (shell_ + margin_) / shape_.diameter(), 1);
        candidates_ = pairs.contacts;
        normals_ = pairs.normals;
        built_ = state.packing.positions;
        turned_ = state.packing.orientations;
        builtCell_ = state.cell;
    }

    void addPair(const State& state, const Matrix3d& cellInverse, std::size_t k, bool hessian,
                 EnergyTerms& terms);

    ParticleShape shape_;
    double shell_, margin_, boxLength_;
    bool rotations_, deformBox_;
    int particles_;
    std::vector<std::pair<int, int>> candidates_;
    std::vector<Vector3d> normals_;
    std::vector<Vector3d> built_;
    std::vector<Quaterniond> turned_;
    Matrix3d builtCell_ = Matrix3d::Identity();
};

constexpr int kPairUnknowns = 12 + kBoxStrains;
using PairVector = Eigen::Matrix<double, kPairUnknowns, 1>;
using PairMatrix = Eigen::Matrix<double, kPairUnknowns, kPairUnknowns>;

/// tr(e_k e_l) of the five strains, computed once: every strained pair's Hessian takes it.
const Eigen::Matrix<double, kBoxStrains, kBoxStrains>& strainTraces() {
    static const Eigen::Matrix<double, kBoxStrains, kBoxStrains> traces = [] {
        Eigen::Matrix<double, kBoxStrains, kBoxStrains> t;
        for (int k = 0; k < kBoxStrains; ++k)
            for (int l = 0; l < kBoxStrains; ++l)
                t(k, l) = (strainBasis(k) * strainBasis(l)).trace();
        return t;
    }();
    return traces;
}

/// The gap's gradient and Hessian in (dr_i, dtheta_i, dr_j, dtheta_j) extended to the strains
/// (docs/jamming.md §6.8): a strain eps moves j's image by eps (F L m), as a translation of j
/// would, so its entries are W^T of j's translation entries, W = [e_k F L m]; the rescaling to
/// det 1 (strainedCell), 1 + tr(eps^2) / 6 to second order, adds tr(e_k e_l) / 3 (n . F L m) to
/// the gap's second derivatives, so -f times it to E's.
void extendToStrains(const Vector3d& shift, const Vector3d& normal, double force,
                     PairVector& column, PairMatrix& second) {
    Eigen::Matrix<double, 12, kBoxStrains> lift = Eigen::Matrix<double, 12, kBoxStrains>::Zero();
    for (int k = 0; k < kBoxStrains; ++k)
        lift.block<3, 1>(6, k) = strainBasis(k) * shift;
    const Eigen::Matrix<double, 12, 12> gap = second.topLeftCorner<12, 12>();
    column.tail<kBoxStrains>() = lift.transpose() * column.head<12>();
    second.topRightCorner<12, kBoxStrains>() = gap * lift;
    second.bottomLeftCorner<kBoxStrains, 12>() = lift.transpose() * gap;
    second.bottomRightCorner<kBoxStrains, kBoxStrains>() = lift.transpose() * gap * lift;
    second.bottomRightCorner<kBoxStrains, kBoxStrains>() -=
        force * normal.dot(shift) / 3.0 * strainTraces();
}

void OverlapEnergy::addPair(const State& state, const Matrix3d& cellInverse, std::size_t k,
                            bool hessian, EnergyTerms& terms) {
    const auto [i, j] = candidates_[k];
    const PairImage image = pairImage(state, cellInverse, i, j);
    const Vector3d& d = image.separation;
    if (d.norm() > 2.0 * shape_.circumradius() + shell_) return;
    const Matrix3d rotationI = state.packing.orientations[i].toRotationMatrix();
    const Matrix3d rotationJ = state.packing.orientations[j].toRotationMatrix();
    const SignedDistanceResult pair =
        signedDistance(BodyPair<ParticleShape>{shape_, rotationI, rotationJ, d}, normals_[k]);
    normals_[k] = pair.normal;
    terms.smallestGap = std::min(terms.smallestGap, pair.signedDistance);
    const double force = shell_ - pair.signedDistance;
    if (force <= 0.0) return;
    // The rigidity column a_c, with the rigidity network's lever arms.
    const ContactCurvature contact =
        contactCurvature(shape_, rotationI, rotationJ, d, pair.normal, pair.signedDistance);
    const Vector3d leverI = midpointLever(contact);
    PairVector column = PairVector::Zero();
    column.head<12>() = gapGradient(pair.normal, leverI, leverI - d);
    PairMatrix second = PairMatrix::Zero();
    second.topLeftCorner<12, 12>() = column.head<12>() * column.head<12>().transpose();
    if (hessian) {
        const Matrix12d curvature = gapHessian(contact);
        if (curvature.allFinite()) // flat faces: Gauss-Newton
            second.topLeftCorner<12, 12>() -= force * curvature;
    }
    const bool strained = deformBox_ && !image.shift.isZero();
    if (strained) extendToStrains(image.shift, pair.normal, force, column, second);
    // The unknowns of the pair's entries: i's and j's translations and rotations, the strains.
    std::array<std::pair<int, int>, kPairUnknowns> entries; // (entry, unknown), no allocation
    int count = 0;
    for (int a = 0; a < 3; ++a) {
        entries[count++] = {a, 3 * i + a};
        entries[count++] = {6 + a, 3 * j + a};
        if (!rotations_) continue;
        entries[count++] = {3 + a, 3 * (particles_ + i) + a};
        entries[count++] = {9 + a, 3 * (particles_ + j) + a};
    }
    for (int s = 0; strained && s < kBoxStrains; ++s)
        entries[count++] = {12 + s, particleUnknowns() + s};
    const auto active = std::span(entries).first(static_cast<std::size_t>(count));
    terms.energy += 0.5 * force * force;
    terms.forceSum += force;
    ++terms.contacts;
    for (const auto& [u, row] : active) {
        terms.gradient[row] -= force * column[u];
        if (!hessian) continue;
        for (const auto& [w, col] : active)
            terms.hessian.emplace_back(row, col, second(u, w));
    }
}

constexpr double kLargestStep = 1e-2;
/// Whatever the rounding, a stall whose net forces reach this fraction of the mean force is no
/// balance (at delta = 1e-10 D the gaps' rounding is 1e-5 of the forces, docs/jamming.md §6.7).
constexpr double kStalledImbalance = 1e-3;

/// The Levenberg-Marquardt step (H + mu M) dq = -grad E, M = 1 on translations, (D / 2)^2 on
/// rotations and L^2 on strains (units); empty where the factorisation fails or is not positive
/// definite.
std::optional<Eigen::VectorXd> dampedStep(const OverlapEnergy& energy, const EnergyTerms& terms,
                                          double mu, double diameter) {
    const int n = energy.unknowns(), particles = energy.particleUnknowns();
    const int translations = energy.rotations() ? particles / 2 : particles;
    const double length = energy.boxLength();
    Triplets entries = terms.hessian;
    for (int u = 0; u < n; ++u)
        entries.emplace_back(u, u,
                             mu * (u < translations ? 1.0
                                   : u < particles  ? 0.25 * diameter * diameter
                                                    : length * length));
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(matrix);
    if (factor.info() != Eigen::Success || factor.vectorD().minCoeff() <= 0.0) return std::nullopt;
    Eigen::VectorXd dq = factor.solve(-terms.gradient);
    // No particle moves by more than kLargestStep D (or turns by 2 kLargestStep rad), nor the
    // cell's strain moves an image by more, in a step, so that no step carries one through
    // another: the path is one of small moves.
    double largest = 0.0;
    for (int u = 0; u < particles; u += 3)
        largest =
            std::max(largest, dq.segment<3>(u).norm() * (u < translations ? 1.0 : 0.5 * diameter));
    if (n > particles)
        largest = std::max(largest, dq.tail(n - particles).norm() * std::sqrt(3.0) * length);
    if (largest > kLargestStep * diameter) dq *= kLargestStep * diameter / largest;
    return dq;
}

/// Jammed, unjammed or not yet (lengths in the packing's units, D = `diameter`). A stall counts
/// as jammed only where the gradient is down to rounding (of the gaps, absolute, or of the
/// normals, relative to the forces), not where the model Hessian (Gauss-Newton on flat faces)
/// finds no descent.
SoftVerdict verdictOf(const EnergyTerms& terms, double shell, double diameter,
                      const RelaxationParameters& p, bool stalled) {
    const double meanForce = terms.meanForce();
    const double gradient = terms.imbalance;
    if (meanForce <= p.unjammedForce * shell) return SoftVerdict::Unjammed;
    if (gradient <= p.balanceTolerance * meanForce) return SoftVerdict::Jammed;
    if (stalled && meanForce > p.stalledForce * shell &&
        gradient <= std::max(p.stalledGradient * diameter, p.stalledBalance * meanForce) &&
        gradient <= kStalledImbalance * meanForce)
        return SoftVerdict::Jammed;
    return SoftVerdict::Unconverged;
}

/// `state`'s positions wrapped into its cell: F wrapIntoBox(F^-1 r).
void wrapIntoCell(State& state) {
    state.packing.positions = referencePacking(state).positions;
    for (Vector3d& r : state.packing.positions)
        r = state.cell * r;
}

} // namespace

Matrix3d strainedCell(const Matrix3d& cell, const BoxStrain& strain) {
    Matrix3d step = Matrix3d::Identity();
    for (int k = 0; k < kBoxStrains; ++k)
        step += strain[k] * strainBasis(k);
    const Matrix3d next = step * cell;
    return next / std::cbrt(next.determinant());
}

OverlapEnergyTerms overlapEnergy(const Packing& packing, double shell,
                                 const std::optional<Matrix3d>& cell) {
    OverlapEnergy energy(packing, shell, RelaxationParameters{}.candidateMargin, cell.has_value());
    EnergyTerms terms = energy.evaluate({packing, cell.value_or(Matrix3d::Identity())}, true);
    Eigen::SparseMatrix<double> hessian(energy.unknowns(), energy.unknowns());
    hessian.setFromTriplets(terms.hessian.begin(), terms.hessian.end());
    return {terms.energy, std::move(terms.gradient), Eigen::MatrixXd(hessian)};
}

ContactResult relaxedContacts(const SoftMinimum& minimum, double tolerance, int rattlerThreshold) {
    const Packing& packing = minimum.packing;
    const double diameter = packing.shape().diameter();
    const State state{packing, minimum.cell};
    const Matrix3d cellInverse = state.cell.inverse();
    const ContactResult candidates = referencePairs(state, tolerance, 1);
    ContactResult result;
    result.parameters = {tolerance, rattlerThreshold};
    result.counts.assign(packing.size(), 0);
    for (const auto& [i, j] : candidates.contacts) {
        const Vector3d d = pairImage(state, cellInverse, i, j).separation;
        const SignedDistanceResult pair = signedDistance(
            BodyPair<ParticleShape>{packing.shape(), packing.orientations[i].toRotationMatrix(),
                                    packing.orientations[j].toRotationMatrix(), d});
        if (pair.signedDistance >= tolerance * diameter) continue;
        result.contacts.emplace_back(i, j);
        result.gaps.push_back(pair.signedDistance / diameter);
        result.normals.push_back(pair.normal);
        result.points.push_back(contactPoint(pair));
        ++result.counts[i];
        ++result.counts[j];
    }
    removeRattlers(result, rattlerThreshold);
    return result;
}

void validate(const RelaxationParameters& p) {
    const auto inUnit = [](double x) { return x > 0.0 && x < 1.0; };
    if (!(p.smallestShell > 0.0 && p.smallestShell <= p.largestShell && p.largestShell <= 0.05))
        throw std::invalid_argument("relaxation: shells must satisfy 0 < smallest (" +
                                    std::to_string(p.smallestShell) + ") <= largest (" +
                                    std::to_string(p.largestShell) + ") <= 0.05 D");
    if (!inUnit(p.bracketWidth) || !inUnit(p.balanceTolerance) || !inUnit(p.unjammedForce) ||
        !inUnit(p.stalledForce) || !inUnit(p.stalledGradient) || !inUnit(p.stalledBalance) ||
        !(p.candidateMargin > 0.0 && p.candidateMargin <= 0.05))
        throw std::invalid_argument("relaxation: the bracket width and the tolerances must lie "
                                    "in (0, 1), the candidate margin in (0, 0.05] D");
    if (p.maxIterations < 1) throw std::invalid_argument("relaxation: at least one iteration");
}

SoftMinimum minimiseOverlapEnergy(const Packing& packing, double shell,
                                  const RelaxationParameters& parameters,
                                  const RelaxationPoll& poll, const Matrix3d& cell) {
    validate(parameters);
    const auto start = std::chrono::steady_clock::now();
    const double diameter = packing.shape().diameter();
    OverlapEnergy energy(packing, shell, parameters.candidateMargin, parameters.deformBox);
    SoftMinimum out;
    out.shell = shell;
    State state{packing, cell};
    EnergyTerms terms = energy.evaluate(state, true);
    out.deepestOverlap = std::max(0.0, -terms.smallestGap / diameter);
    double mu = shell; // dimensionless, as the translation block of H (units of D)
    bool stalled = false;
    for (; out.iterations < parameters.maxIterations; ++out.iterations) {
        out.verdict = verdictOf(terms, energy.shell(), diameter, parameters, stalled);
        if (out.verdict != SoftVerdict::Unconverged || stalled) break;
        if (poll) poll();
        bool improved = false;
        for (; !improved && mu < 1e3; mu *= 10.0) {
            const std::optional<Eigen::VectorXd> dq = dampedStep(energy, terms, mu, diameter);
            if (!dq) continue;
            State trial = energy.moved(state, *dq);
            EnergyTerms next = energy.evaluate(trial, true);
            if (next.energy < terms.energy) {
                out.deepestOverlap = std::max(out.deepestOverlap, -next.smallestGap / diameter);
                state = std::move(trial);
                terms = std::move(next);
                improved = true;
            }
        }
        mu = std::max(mu / 100.0, 1e-20);
        stalled = !improved; // rounding: no damped step lowers E
    }
    wrapIntoCell(state);
    out.packing = std::move(state.packing);
    out.cell = state.cell;
    out.contacts = terms.contacts;
    out.meanForce = terms.meanForce() / diameter;
    out.balanceResidual = terms.contacts > 0 ? terms.imbalance / terms.meanForce() : 0.0;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

namespace {

/// Each particle's displacement from `given` less the cell's affine part, the rotations and the
/// cell's strain (docs/jamming.md §6.8).
void measureMotion(const Packing& given, JammingPoint& point) {
    const double diameter = given.shape().diameter();
    const Packing& relaxed = point.relaxed.packing;
    const Matrix3d cellInverse = point.relaxed.cell.inverse();
    point.boxStrain = (point.relaxed.cell - Matrix3d::Identity()).cwiseAbs().maxCoeff();
    for (std::size_t i = 0; i < given.size(); ++i) {
        point.displacement.push_back(
            minimumImage(cellInverse * relaxed.positions[i] - given.positions[i], given.boxLength) /
            diameter);
        point.largestDisplacement =
            std::max(point.largestDisplacement, point.displacement.back().norm());
        point.largestRotation = std::max(
            point.largestRotation, relaxed.orientations[i].angularDistance(given.orientations[i]));
    }
}

} // namespace

JammingPoint findJammingPoint(const Packing& packing, const RelaxationParameters& parameters,
                              const RelaxationPoll& poll, const RelaxationReport& report) {
    validate(parameters);
    const auto start = std::chrono::steady_clock::now();
    JammingPoint point;
    // The last unjammed minimum and its cell: each shell compresses from there.
    Packing base = packing;
    Matrix3d baseCell = Matrix3d::Identity();
    double chainOverlap = 0.0;
    SoftMinimum last; // the latest minimisation not jammed: the result where none is
    // Jammed only at a minimum whose forces balance (or stall at rounding); an unconverged
    // minimisation is still sliding and counts as unjammed, its state not kept.
    const auto attempt = [&](double shell) {
        SoftMinimum minimum = minimiseOverlapEnergy(base, shell, parameters, poll, baseCell);
        ++point.minimisations;
        if (report) report(minimum);
        if (minimum.verdict == SoftVerdict::Jammed) {
            point.relaxed = std::move(minimum);
            return true;
        }
        if (minimum.verdict == SoftVerdict::Unconverged)
            ++point.unconverged;
        else {
            chainOverlap = std::max(chainOverlap, minimum.deepestOverlap);
            base = minimum.packing;
            baseCell = minimum.cell;
        }
        last = std::move(minimum);
        return false;
    };
    for (double shell = parameters.smallestShell;; shell *= 10.0) {
        shell = std::min(shell, parameters.largestShell);
        point.found = attempt(shell);
        (point.found ? point.jammedShell : point.unjammedShell) = shell;
        if (point.found || shell >= parameters.largestShell) break;
    }
    while (point.found && point.unjammedShell > 0.0 &&
           point.jammedShell - point.unjammedShell > parameters.bracketWidth * point.jammedShell) {
        const double middle = 0.5 * (point.unjammedShell + point.jammedShell);
        (attempt(middle) ? point.jammedShell : point.unjammedShell) = middle;
    }
    if (!point.found) point.relaxed = std::move(last);
    point.deepestOverlap = std::max(chainOverlap, point.relaxed.deepestOverlap);
    measureMotion(packing, point);
    point.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return point;
}

} // namespace sbpack

#include "jamming/soft_relaxation.hpp"

#include "contacts/contact_network.hpp"
#include "jamming/gap_hessian.hpp"
#include "jamming/rigidity_matrix.hpp"
#include "pair/pair_geometry.hpp"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace sbpack {

namespace {

using Vector12d = Eigen::Matrix<double, 12, 1>;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// What one evaluation of E gives.
struct EnergyTerms {
    double energy = 0.0;
    Eigen::VectorXd gradient;
    Triplets hessian;
    int contacts = 0;
    double forceSum = 0.0;                                        ///< sum of f_c, length units
    double smallestGap = std::numeric_limits<double>::infinity(); ///< min s_c, length units
    double meanForce() const { return contacts > 0 ? forceSum / contacts : 0.0; }
};

/// E at one shell, in the packing's length units (forces f_c = shell - s_c are lengths): the
/// candidate pairs and their last normals (warm starts of the pair solver), translations then
/// rotations (p != 1) per particle as in jamming/rigidity_matrix.hpp.
class OverlapEnergy {
  public:
    OverlapEnergy(const Packing& packing, double shell, double margin)
        : shape_(packing.shape()), shell_(shell * packing.shape().diameter()),
          margin_(margin * packing.shape().diameter()), rotations_(!shape_.isSphere()),
          particles_(static_cast<int>(packing.size())) {}

    int unknowns() const { return (rotations_ ? 6 : 3) * particles_; }
    bool rotations() const { return rotations_; }
    double shell() const { return shell_; }

    EnergyTerms evaluate(const Packing& state, bool hessian) {
        if (built_.empty() || movedSinceBuilt(state) > 0.25 * margin_) findCandidates(state);
        EnergyTerms terms;
        terms.gradient = Eigen::VectorXd::Zero(unknowns());
        for (std::size_t k = 0; k < candidates_.size(); ++k)
            addPair(state, k, hessian, terms);
        return terms;
    }

    /// The state moved by dq: r += dr, R = exp([dtheta]) R (as gap_hessian.hpp's chart).
    Packing moved(const Packing& state, const Eigen::VectorXd& dq) const {
        Packing next = state;
        for (int i = 0; i < particles_; ++i) {
            next.positions[i] = state.positions[i] + dq.segment<3>(3 * i);
            if (!rotations_) continue;
            const Vector3d turn = dq.segment<3>(3 * (particles_ + i));
            const double angle = turn.norm();
            if (angle > 0.0)
                next.orientations[i] =
                    (Quaterniond(Eigen::AngleAxisd(angle, turn / angle)) * state.orientations[i])
                        .normalized();
        }
        return next;
    }

  private:
    /// The largest surface motion since the candidates were found: translation plus the
    /// circumradius times the angle turned.
    double movedSinceBuilt(const Packing& state) const {
        double largest = 0.0;
        for (int i = 0; i < particles_; ++i)
            largest = std::max(largest, (state.positions[i] - built_[i]).norm() +
                                            shape_.circumradius() *
                                                state.orientations[i].angularDistance(turned_[i]));
        return largest;
    }

    void findCandidates(const Packing& state) {
        Packing wrapped = state;
        for (Vector3d& r : wrapped.positions)
            r = wrapIntoBox(r, state.boxLength);
        const double range =
            std::min((shell_ + margin_) / shape_.diameter(), ContactParameters::kMaxTolerance);
        const ContactResult pairs = ContactNetwork({range, 1}).compute(wrapped);
        candidates_ = pairs.contacts;
        normals_ = pairs.normals;
        built_ = state.positions;
        turned_ = state.orientations;
    }

    void addPair(const Packing& state, std::size_t k, bool hessian, EnergyTerms& terms);

    Superball shape_;
    double shell_, margin_;
    bool rotations_;
    int particles_;
    std::vector<std::pair<int, int>> candidates_;
    std::vector<Vector3d> normals_;
    std::vector<Vector3d> built_;
    std::vector<Quaterniond> turned_;
};

void OverlapEnergy::addPair(const Packing& state, std::size_t k, bool hessian, EnergyTerms& terms) {
    const auto [i, j] = candidates_[k];
    const Vector3d d = minimumImage(state.positions[j] - state.positions[i], state.boxLength);
    if (d.norm() > 2.0 * shape_.circumradius() + shell_) return;
    const Matrix3d rotationI = state.orientations[i].toRotationMatrix();
    const Matrix3d rotationJ = state.orientations[j].toRotationMatrix();
    const SignedDistanceResult pair =
        signedDistance({shape_, rotationI, rotationJ, d}, normals_[k]);
    normals_[k] = pair.normal;
    terms.smallestGap = std::min(terms.smallestGap, pair.signedDistance);
    const double force = shell_ - pair.signedDistance;
    if (force <= 0.0) return;
    // The rigidity column a_c, with the rigidity network's lever arms.
    const ContactCurvature contact =
        contactCurvature(shape_, rotationI, rotationJ, d, pair.normal, pair.signedDistance);
    const Vector3d leverI = midpointLever(contact);
    const Vector12d column = gapGradient(pair.normal, leverI, leverI - d);
    int index[12];
    for (int a = 0; a < 3; ++a) {
        index[a] = 3 * i + a;
        index[3 + a] = 3 * (particles_ + i) + a;
        index[6 + a] = 3 * j + a;
        index[9 + a] = 3 * (particles_ + j) + a;
    }
    const int blocks[4] = {0, 1, 2, 3};
    terms.energy += 0.5 * force * force;
    terms.forceSum += force;
    ++terms.contacts;
    Matrix12d second = column * column.transpose();
    if (hessian) {
        const Matrix12d curvature = gapHessian(contact);
        if (curvature.allFinite()) second -= force * curvature; // flat faces: Gauss-Newton
    }
    for (const int a : blocks) {
        if (!rotations_ && a % 2 == 1) continue;
        for (int u = 3 * a; u < 3 * a + 3; ++u) {
            terms.gradient[index[u]] -= force * column[u];
            if (!hessian) continue;
            for (const int b : blocks) {
                if (!rotations_ && b % 2 == 1) continue;
                for (int w = 3 * b; w < 3 * b + 3; ++w)
                    terms.hessian.emplace_back(index[u], index[w], second(u, w));
            }
        }
    }
}

constexpr double kLargestStep = 1e-2;
/// Whatever the rounding, a stall whose net forces reach this fraction of the mean force is no
/// balance (at delta = 1e-10 D the gaps' rounding is 1e-5 of the forces, docs/jamming.md §6.7).
constexpr double kStalledImbalance = 1e-3;

/// The Levenberg-Marquardt step (H + mu M) dq = -grad E, M = 1 on translations and (D / 2)^2 on
/// rotations (units); empty where the factorisation fails or is not positive definite.
std::optional<Eigen::VectorXd> dampedStep(const OverlapEnergy& energy, const EnergyTerms& terms,
                                          double mu, double diameter) {
    const int n = energy.unknowns();
    const int translations = energy.rotations() ? n / 2 : n;
    Triplets entries = terms.hessian;
    for (int u = 0; u < n; ++u)
        entries.emplace_back(u, u, u < translations ? mu : mu * 0.25 * diameter * diameter);
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(matrix);
    if (factor.info() != Eigen::Success || factor.vectorD().minCoeff() <= 0.0) return std::nullopt;
    Eigen::VectorXd dq = factor.solve(-terms.gradient);
    // No particle moves by more than kLargestStep D (or turns by 2 kLargestStep rad) in a step,
    // so that no step carries one through another: the path is one of small moves.
    double largest = 0.0;
    for (int u = 0; u < n; u += 3)
        largest =
            std::max(largest, dq.segment<3>(u).norm() * (u < translations ? 1.0 : 0.5 * diameter));
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
    const double gradient = terms.gradient.lpNorm<Eigen::Infinity>();
    if (meanForce <= p.unjammedForce * shell) return SoftVerdict::Unjammed;
    if (gradient <= p.balanceTolerance * meanForce) return SoftVerdict::Jammed;
    if (stalled && meanForce > p.stalledForce * shell &&
        gradient <= std::max(p.stalledGradient * diameter, p.stalledBalance * meanForce) &&
        gradient <= kStalledImbalance * meanForce)
        return SoftVerdict::Jammed;
    return SoftVerdict::Unconverged;
}

} // namespace

OverlapEnergyTerms overlapEnergy(const Packing& packing, double shell) {
    OverlapEnergy energy(packing, shell, RelaxationParameters{}.candidateMargin);
    EnergyTerms terms = energy.evaluate(packing, true);
    Eigen::SparseMatrix<double> hessian(energy.unknowns(), energy.unknowns());
    hessian.setFromTriplets(terms.hessian.begin(), terms.hessian.end());
    return {terms.energy, std::move(terms.gradient), Eigen::MatrixXd(hessian)};
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
                                  const RelaxationPoll& poll) {
    validate(parameters);
    const double diameter = packing.shape().diameter();
    OverlapEnergy energy(packing, shell, parameters.candidateMargin);
    SoftMinimum out;
    out.shell = shell;
    out.packing = packing;
    EnergyTerms terms = energy.evaluate(out.packing, true);
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
            Packing trial = energy.moved(out.packing, *dq);
            EnergyTerms next = energy.evaluate(trial, true);
            if (next.energy < terms.energy) {
                out.deepestOverlap = std::max(out.deepestOverlap, -next.smallestGap / diameter);
                out.packing = std::move(trial);
                terms = std::move(next);
                improved = true;
            }
        }
        mu = std::max(mu / 100.0, 1e-20);
        stalled = !improved; // rounding: no damped step lowers E
    }
    for (Vector3d& r : out.packing.positions)
        r = wrapIntoBox(r, packing.boxLength);
    out.contacts = terms.contacts;
    out.meanForce = terms.meanForce() / diameter;
    out.balanceResidual =
        terms.contacts > 0 ? terms.gradient.lpNorm<Eigen::Infinity>() / terms.meanForce() : 0.0;
    return out;
}

namespace {

void measureMotion(const Packing& given, JammingPoint& point) {
    const double diameter = given.shape().diameter();
    const Packing& relaxed = point.relaxed.packing;
    for (std::size_t i = 0; i < given.size(); ++i) {
        point.displacement.push_back(
            minimumImage(relaxed.positions[i] - given.positions[i], given.boxLength) / diameter);
        point.largestDisplacement =
            std::max(point.largestDisplacement, point.displacement.back().norm());
        point.largestRotation = std::max(
            point.largestRotation, relaxed.orientations[i].angularDistance(given.orientations[i]));
    }
}

} // namespace

JammingPoint findJammingPoint(const Packing& packing, const RelaxationParameters& parameters,
                              const RelaxationPoll& poll) {
    validate(parameters);
    const auto start = std::chrono::steady_clock::now();
    JammingPoint point;
    Packing base = packing; // the last unjammed minimum: each shell compresses from there
    double chainOverlap = 0.0;
    SoftMinimum last; // the latest minimisation not jammed: the result where none is
    // Jammed only at a minimum whose forces balance (or stall at rounding); an unconverged
    // minimisation is still sliding and counts as unjammed, its state not kept.
    const auto attempt = [&](double shell) {
        SoftMinimum minimum = minimiseOverlapEnergy(base, shell, parameters, poll);
        ++point.minimisations;
        if (minimum.verdict == SoftVerdict::Jammed) {
            point.relaxed = std::move(minimum);
            return true;
        }
        if (minimum.verdict == SoftVerdict::Unconverged)
            ++point.unconverged;
        else {
            chainOverlap = std::max(chainOverlap, minimum.deepestOverlap);
            base = minimum.packing;
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

#include "jamming/jamming_test.hpp"

#include "jamming/gordan_motion.hpp"
#include "random/random.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A particle moves when by more than this (units of D): the motion tolerance, or in the
/// finite-gap test the unjamming distance.
double movingThreshold(const JammingParameters& parameters) {
    return parameters.finiteGaps() ? parameters.unjammingDistance
                                   : parameters.motionTolerance * parameters.maxStep;
}

/// The rows of a program (units of Delta, x = dq / Delta): A^T, and for Strict the trace
/// eps_xx + eps_yy + eps_zz last.
Eigen::SparseMatrix<double> constraintRows(const Eigen::SparseMatrix<double>& a,
                                           const DegreesOfFreedom& dof) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(a.nonZeros() + 3);
    for (int gap = 0; gap < a.outerSize(); ++gap)
        for (Eigen::SparseMatrix<double>::InnerIterator it(a, gap); it; ++it)
            entries.emplace_back(gap, static_cast<int>(it.row()), it.value());
    const int traceRow = static_cast<int>(a.cols());
    if (dof.strain)
        for (int k = 0; k < 3; ++k)
            entries.emplace_back(traceRow, dof.strainComponent(k), 1.0);
    Eigen::SparseMatrix<double> rows(traceRow + (dof.strain ? 1 : 0), dof.count());
    rows.setFromTriplets(entries.begin(), entries.end());
    return rows;
}

/// The bounds of both programs: |x| <= 1, the strain's |eps| <= 1 / L, the fixed particle's
/// translation 0 (none fixed: fixed < 0); the trace row <= 0.
LinearProgram boundedProgram(const Eigen::SparseMatrix<double>& a, const DegreesOfFreedom& dof,
                             double boxLength, int fixed) {
    LinearProgram program;
    program.constraints = constraintRows(a, dof);
    const Eigen::Index columns = dof.count(), rows = program.constraints.rows();
    program.columnLower = Eigen::VectorXd::Constant(columns, -1.0);
    program.columnUpper = Eigen::VectorXd::Constant(columns, 1.0);
    if (dof.strain) {
        program.columnLower.tail(6).setConstant(-1.0 / boxLength);
        program.columnUpper.tail(6).setConstant(1.0 / boxLength);
    }
    if (fixed >= 0) {
        program.columnLower.segment<3>(dof.translation(fixed)).setZero();
        program.columnUpper.segment<3>(dof.translation(fixed)).setZero();
    }
    program.rowLower = Eigen::VectorXd::Zero(rows);
    program.rowUpper = Eigen::VectorXd::Zero(rows);
    if (dof.strain) program.rowLower[rows - 1] = -kInfinity;
    return program;
}

/// The contact behind column `gap` of A.
int contactOf(int gap, JammingCategory category) {
    return category == JammingCategory::Local ? gap / 2 : gap;
}

/// How far column `gap`'s contact may close in units of Delta: -g / Delta with the gaps, else 0.
double closingBound(int gap, const RigidityNetwork& network, JammingCategory category,
                    const JammingParameters& parameters) {
    return parameters.useGaps ? -network.contacts[contactOf(gap, category)].gap / parameters.maxStep
                              : 0.0;
}

/// The opening program (Donev et al. 2004): maximise sum_c ds_c, ds_c >= -g_c / Delta.
void makeOpening(LinearProgram& program, const Eigen::SparseMatrix<double>& a,
                 const RigidityNetwork& network, JammingCategory category,
                 const JammingParameters& parameters) {
    program.objective = a * Eigen::VectorXd::Ones(a.cols());
    for (int gap = 0; gap < a.cols(); ++gap) {
        program.rowLower[gap] = closingBound(gap, network, category, parameters);
        program.rowUpper[gap] = kInfinity;
    }
}

/// The flex program: maximise sign c . x for a random c, A^T x = 0; in the finite-gap test
/// Donev et al.'s random load over the gaps' polytope, A^T x >= -g / Delta.
void makeFlex(LinearProgram& program, const Eigen::SparseMatrix<double>& a,
              const RigidityNetwork& network, JammingCategory category,
              const JammingParameters& parameters, double sign) {
    Random random(parameters.seed);
    program.objective.resize(a.rows());
    for (Eigen::Index k = 0; k < a.rows(); ++k)
        program.objective[k] = sign * (2.0 * random.uniform() - 1.0);
    const bool load = parameters.finiteGaps();
    for (int gap = 0; gap < a.cols(); ++gap) {
        program.rowLower[gap] = load ? closingBound(gap, network, category, parameters) : 0.0;
        program.rowUpper[gap] = load ? kInfinity : 0.0;
    }
}

/// eps from its components eps_xx, eps_yy, eps_zz, eps_yz, eps_xz, eps_xy.
Matrix3d strainOf(const Eigen::VectorXd& dq, const DegreesOfFreedom& dof) {
    const auto e = [&](int k) { return dq[dof.strainComponent(k)]; };
    Matrix3d strain;
    strain << e(0), e(5), e(4), e(5), e(1), e(3), e(4), e(3), e(2);
    return strain;
}

/// The motion dq = Delta x per packing particle, its ds and the particles that move.
UnjammingMotion motionOf(const Eigen::VectorXd& x, const Eigen::SparseMatrix<double>& a,
                         const RigidityNetwork& network, const DegreesOfFreedom& dof,
                         const JammingParameters& parameters) {
    const Eigen::VectorXd dq = parameters.maxStep * x;
    const double threshold = movingThreshold(parameters);
    UnjammingMotion motion;
    motion.displacement.assign(network.packingSize, Vector3d::Zero());
    if (dof.rotations) motion.rotation.assign(network.packingSize, Vector3d::Zero());
    for (int b = 0; b < dof.particles; ++b) {
        const int particle = network.backbone[b];
        motion.displacement[particle] = dq.segment<3>(dof.translation(b));
        double largest = motion.displacement[particle].lpNorm<Eigen::Infinity>();
        if (dof.rotations) { // radians: not a distance of the finite-gap test's (spheres)
            motion.rotation[particle] = dq.segment<3>(dof.rotation(b));
            if (!parameters.finiteGaps())
                largest = std::max(largest, motion.rotation[particle].lpNorm<Eigen::Infinity>());
        }
        if (largest > threshold) motion.moving.push_back(particle);
    }
    if (dof.strain) motion.strain = strainOf(dq, dof);
    motion.gapChange = a.transpose() * dq;
    return motion;
}

/// How far a motion moves the box's images, eps L (D).
double boxMotion(const UnjammingMotion& motion, const RigidityNetwork& network) {
    return motion.strain.cwiseAbs().maxCoeff() * network.boxLength;
}

/// The largest displacement of a particle, or of the box's images, by a motion (D).
double largestDisplacement(const UnjammingMotion& motion, const RigidityNetwork& network) {
    double largest = boxMotion(motion, network);
    for (const Vector3d& d : motion.displacement)
        largest = std::max(largest, d.lpNorm<Eigen::Infinity>());
    return largest;
}

/// Whether a motion moves a particle, or the box's images by eps L, by more than the moving
/// threshold (the tolerance, or the finite-gap test's unjamming distance).
bool moves(const UnjammingMotion& motion, const RigidityNetwork& network,
           const JammingParameters& parameters) {
    return !motion.moving.empty() || boxMotion(motion, network) > movingThreshold(parameters);
}

/// Records a solution's largest displacement in the result, whether it is kept or not.
const UnjammingMotion& measured(const UnjammingMotion& motion, const RigidityNetwork& network,
                                JammingResult& result) {
    result.largestDisplacement =
        std::max(result.largestDisplacement, largestDisplacement(motion, network));
    return motion;
}

/// The two ends of column `gap` of A: the particle whose test it is first (Local: the other end
/// is held fixed there, -1).
std::pair<int, int> endsOf(int gap, const RigidityNetwork& network, JammingCategory category) {
    const RigidContact& c = network.contacts[contactOf(gap, category)];
    const int i = network.backbone[c.i], j = network.backbone[c.j];
    if (category != JammingCategory::Local) return {i, j};
    return gap % 2 == 0 ? std::pair{i, -1} : std::pair{j, -1};
}

/// Whether column `gap` stays closed (ds <= threshold) while its bodies slide or roll on each
/// other: then curvature decides its second-order change, which for p != 1 can close it (a
/// sphere contact only opens at second order, by |d_perp|^2 / 2D).
bool slidesClosed(const UnjammingMotion& motion, const RigidityNetwork& network,
                  JammingCategory category, int gap, double threshold) {
    if (motion.gapChange[gap] > threshold) return false;
    const RigidContact& c = network.contacts[contactOf(gap, category)];
    const bool local = category == JammingCategory::Local;
    const auto rigidMotion = [&](int backbone, bool held) {
        const int k = network.backbone[backbone];
        return held ? std::pair{Vector3d::Zero().eval(), Vector3d::Zero().eval()}
                    : std::pair{motion.displacement[k], motion.rotation[k]};
    };
    const auto [dri, dti] = rigidMotion(c.i, local && gap % 2 == 1);
    const auto [drj, dtj] = rigidMotion(c.j, local && gap % 2 == 0);
    const Vector3d slip =
        drj + dtj.cross(c.leverJ) - dri - dti.cross(c.leverI) + motion.strain * c.boxShift;
    return std::max(slip.lpNorm<Eigen::Infinity>(), (dtj - dti).lpNorm<Eigen::Infinity>()) >
           threshold;
}

/// The particles an opening certainly frees: the ends of its opening contacts (Local: the end
/// whose test it is). For p != 1 only where no closed contact slides (slidesClosed): in the
/// local test per particle, in the others for the whole motion.
std::vector<int> openedParticles(const UnjammingMotion& opening, const RigidityNetwork& network,
                                 JammingCategory category, double threshold) {
    std::vector<char> opened(network.packingSize, 0), sliding(network.packingSize, 0);
    bool anySliding = false;
    for (int gap = 0; gap < opening.gapChange.size(); ++gap) {
        const auto [a, b] = endsOf(gap, network, category);
        if (opening.gapChange[gap] > threshold) {
            opened[a] = 1;
            if (b >= 0) opened[b] = 1;
        } else if (network.rotations && slidesClosed(opening, network, category, gap, threshold)) {
            sliding[a] = 1;
            anySliding = anySliding || category != JammingCategory::Local;
        }
    }
    std::vector<int> freed;
    for (int k = 0; k < network.packingSize; ++k)
        if (opened[k] && !sliding[k] && !anySliding) freed.push_back(k);
    return freed;
}

/// The particles an opening certainly frees and, for spheres, those a flex moves (sorted); in
/// the finite-gap test those either motion moves by more than the unjamming distance.
std::vector<int> freedParticles(const JammingResult& result, const RigidityNetwork& network) {
    const double threshold = result.parameters.motionTolerance * result.parameters.maxStep;
    const bool finite = result.parameters.finiteGaps();
    std::vector<int> freed;
    if (result.opening)
        freed = finite ? result.opening->moving
                       : openedParticles(*result.opening, network, result.category, threshold);
    if (result.flex && (finite || !network.rotations))
        freed.insert(freed.end(), result.flex->moving.begin(), result.flex->moving.end());
    std::sort(freed.begin(), freed.end());
    freed.erase(std::unique(freed.begin(), freed.end()), freed.end());
    return freed;
}

/// Unjammed where a particle is certainly freed, or for spheres by any motion (a sphere packing
/// is jammed iff first-order rigid); undecided where only motions that second order can block
/// remain (p != 1). The finite-gap test keeps only motions of the unjamming distance, of a
/// particle or of the box's images: any one kept unjams.
FirstOrderVerdict verdictOf(const JammingResult& result, bool rotations) {
    if (!result.freed.empty()) return FirstOrderVerdict::Unjammed;
    const bool motion = result.opening || result.flex;
    if (result.parameters.finiteGaps())
        return motion ? FirstOrderVerdict::Unjammed : FirstOrderVerdict::Jammed;
    if (!motion) return FirstOrderVerdict::Jammed;
    return rotations ? FirstOrderVerdict::Undecided : FirstOrderVerdict::Unjammed;
}

/// The programs' motions found without them where Gordan's alternative allows (Collective and
/// Strict, A of full column rank: jamming/gordan_motion.hpp): an opening accepted only where
/// A^T x opens every contact by more than the tolerance, a flex only where it keeps every gap
/// to the solver's feasibility and moves. Each one not found here is left to its program.
void gordanShortcut(JammingResult& result, const Eigen::SparseMatrix<double>& a,
                    const RigidityNetwork& network, const DegreesOfFreedom& dof,
                    const JammingParameters& parameters) {
    const auto motions = gordanMotions(a, dof, 0, parameters.seed);
    if (!motions) return;
    const double threshold = parameters.motionTolerance * parameters.maxStep;
    if (motions->opening.size() > 0) {
        UnjammingMotion opening = motionOf(motions->opening, a, network, dof, parameters);
        if (opening.gapChange.size() > 0 && opening.gapChange.minCoeff() > threshold &&
            moves(measured(opening, network, result), network, parameters)) {
            result.largestOpening = opening.gapChange.maxCoeff();
            result.opensEveryContact = true;
            result.opening = std::move(opening);
        }
    }
    if (motions->flex.size() > 0) {
        UnjammingMotion flex = motionOf(motions->flex, a, network, dof, parameters);
        if (flex.gapChange.lpNorm<Eigen::Infinity>() <= parameters.solver.feasibility &&
            moves(measured(flex, network, result), network, parameters))
            result.flex = std::move(flex);
    }
}

/// The opening and flex programs for the motions the shortcut left open (Local: both): the
/// local program by the dual simplex, the coupled ones by the barrier (docs/jamming.md §3).
void runPrograms(JammingResult& result, const Eigen::SparseMatrix<double>& a,
                 const RigidityNetwork& network, JammingCategory category,
                 const DegreesOfFreedom& dof, const JammingParameters& parameters) {
    const bool local = category == JammingCategory::Local;
    const LinearProgramMethod method =
        local ? LinearProgramMethod::DualSimplex : LinearProgramMethod::Barrier;
    LinearProgram program = boundedProgram(a, dof, network.boxLength, local ? -1 : 0);
    const bool finite = parameters.finiteGaps();
    if (!result.opensEveryContact) {
        makeOpening(program, a, network, category, parameters);
        UnjammingMotion opening =
            motionOf(maximise(program, method, parameters.solver), a, network, dof, parameters);
        result.largestOpening = opening.gapChange.size() > 0 ? opening.gapChange.maxCoeff() : 0.0;
        if (finite ? moves(measured(opening, network, result), network, parameters)
                   : result.largestOpening > parameters.motionTolerance * parameters.maxStep)
            result.opening = std::move(opening);
    }
    // Donev et al.'s random load in both directions (finite-gap test); else one random flex.
    for (const double sign : {1.0, -1.0}) {
        if (result.flex || (sign < 0.0 && !finite)) break;
        makeFlex(program, a, network, category, parameters, sign);
        UnjammingMotion flex =
            motionOf(maximise(program, method, parameters.solver), a, network, dof, parameters);
        if (moves(measured(flex, network, result), network, parameters))
            result.flex = std::move(flex);
    }
}

} // namespace

JammingTest::JammingTest(JammingParameters parameters) : parameters_(parameters) {
    const double tolerance = parameters_.motionTolerance;
    if (!(parameters_.maxStep > 0.0) || !std::isfinite(parameters_.maxStep))
        throw std::invalid_argument("jamming test: maximum step " +
                                    std::to_string(parameters_.maxStep) +
                                    " must be positive and finite");
    if (!(tolerance > 0.0 && tolerance < 1.0))
        throw std::invalid_argument("jamming test: motion tolerance " + std::to_string(tolerance) +
                                    " must lie in (0, 1)");
    const double distance = parameters_.unjammingDistance;
    if (!(distance >= 0.0 && distance <= parameters_.maxStep) ||
        (distance > 0.0 && !parameters_.useGaps))
        throw std::invalid_argument("jamming test: unjamming distance " + std::to_string(distance) +
                                    " (--jamming-unjam-distance) must lie in [0, the maximum "
                                    "step] and needs the contacts' gaps (--jamming-contacts "
                                    "gaps)");
    const LinearProgramTolerances& solver = parameters_.solver;
    if (!(solver.feasibility > 0.0 && solver.feasibility <= 1e-2 * tolerance &&
          solver.optimality > 0.0 && solver.optimality <= 1e-2 * tolerance))
        throw std::invalid_argument("jamming test: the solver's tolerances must be positive and "
                                    "at most 1e-2 of the motion tolerance");
    SecondOrderTest{parameters_.secondOrder}; // validates its parameters
}

JammingResult JammingTest::compute(const RigidityNetwork& network, JammingCategory category,
                                   const std::optional<Eigen::VectorXd>& forces) const {
    if (network.backbone.empty())
        throw std::invalid_argument("jamming test: the packing has no backbone (all rattlers)");
    const auto start = std::chrono::steady_clock::now();
    JammingResult result;
    result.category = category;
    result.parameters = parameters_;
    result.contacts = static_cast<int>(network.contacts.size());
    const DegreesOfFreedom dof = degreesOfFreedom(network, category);
    const Eigen::SparseMatrix<double> a = rigidityMatrix(network, category);
    const bool local = category == JammingCategory::Local;
    if (!local) {
        result.fixedParticle = network.backbone.front();
        result.isostaticDeficit = dof.count() - 3 - result.contacts;
        if (parameters_.gordanShortcut) gordanShortcut(result, a, network, dof, parameters_);
    }
    if (!result.opensEveryContact || !result.flex)
        runPrograms(result, a, network, category, dof, parameters_);
    result.freed = freedParticles(result, network);
    result.verdict = verdictOf(result, network.rotations);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (category == JammingCategory::Collective && result.verdict == FirstOrderVerdict::Undecided &&
        parameters_.secondOrder.enabled)
        result.secondOrder = SecondOrderTest(parameters_.secondOrder).compute(network, forces);
    return result;
}

JammingResult JammingTest::strictFromCollective(const JammingResult& collective,
                                                const RigidityNetwork& network) {
    if (collective.category != JammingCategory::Collective || !collective.opensEveryContact ||
        collective.contacts != static_cast<int>(network.contacts.size()))
        throw std::invalid_argument("jamming test: strict from collective needs a collective "
                                    "result on the same network that opens every contact");
    const auto start = std::chrono::steady_clock::now();
    JammingResult strict = collective;
    strict.category = JammingCategory::Strict;
    strict.isostaticDeficit =
        degreesOfFreedom(network, JammingCategory::Strict).count() - 3 - strict.contacts;
    strict.secondOrder.reset();
    strict.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return strict;
}

} // namespace sbpack

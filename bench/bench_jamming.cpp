// bench_jamming: the first-order jamming categories of a packing (issue 62; docs/jamming.md §5;
// bench/RESULTS.md, "First-order jamming categories"). For each contact tolerance (default: the
// jam check's at the recorded pressure) and each category: the verdict, the Maxwell count, the
// largest first-order opening, how many particles the opening and the flex move and how spread
// the flex is (participation ratio), the particles freed, and the wall time of both programs;
// where the collective first order is undecided, the second-order stress test. Letter r: the
// least-residual self-stress of a finite-pressure snapshot (docs/jamming.md §6.6) and its rho;
// letter a: that and the second-order test with it (bench/RESULTS.md, "Approximate self-stress");
// letter g: the collective and strict tests by Gordan's shortcut and by the programs alone, side
// by side in one run, with their verdicts and the time ratio (bench/RESULTS.md, "Gordan's
// shortcut").
//
//   bench_jamming FILE [TOLERANCES] [CATEGORIES]   (e.g. 1e-10,1e-8 and lcsrag; default: jam
//   check's, lcs)

#include "contacts/jam_check.hpp"
#include "io/packing_formats.hpp"
#include "jamming/jamming_test.hpp"
#include "jamming/rigidity_matrix.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace sbpack;

namespace {

/// (sum a^2)^2 / (n sum a^4) over the backbone, a the largest motion of each particle: 1 when all
/// move alike, 1 / n when one moves.
double participationRatio(const UnjammingMotion& motion, const RigidityNetwork& network) {
    double second = 0.0, fourth = 0.0;
    for (const int k : network.backbone) {
        double a = motion.displacement[k].norm();
        if (!motion.rotation.empty()) a = std::max(a, 0.5 * motion.rotation[k].norm());
        second += a * a;
        fourth += a * a * a * a;
    }
    return fourth > 0.0 ? second * second / (fourth * static_cast<double>(network.backbone.size()))
                        : 0.0;
}

std::string firstFew(const std::vector<int>& particles) {
    std::string list;
    for (std::size_t k = 0; k < particles.size() && k < 8; ++k) {
        if (k > 0) list += ' ';
        list += std::to_string(particles[k]);
    }
    return particles.size() > 8 ? list + " ..." : list;
}

void row(const char* name, const JammingResult& r, const RigidityNetwork& network) {
    const char* verdicts[] = {"jammed", "unjammed", "undecided (second order)"};
    std::printf("| %s | %s | %d | %.3g | %zu | %zu | %.2f | %zu: %s | %.2f |\n", name,
                verdicts[static_cast<int>(r.verdict)], r.isostaticDeficit, r.largestOpening,
                r.opening ? r.opening->moving.size() : 0, r.flex ? r.flex->moving.size() : 0,
                r.flex ? participationRatio(*r.flex, network) : 0.0, r.freed.size(),
                firstFew(r.freed).c_str(), r.seconds);
}

/// The second-order test (docs/jamming.md §6) below the collective row.
void secondOrderRow(const SecondOrderResult& r) {
    const char* verdicts[] = {"jammed", "not jammed", "no self-stress", "singular curvature"};
    std::printf("\nsecond order: %s; self-stress %s, %d of %lld contacts loaded, balance %.1e; "
                "%d floppy modes (%d on the loaded contacts), %d self-stresses; smallest "
                "stiffness %.3e at mu %.1e (flex residual %.1e); %.2f s\n\n",
                verdicts[static_cast<int>(r.verdict)], r.forcesGiven ? "given" : "by LP",
                r.stress.loadedContacts, static_cast<long long>(r.stress.forces.size()),
                r.stress.balanceResidual, r.floppyModes, r.testedModes, r.selfStresses,
                r.smallestStiffness, r.penalty, r.flexResidual, r.seconds);
}

/// Where the least-residual forces miss balance (docs/jamming.md §6.6): the particles whose net
/// force or torque exceeds rho / 100, and gap x force of the three widest contacts (hard
/// particles' time-averaged forces obey f ~ kT / <gap>, so a balanced network's widest, weakest
/// contacts share one product).
void residualWhere(const RigidityNetwork& network, const SelfStress& stress) {
    const Eigen::VectorXd residual =
        rigidityMatrix(network, JammingCategory::Collective) * stress.forces;
    const int particles = static_cast<int>(network.backbone.size());
    std::vector<char> above(particles, 0);
    for (Eigen::Index k = 0; k < residual.size(); ++k)
        if (std::abs(residual[k]) > 1e-2 * stress.balanceResidual) above[(k / 3) % particles] = 1;
    std::vector<std::pair<double, int>> widest;
    for (std::size_t c = 0; c < network.contacts.size(); ++c)
        widest.emplace_back(network.contacts[c].gap, static_cast<int>(c));
    std::sort(widest.rbegin(), widest.rend());
    std::printf("residual above rho / 100 at %lld particles; widest contacts gap x f:",
                static_cast<long long>(std::count(above.begin(), above.end(), 1)));
    for (std::size_t k = 0; k < 3 && k < widest.size(); ++k)
        std::printf(" %.1e D x %.1e", widest[k].first, stress.forces[widest[k].second]);
    std::printf("\n");
}

/// The least-residual self-stress (docs/jamming.md §6.6) and, with `secondOrder`, the stress test
/// with it given (the acceptance threshold left aside, to see what it would say).
void approximateRow(const RigidityNetwork& network, bool secondOrder) {
    const auto start = std::chrono::steady_clock::now();
    const SecondOrderParameters parameters;
    const SelfStress stress = findSelfStress(network, parameters.loadTolerance, parameters.solver,
                                             SelfStressProgram::LeastResidual);
    std::printf("\nleast-residual self-stress: rho = |A f|_inf %.3e, |A f|_2 %.3e, %d of %lld "
                "contacts loaded, f max %.2f; %.2f s\n",
                stress.balanceResidual, stress.residualNorm, stress.loadedContacts,
                static_cast<long long>(stress.forces.size()), stress.forces.maxCoeff(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    residualWhere(network, stress);
    if (secondOrder) {
        const SecondOrderResult r = SecondOrderTest(parameters).compute(network, stress.forces);
        secondOrderRow(r);
        std::printf("curvature radius |A f|_2 / lambda: %.3e D\n", r.curvatureRadius);
    }
    std::fflush(stdout);
}

/// The collective and strict tests with Gordan's shortcut and with the programs alone.
void gordanRows(const RigidityNetwork& network) {
    JammingParameters programs; // first order only: seconds exclude the second order anyway
    programs.gordanShortcut = false;
    programs.secondOrder.enabled = false;
    const char* verdicts[] = {"jammed", "unjammed", "undecided"};
    for (const auto& [name, category] : {std::pair{"collective", JammingCategory::Collective},
                                         std::pair{"strict", JammingCategory::Strict}}) {
        const JammingResult shortcut = JammingTest({}).compute(network, category);
        const JammingResult baseline = JammingTest(programs).compute(network, category);
        std::printf("gordan %s: shortcut %s (every contact opens: %s, by %.3g D) %.2f s; programs "
                    "%s %.2f s; programs / shortcut %.1f\n",
                    name, verdicts[static_cast<int>(shortcut.verdict)],
                    shortcut.opensEveryContact ? "yes" : "no",
                    shortcut.opening ? shortcut.opening->gapChange.minCoeff() : 0.0,
                    shortcut.seconds, verdicts[static_cast<int>(baseline.verdict)],
                    baseline.seconds, baseline.seconds / shortcut.seconds);
        std::fflush(stdout);
    }
}

std::vector<double> parseList(const std::string& text) {
    std::vector<double> values;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        values.push_back(std::stod(item));
    return values;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_jamming FILE [TOLERANCES] [CATEGORIES]\n");
        return 1;
    }
    const Packing packing = readPackingFile(argv[1]);
    const std::vector<double> tolerances =
        argc > 2 ? parseList(argv[2])
                 : std::vector<double>{
                       checkJam(packing, packing.reducedPressure.value_or(1e12)).tolerance};
    const std::string categories = argc > 3 ? argv[3] : "lcs";
    const JammingTest test({});
    std::printf("%s: N = %zu, p = %g\n", argv[1], packing.size(), packing.superball().p());
    for (const double tolerance : tolerances) {
        const RigidityNetwork network =
            backboneNetwork(packing, ContactNetwork({tolerance, 4}).compute(packing));
        const int deficit = degreesOfFreedom(network, JammingCategory::Collective).count() - 3 -
                            static_cast<int>(network.contacts.size());
        double largestGap = 0.0;
        for (const RigidContact& c : network.contacts)
            largestGap = std::max(largestGap, c.gap);
        std::printf("\ntolerance %.0e D: %zu backbone particles, %zu contacts, deficit %d, "
                    "largest gap %.1e D\n\n",
                    tolerance, network.backbone.size(), network.contacts.size(), deficit,
                    largestGap);
        if (categories.find_first_of("lcs") != std::string::npos)
            std::printf(
                "| category | verdict | deficit | largest opening (D) | opening moves | "
                "flex moves | flex PR | freed | s |\n|---|---|---|---|---|---|---|---|---|\n");
        const std::pair<char, JammingCategory> all[] = {{'l', JammingCategory::Local},
                                                        {'c', JammingCategory::Collective},
                                                        {'s', JammingCategory::Strict}};
        const char* names[] = {"local", "collective", "strict"};
        for (const auto& [letter, category] : all)
            if (categories.find(letter) != std::string::npos) {
                const JammingResult result = test.compute(network, category);
                row(names[static_cast<int>(category)], result, network);
                if (result.secondOrder) secondOrderRow(*result.secondOrder);
                std::fflush(stdout);
            }
        if (categories.find('r') != std::string::npos || categories.find('a') != std::string::npos)
            approximateRow(network, categories.find('a') != std::string::npos);
        if (categories.find('g') != std::string::npos) gordanRows(network);
    }
    return 0;
}

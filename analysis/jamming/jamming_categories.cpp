#include "jamming/jamming_categories.hpp"

#include "contacts/jam_check.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <stdexcept>
#include <tuple>

namespace sbpack {

namespace {

constexpr std::array kCategories{JammingCategory::Local, JammingCategory::Collective,
                                 JammingCategory::Strict};

/// "locally", "collectively", "strictly".
std::string_view adverb(JammingCategory category) {
    return category == JammingCategory::Local        ? "locally"
           : category == JammingCategory::Collective ? "collectively"
                                                     : "strictly";
}

/// The jam check's tolerance at the file's reduced pressure, or --tolerance where it has none,
/// and where it comes from (docs/jamming.md §2).
std::pair<double, std::string> jamCheckTolerance(const Packing& packing,
                                                 const ContactParameters& contacts) {
    if (packing.reducedPressure && *packing.reducedPressure > 0.0) {
        const JamCheckParameters jam;
        const double p = *packing.reducedPressure;
        return {std::clamp(jam.gapsPerPressure / p, jam.minTolerance, jam.maxTolerance),
                fmt::format("jam check at P = {:.3g}", p)};
    }
    return {contacts.tolerance, "--tolerance (no reduced pressure)"};
}

/// The network's tolerance and where it comes from: --jamming-tolerance, else the jam check's.
std::pair<double, std::string> networkTolerance(const Packing& packing,
                                                const JammingSettings& settings,
                                                const ContactParameters& contacts) {
    if (settings.tolerance) return {*settings.tolerance, "--jamming-tolerance"};
    return jamCheckTolerance(packing, contacts);
}

/// Donev et al. 2004's network for the finite-gap test (docs/jamming.md §4.1): the backbone of
/// the jam check's network (its rattlers removed), with every pair of it within
/// --jamming-tolerance (default kFiniteGapTolerance) and its gap.
RigidityNetwork neighbourNetwork(const Packing& packing, const JammingSettings& settings,
                                 const ContactParameters& contacts, PackingJamming& out) {
    const double held = jamCheckTolerance(packing, contacts).first;
    const ContactResult rattlers =
        ContactNetwork({held, contacts.rattlerThreshold}).compute(packing);
    out.tolerance = settings.tolerance.value_or(kFiniteGapTolerance);
    out.toleranceFrom =
        fmt::format("{}: every pair with its gap, the rattlers at {:g} D",
                    settings.tolerance ? "--jamming-tolerance" : "Donev et al.'s", held);
    ContactResult neighbours =
        ContactNetwork({out.tolerance, contacts.rattlerThreshold, true}).compute(packing);
    neighbours.rattler = rattlers.rattler;
    return backboneNetwork(packing, neighbours);
}

} // namespace

std::string_view jammingCategoryName(JammingCategory category) {
    return category == JammingCategory::Local        ? "local"
           : category == JammingCategory::Collective ? "collective"
                                                     : "strict";
}

std::vector<JammingCategory> parseJammingCategories(std::string_view option,
                                                    std::string_view list) {
    std::vector<JammingCategory> categories;
    for (std::size_t begin = 0; begin <= list.size();) {
        const std::size_t comma = std::min(list.find(',', begin), list.size());
        const std::string_view name = list.substr(begin, comma - begin);
        begin = comma + 1;
        const auto* found = std::find_if(kCategories.begin(), kCategories.end(),
                                         [&](auto c) { return jammingCategoryName(c) == name; });
        if (found == kCategories.end())
            throw std::invalid_argument(
                fmt::format("option {}: '{}' is not a jamming category (local, collective, strict)",
                            option, name));
        categories.push_back(*found);
    }
    std::sort(categories.begin(), categories.end());
    categories.erase(std::unique(categories.begin(), categories.end()), categories.end());
    return categories;
}

std::string jammingCategoryNames(const std::vector<JammingCategory>& categories) {
    std::string names;
    for (JammingCategory c : categories) {
        if (!names.empty()) names += ',';
        names += jammingCategoryName(c);
    }
    return names;
}

std::string_view firstOrderVerdictName(FirstOrderVerdict verdict) {
    return verdict == FirstOrderVerdict::Jammed     ? "jammed"
           : verdict == FirstOrderVerdict::Unjammed ? "unjammed"
                                                    : "undecided";
}

std::string_view softVerdictName(SoftVerdict verdict) {
    return verdict == SoftVerdict::Jammed     ? "jammed"
           : verdict == SoftVerdict::Unjammed ? "unjammed"
                                              : "unconverged";
}

std::string_view secondOrderVerdictName(SecondOrderVerdict verdict) {
    return verdict == SecondOrderVerdict::Jammed         ? "jammed"
           : verdict == SecondOrderVerdict::NotJammed    ? "not jammed"
           : verdict == SecondOrderVerdict::NoSelfStress ? "no self-stress"
                                                         : "singular curvature";
}

std::string categoryDetail(const JammingResult& r) {
    std::string detail(firstOrderVerdictName(r.verdict));
    if (!r.freed.empty()) detail += fmt::format(", {} freed", r.freed.size());
    if (r.opening) detail += fmt::format(", an opening moves {}", r.opening->moving.size());
    if (r.opensEveryContact)
        detail += fmt::format(" and opens every contact by {:.3g} D (no self-stress: Gordan)",
                              r.opening->gapChange.minCoeff());
    if (r.flex) detail += fmt::format(", a flex moves {}", r.flex->moving.size());
    if (const auto& s = r.secondOrder)
        detail += fmt::format("; second order: {} ({} floppy modes, {} self-stresses, smallest "
                              "stiffness {:.3g}, {:.3g} s)",
                              secondOrderVerdictName(s->verdict), s->floppyModes, s->selfStresses,
                              s->smallestStiffness, s->seconds);
    return detail;
}

std::optional<JammingCategory> PackingJamming::reached() const {
    std::optional<JammingCategory> highest;
    for (const JammingResult& t : tests)
        if (t.jammed()) highest = t.category;
    return highest;
}

std::string_view PackingJamming::reachedName() const {
    const auto r = reached();
    return r ? jammingCategoryName(*r) : "none";
}

std::vector<std::string_view> PackingJamming::tested(FirstOrderVerdict verdict) const {
    std::vector<std::string_view> names;
    for (const JammingResult& t : tests)
        if (t.verdict == verdict) names.push_back(jammingCategoryName(t.category));
    return names;
}

std::vector<std::string_view> PackingJamming::open() const {
    std::vector<std::string_view> names;
    for (const JammingResult& t : tests)
        if (t.verdict == FirstOrderVerdict::Undecided && !t.jammed())
            names.push_back(jammingCategoryName(t.category));
    return names;
}

std::string PackingJamming::undecided() const {
    return fmt::format("{}", fmt::join(open(), ","));
}

std::string PackingJamming::relaxationSummary() const {
    if (!relaxation) return "";
    const JammingPoint& j = *relaxation;
    if (!j.found)
        return fmt::format("no jammed minimum up to a shell of {:.3g} D ({} of {} minimisations "
                           "unconverged)",
                           j.unjammedShell, j.unconverged, j.minimisations);
    return fmt::format(
        "relaxed to the nearest jammed packing: jamming shell in ({:.3g}, {:.3g}] D, "
        "particles moved <= {:.3g} D, turned <= {:.3g} rad{}",
        j.unjammedShell, j.jammedShell, j.largestDisplacement, j.largestRotation,
        j.boxStrain > 0.0 ? fmt::format(", the box strained by <= {:.3g}", j.boxStrain) : "");
}

std::string PackingJamming::verdict() const {
    if (tests.empty()) return "no backbone: every particle is a rattler";
    const auto r = reached();
    // The first category tested above the one reached that is not jammed.
    const auto next = std::find_if(tests.begin(), tests.end(), [&](const JammingResult& t) {
        return (!r || t.category > *r) && !t.jammed();
    });
    const auto top = std::find_if(tests.begin(), tests.end(),
                                  [&](const JammingResult& t) { return r && t.category == *r; });
    if (next == tests.end())
        return fmt::format("{} jammed at {} order", adverb(*r),
                           top->verdict == FirstOrderVerdict::Jammed ? "first" : "second");
    if (next->secondOrder && next->secondOrder->verdict == SecondOrderVerdict::NotJammed)
        return fmt::format("{}not {} jammed at second order with the self-stress tested",
                           r ? fmt::format("{} jammed, ", adverb(*r)) : "", adverb(next->category));
    if (next->verdict == FirstOrderVerdict::Unjammed)
        return r ? fmt::format("{} jammed, not {} (first order)", adverb(*r),
                               adverb(next->category))
                 : fmt::format("not {} jammed (first order)", adverb(next->category));
    // The second order runs on the collective test only (docs/jamming.md §6).
    const auto second = std::find_if(tests.begin(), tests.end(), [](const JammingResult& t) {
        return t.secondOrder.has_value();
    });
    const std::string pending = fmt::format(
        "undecided at first order: {} (second order: {}; docs/jamming.md §6)",
        fmt::join(open(), ", "),
        second != tests.end()
            ? fmt::format("collective {}", secondOrderVerdictName(second->secondOrder->verdict))
            : std::string("not run"));
    // A category above the undecided ones that first order already decided (unjammed).
    const auto above = std::find_if(next, tests.end(), [](const JammingResult& t) {
        return t.verdict == FirstOrderVerdict::Unjammed;
    });
    const std::string decided =
        above == tests.end()
            ? std::string()
            : fmt::format("; not {} jammed (first order{})", adverb(above->category),
                          above->opensEveryContact ? ": every contact opens" : "");
    return (r ? fmt::format("{} jammed; {}", adverb(*r), pending) : pending) + decided;
}

/// sbgen's stored contact forces on the network's contacts (0 where a contact has none), the
/// second order's self-stress where the packing has them (docs/jamming.md §6, §8); else none.
std::optional<Eigen::VectorXd> storedForces(const Packing& packing,
                                            const RigidityNetwork& network) {
    if (!packing.contactForces) return std::nullopt;
    std::map<std::pair<int, int>, double> force;
    for (const ContactForce& c : packing.contactForces->contacts)
        force[{c.i, c.j}] = c.force;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(network.contacts.size()));
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        const int a = network.backbone[network.contacts[c].i];
        const int b = network.backbone[network.contacts[c].j];
        if (const auto it = force.find({std::min(a, b), std::max(a, b)}); it != force.end())
            f[static_cast<Eigen::Index>(c)] = it->second;
    }
    return f;
}

namespace {

/// The relaxed packing's network at its jamming shell, in its cell, and the relaxation's forces
/// on it, f_c = shell - s_c (docs/jamming.md §6.7-6.8).
std::pair<RigidityNetwork, Eigen::VectorXd>
relaxedNetwork(const JammingPoint& point, const ContactParameters& contacts, PackingJamming& out) {
    // Just above the shell: every pair the relaxation loaded, none it did not (rounding apart).
    out.tolerance = point.jammedShell * (1.0 + 1e-6);
    out.toleranceFrom = "the relaxation's jamming shell";
    const ContactResult network =
        relaxedContacts(point.relaxed, out.tolerance, contacts.rattlerThreshold);
    RigidityNetwork backbone = backboneNetwork(point.relaxed.packing, network, point.relaxed.cell);
    Eigen::VectorXd forces(static_cast<Eigen::Index>(backbone.contacts.size()));
    Eigen::Index k = 0;
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        const auto [i, j] = network.contacts[c];
        if (!network.rattler[i] && !network.rattler[j])
            forces[k++] = std::max(point.jammedShell - network.gaps[c], 0.0);
    }
    return {std::move(backbone), std::move(forces)};
}

} // namespace

PackingJamming testJammingCategories(const Packing& packing, const JammingSettings& settings,
                                     const ContactParameters& contacts,
                                     const JammingObserver& observer) {
    const auto start = std::chrono::steady_clock::now();
    const JammingTest test(settings.test); // refuses bad parameters before any work
    if (settings.relax) validate(settings.relaxation);
    const bool finiteGap = settings.test.finiteGaps();
    if (finiteGap && !packing.shape().isSphere())
        throw std::invalid_argument(
            fmt::format("jamming: --jamming-unjam-distance is Donev et al.'s finite-gap test of "
                        "sphere packings; at {} it would linearise rotations of up to radians, "
                        "and unjams every packing of rotating particles (docs/jamming.md §4.1)",
                        packing.shapeSpec.describe()));
    if (settings.relax && packing.isMixture())
        throw std::invalid_argument("jamming: --jamming-relax reads one size; a mixture's "
                                    "nearest jammed packing is not computed yet "
                                    "(docs/mixtures.md)");
    if (finiteGap && settings.relax)
        throw std::invalid_argument(
            "jamming: --jamming-unjam-distance tests the packing as given, with its gaps; "
            "--jamming-relax tests the nearest jammed packing, without gaps: give one");
    PackingJamming out;
    RigidityNetwork backbone;
    std::optional<Eigen::VectorXd> forces;
    if (settings.relax)
        out.relaxation =
            findJammingPoint(packing, settings.relaxation, observer.relaxing, observer.minimised);
    if (out.relaxation && out.relaxation->found) {
        std::tie(backbone, forces) = relaxedNetwork(*out.relaxation, contacts, out);
    } else if (finiteGap) {
        backbone = neighbourNetwork(packing, settings, contacts, out);
    } else {
        std::tie(out.tolerance, out.toleranceFrom) = networkTolerance(packing, settings, contacts);
        const ContactResult network =
            ContactNetwork({out.tolerance, contacts.rattlerThreshold}).compute(packing);
        backbone = backboneNetwork(packing, network);
        forces = storedForces(packing, backbone);
    }
    out.particles = static_cast<int>(packing.size());
    out.backbone = static_cast<int>(backbone.backbone.size());
    out.contacts = static_cast<int>(backbone.contacts.size());
    for (JammingCategory category : settings.categories) {
        if (backbone.backbone.empty()) break;
        if (observer.before) observer.before(category);
        const auto collective =
            std::find_if(out.tests.begin(), out.tests.end(), [](const JammingResult& t) {
                return t.category == JammingCategory::Collective && t.opensEveryContact;
            });
        out.tests.push_back(category == JammingCategory::Strict && collective != out.tests.end()
                                ? JammingTest::strictFromCollective(*collective, backbone)
                                : test.compute(backbone, category, forces));
        if (observer.after) observer.after(out.tests.back());
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace sbpack

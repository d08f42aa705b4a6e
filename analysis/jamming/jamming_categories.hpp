#pragma once
// The jamming analysis of one packing (docs/jamming.md): the backbone's contact network at the
// jam check's tolerance, then the first-order tests of the categories asked for (common/jamming),
// and the category reached. Shared by the stage `jamming` (pipeline/stages/jamming_stage.cpp) and
// `sbanalyze info --jamming` (info/packing_info.cpp).

#include "contacts/contact_network.hpp"
#include "jamming/jamming_test.hpp"
#include "jamming/soft_relaxation.hpp"
#include "packing/packing.hpp"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sbpack {

/// The finite-gap test's network where --jamming-tolerance is not given: every pair within
/// 0.25 D, the lower end of Donev et al. 2004's 0.25-0.5 D (docs/jamming.md §4.1).
inline constexpr double kFiniteGapTolerance = 0.25;

/// The jamming analysis's parameters (--jamming-categories, --jamming-tolerance,
/// --jamming-max-step, --jamming-contacts, --jamming-unjam-distance), its defaults written here
/// once.
struct JammingSettings {
    /// The categories tested, in ascending order. All three by default: the analysis answers
    /// "which category?", and an opt-in analysis (not in --compute all) may take the minutes that
    /// the coupled programs need at N = 5000 (docs/jamming.md §3); local alone costs seconds.
    std::vector<JammingCategory> categories{JammingCategory::Local, JammingCategory::Collective,
                                            JammingCategory::Strict};
    /// The network's contact tolerance in units of D; unset: the jam check's,
    /// max(1e-10, 100 / P) D at the file's reduced pressure P (docs/jamming.md §2), or the contact
    /// analysis's --tolerance where the file has none; the finite-gap test's: kFiniteGapTolerance.
    std::optional<double> tolerance;
    /// maxStep (Delta, units of D) and useGaps (ideal contacts, as Donev et al. 2004, or gaps);
    /// their defaults are the jamming test's own (docs/jamming.md §3-4).
    JammingParameters test;
    /// --jamming-relax: test the nearest jammed packing instead (docs/jamming.md §6.7): the
    /// network of the relaxed packing at its jamming shell, with the relaxation's forces.
    bool relax = false;
    RelaxationParameters relaxation;
};

/// "local", "collective", "strict": the names of the options and of the results groups.
std::string_view jammingCategoryName(JammingCategory category);
/// "local,strict" -> {Local, Strict}, sorted and each once; throws std::invalid_argument naming
/// `option` for an unknown or empty name.
std::vector<JammingCategory> parseJammingCategories(std::string_view option, std::string_view list);
/// The names of `categories`, comma-separated.
std::string jammingCategoryNames(const std::vector<JammingCategory>& categories);
/// "jammed", "unjammed", "undecided".
std::string_view firstOrderVerdictName(FirstOrderVerdict verdict);
/// "jammed", "unjammed", "unconverged": a relaxation's minimisation (docs/jamming.md §6.7).
std::string_view softVerdictName(SoftVerdict verdict);
/// "jammed", "not jammed", "no self-stress", "singular curvature" (docs/jamming.md §6).
std::string_view secondOrderVerdictName(SecondOrderVerdict verdict);
/// One line of a category's test: "undecided; second order: no self-stress (2041 floppy modes)".
std::string categoryDetail(const JammingResult& result);

/// What the jamming analysis found on one packing.
struct PackingJamming {
    double tolerance = 0.0;    ///< the network's contact tolerance, units of D
    std::string toleranceFrom; ///< "jam check at P = 1e+12", "--jamming-tolerance", "--tolerance"
    int particles = 0;         ///< N
    int backbone = 0;          ///< particles that are not rattlers
    int contacts = 0;          ///< contacts among the backbone
    /// One first-order test per category asked, ascending; empty where there is no backbone.
    std::vector<JammingResult> tests;
    /// --jamming-relax: the jamming point; the tests are of its relaxed packing where found.
    std::optional<JammingPoint> relaxation;
    double seconds = 0.0; ///< the network and every test

    /// The highest category tested that is jammed, at first order or, where first order is
    /// undecided, at second (JammingResult::jammed; a jammed category implies those below it);
    /// nullopt where none is.
    std::optional<JammingCategory> reached() const;
    /// "strict", "collective", "local" or "none" (reached()).
    std::string_view reachedName() const;
    /// The names of the tested categories whose first-order verdict is `verdict`.
    std::vector<std::string_view> tested(FirstOrderVerdict verdict) const;
    /// The tested categories undecided at first order and not jammed at second (not run, or
    /// without a verdict: no self-stress), comma-separated; "" for none.
    std::string undecided() const;
    /// The same categories, by name.
    std::vector<std::string_view> open() const;
    /// One line: "strictly jammed at first order", "locally jammed, not collectively (first
    /// order)", "undecided at first order: local, collective (second order pending)", ...
    std::string verdict() const;
    /// With --jamming-relax, one line: "relaxed to the nearest jammed packing: jamming shell in
    /// (1.56e-04, 1.63e-04] D, particles moved <= 0.0497 D, turned <= 0.512 rad" or "no
    /// jammed minimum up to a shell of 0.01 D (4 of 9 minimisations unconverged)"; "" without.
    std::string relaxationSummary() const;
};

/// Called before each category's test (it may throw to stop the analysis: an interrupt) and
/// after it, with its result (a progress line).
struct JammingObserver {
    std::function<void(JammingCategory)> before;
    std::function<void(const JammingResult&)> after;
    /// Before every step of the relaxation (--jamming-relax): it may throw, as `before`.
    RelaxationPoll relaxing;
    /// After each of its minimisations, with it (a progress line).
    RelaxationReport minimised;
};

/// Tests `settings.categories` on `packing`'s backbone; the network's rattlers by `contacts`
/// (its rattler threshold; its tolerance where the file has no reduced pressure and
/// settings.tolerance is unset).
PackingJamming testJammingCategories(const Packing& packing, const JammingSettings& settings,
                                     const ContactParameters& contacts,
                                     const JammingObserver& observer = {});

} // namespace sbpack

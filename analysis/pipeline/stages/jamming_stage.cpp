// jamming: the jamming categories of the packing's backbone at first order (common/jamming,
// docs/jamming.md): the category reached, and per category tested its verdict and motions.
#include "jamming/jamming_fields.hpp"
#include "pipeline/ensemble.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"

#include <fmt/format.h>

#include <array>
#include <string>

namespace sbpack::stages {

namespace {

/// Members of `name`'s group whose `field` is each of `values`, in the ensemble's group as the
/// fields `counts` (Reduce::Pooled).
template <std::size_t K>
void countValues(EnsembleResults& ensemble, std::span<const FileResults> files,
                 std::string_view name, std::string_view field,
                 const std::array<std::string_view, K>& values,
                 const std::array<std::string_view, K>& counts) {
    schema::Record* group = ensemble.group(name);
    if (group == nullptr) return;
    std::array<std::int64_t, K> n{};
    for (std::size_t m : ensemble.members)
        if (const schema::Record* r = files[m].group(name))
            for (std::size_t k = 0; k < K; ++k)
                n[k] += r->text(field) == values[k] ? 1 : 0;
    for (std::size_t k = 0; k < K; ++k)
        group->set(counts[k], n[k]);
}

} // namespace

bool runJamming(FileContext& context, schema::Record& record) {
    const Progress& progress = context.progress();
    const JammingObserver observer{
        [&](JammingCategory) { progress.checkInterrupt(); },
        [&](const JammingResult& r) {
            progress.stageDone("jamming " + std::string(jammingCategoryName(r.category)), r.seconds,
                               categoryDetail(r));
        },
        [&] { progress.checkInterrupt(); },
        [&](const SoftMinimum& m) {
            progress.stageDone(fmt::format("jamming relaxation at {:.3g} D", m.shell), m.seconds,
                               fmt::format("{} after {} steps, {} contacts, mean force {:.3g} D",
                                           softVerdictName(m.verdict), m.iterations, m.contacts,
                                           m.meanForce));
        }};
    const PackingJamming jamming = testJammingCategories(
        context.packing(), context.settings().jamming, context.settings().contacts, observer);
    if (jamming.tests.empty()) {
        progress.warn(fmt::format("jamming: skipped: every particle is a rattler at contact gap < "
                                  "{:.3g} D ({}): no backbone to test",
                                  jamming.tolerance, jamming.toleranceFrom));
        return false;
    }
    if (jamming.relaxation)
        progress.stageDone("jamming relaxation", jamming.relaxation->seconds,
                           jamming.relaxationSummary());
    progress.stageDone("jamming", jamming.seconds,
                       fmt::format("{} ({} of {} particles, {} contacts at gap < {:.3g} D)",
                                   jamming.verdict(), jamming.backbone, jamming.particles,
                                   jamming.contacts, jamming.tolerance));
    jamming_fields::kTable.fill(record, jamming, context.scales());
    for (const JammingResult& test : jamming.tests) {
        schema::Record category(jammingCategoryGroup(test.category));
        jamming_fields::kCategoryTable.fill(category, test, context.scales());
        context.addGroup(std::move(category));
    }
    return true;
}

void countJammingCategories(EnsembleResults& ensemble, std::span<const FileResults> files) {
    countValues<4>(ensemble, files, kJammingGroup.name, "category",
                   {"strict", "collective", "local", "none"},
                   {"n_strict", "n_collective", "n_local", "n_none"});
    schema::Record* group = ensemble.group(kJammingGroup.name);
    std::int64_t undecided = 0;
    for (std::size_t m : ensemble.members)
        if (const schema::Record* r = files[m].group(kJammingGroup.name))
            undecided += r->text("undecided").empty() ? 0 : 1;
    group->set("n_undecided", undecided);
    for (const schema::Group* g :
         {&kJammingLocalGroup, &kJammingCollectiveGroup, &kJammingStrictGroup})
        countValues<3>(ensemble, files, g->name, "verdict", {"jammed", "unjammed", "undecided"},
                       {"n_jammed", "n_unjammed", "n_undecided"});
}

} // namespace sbpack::stages

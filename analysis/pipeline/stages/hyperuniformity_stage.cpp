// hyper: the excess spreadability, alpha, the small-Q fit and H of one file
// (docs/hyperuniformity.md), from the voxel spectrum chi kept, with chi_V exact at Q w <=
// --chi-exact-qmax.
#include "hyperuniformity/debye_medium.hpp"
#include "hyperuniformity/hyperuniformity_fields.hpp"
#include "pipeline/ensemble.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace sbpack::stages {

namespace {

/// A results group of hyper, filled from the recorded figures.
template <class Table>
schema::Record hyperRecord(const schema::Group& group, const Table& table,
                           const HyperuniformityFigures& figures, const schema::Scales& scales) {
    schema::Record r(group);
    table.fill(r, figures, scales);
    return r;
}

} // namespace

bool runHyperuniformity(FileContext& context, schema::Record& record) {
    const Stopwatch clock;
    const KeptSpectrum& kept = context.kept<KeptSpectrum>(Analysis::SpectralDensity);
    const DiscreteSpectrum spectrum = spectrumOf(context, kept.spectrum);
    HyperuniformityResult h;
    try {
        h = Hyperuniformity(context.settings().hyperuniformity)
                .compute(std::span(&spectrum, 1), kept.peak);
    } catch (const std::domain_error& e) {
        // No long-time regime or too few wave vectors in this box: no groups, a warning.
        context.progress().warn(std::string("hyperuniformity skipped: ") + e.what());
        return false;
    }
    context.progress().stageDone(
        "hyperuniformity", clock.seconds(),
        fmt::format(
            "alpha = {} +- {} (window ends: {} .. {}; window mean {}; t D_diff / w^2 in [{}, "
            "{}], {}), H = {} +- {} (a0 = {} w^3, chi_peak = {} w^3 at Q w = {})",
            describe(h.alpha.alpha, 3), describe(h.alpha.standardError, 2),
            describe(h.alpha.endLow, 3), describe(h.alpha.endHigh, 3),
            describe(h.alpha.windowMean, 3), describe(h.window.tMin, 3), describe(h.window.tMax, 3),
            spectrum.source, describe(h.h, 3), describe(h.fit.a0Error / h.peak.chi, 2),
            describe(h.fit.a0, 3), describe(h.peak.chi, 4), describe(h.peak.qw, 3)));
    const HyperuniformityFigures figures{std::move(h), spectrum.source, spectrum.phi,
                                         context.settings().hyperuniformity.chiExactQw,
                                         clock.seconds()};
    hyperuniformity_fields::kSpreadability.fill(record, figures, context.scales());
    context.addGroup(hyperRecord(kHyperuniformityGroup, hyperuniformity_fields::kHyperuniformity,
                                 figures, context.scales()));
    context.addGroup(hyperRecord(kSpreadabilityDebyeGroup,
                                 hyperuniformity_fields::kSpreadabilityDebye, figures,
                                 context.scales()));
    return true;
}

namespace {

/// Every member's fitted wave vectors (fit_Q_w, fit_chi of its hyperuniformity group) together.
SmallQPoints pooledPoints(const EnsembleResults& e, std::span<const FileResults> files) {
    SmallQPoints all;
    for (std::size_t m : e.members)
        if (const schema::Record* h = files[m].group(kHyperuniformityGroup.name)) {
            const std::vector<double>& qw = h->floats("fit_Q_w");
            const std::vector<double>& chi = h->floats("fit_chi");
            all.qw.insert(all.qw.end(), qw.begin(), qw.end());
            all.chi.insert(all.chi.end(), chi.begin(), chi.end());
        }
    return all;
}

} // namespace

void poolHyperuniformity(EnsembleResults& e, std::span<const FileResults> files) {
    schema::Record& s = *e.group(kSpreadabilityGroup.name);
    const ExponentWindow window{s.number("t_fit_min"), s.number("t_fit_max")};
    const double alpha = sampledExponent(s.floats("t"), s.floats("excess"), window).alpha;
    s.set("alpha_pooled", alpha);
    // The members' wave vectors in one fit at the pooled alpha: the fit of the ensemble-mean
    // chi_V, which one member's near-degenerate fit (alpha near 0: a0 and a1 Q^alpha nearly
    // collinear) cannot dominate as it does the mean of the members' a0 (docs/hyperuniformity.md).
    schema::Record* h = e.group(kHyperuniformityGroup.name);
    if (!h) return;
    const PowerLawFit fit = fitFixedExponent(pooledPoints(e, files), alpha);
    const double peak = h->number("chi_peak");
    h->set("a0_pooled", fit.a0)
        .set("a0_pooled_stderr", fit.a0Error)
        .set("a1_pooled", fit.a1)
        .set("a1_pooled_stderr", fit.a1Error)
        .set("H_pooled", fit.a0 / peak)
        .set("H_pooled_stderr", fit.a0Error / peak);
}

} // namespace sbpack::stages

// hyper: the excess spreadability, alpha, the small-Q fit and H of one file
// (docs/hyperuniformity.md), from the voxel spectrum chi kept, with chi_V exact at Q w <=
// --chi-exact-qmax.
#include "hyperuniformity/debye_medium.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "spectral/exact_spectral_density.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace sbpack::stages {

namespace {

/// The voxel spectrum with the exact values at small Q (none when --chi-exact-qmax is 0).
DiscreteSpectrum spectrumOf(FileContext& context, const DiscreteSpectrum& voxel) {
    const double qmax = context.settings().chiExactQw;
    if (qmax == 0.0) return voxel;
    ExactSpectralDensityParameters parameters;
    parameters.maxQw = qmax;
    const ExactSpectralDensityResult exact =
        ExactSpectralDensity(parameters).compute(context.packing(), context.progress());
    context.progress().stageDone(
        "exact chi", exact.runtimeSeconds,
        fmt::format("{} wave vectors up to Q w = {}", 2 * exact.modes.size(), describe(qmax, 3)));
    return withExactSmallQ(voxel, exact);
}

void setSpreadability(schema::Record& r, const HyperuniformityResult& h, const DiscreteSpectrum& s,
                      double chiExactQw) {
    r.set("source", s.source)
        .set("chi_exact_qmax", chiExactQw)
        .set("phi", s.phi)
        .set("alpha", h.alpha.alpha)
        .set("alpha_stderr", h.alpha.standardError)
        .set("bootstrap_replicas", h.alpha.replicas)
        .set("alpha_window_low", h.alpha.windowLow)
        .set("alpha_window_high", h.alpha.windowHigh)
        .set("t_fit_min", h.window.tMin)
        .set("t_fit_max", h.window.tMax)
        .set("t_cutoff", h.cutoffTime)
        .set("runtime_s", h.runtimeSeconds)
        .set("t", h.t)
        .set("excess", h.excess)
        .set("local_exponent", h.localExponent)
        .set("local_alpha", h.localAlpha)
        .set("truncation_bound", h.truncation);
}

schema::Record hyperuniformityRecord(const HyperuniformityResult& h, double seconds) {
    schema::Record r(*schema::findAnalysisGroup("hyperuniformity"));
    r.set("alpha", h.fit.alpha)
        .set("a0", h.fit.a0)
        .set("a0_stderr", h.fit.a0Error)
        .set("a1", h.fit.a1)
        .set("a1_stderr", h.fit.a1Error)
        .set("fit_points", h.fit.points)
        .set("q_fit_max_w", h.parameters.fitQmaxW)
        .set("H", h.h)
        .set("H_stderr", h.fit.a0Error / h.peak.chi)
        .set("H_min", h.hSpread.hMin)
        .set("H_max", h.hSpread.hMax)
        .set("chi_peak", h.peak.chi)
        .set("q_peak_w", h.peak.qw)
        .set("alpha_free", h.freeFit.best.alpha)
        .set("a0_free", h.freeFit.best.a0)
        .set("alpha_free_low", h.freeFit.alphaLow)
        .set("alpha_free_high", h.freeFit.alphaHigh)
        .set("free_fit_degenerate", h.freeFit.degenerate)
        .set("runtime_s", seconds);
    return r;
}

schema::Record debyeRecord(const HyperuniformityResult& h, double phi) {
    schema::Record r(*schema::findAnalysisGroup("spreadability_debye"));
    r.set("phi", phi).set("t", h.t).set("excess", h.debyeExcess);
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
        fmt::format("alpha = {} +- {} (windows: {} .. {}; t D / w^2 in [{}, {}], {}), H = {} +- {} "
                    "(a0 = {} w^3)",
                    describe(h.alpha.alpha, 3), describe(h.alpha.standardError, 2),
                    describe(h.alpha.windowLow, 3), describe(h.alpha.windowHigh, 3),
                    describe(h.window.tMin, 3), describe(h.window.tMax, 3), spectrum.source,
                    describe(h.h, 3), describe(h.fit.a0Error / h.peak.chi, 2),
                    describe(h.fit.a0, 3)));
    setSpreadability(record, h, spectrum, context.settings().chiExactQw);
    context.addGroup(hyperuniformityRecord(h, clock.seconds()));
    context.addGroup(debyeRecord(h, spectrum.phi));
    return true;
}

void poolSpreadability(schema::Record& e) {
    const ExponentWindow window{e.number("t_fit_min"), e.number("t_fit_max")};
    e.set("alpha_pooled", sampledExponent(e.floats("t"), e.floats("excess"), window));
}

} // namespace sbpack::stages

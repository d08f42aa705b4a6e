#pragma once
// The results group of order, declared once (schema/field_table.hpp, docs/results-schema.md):
// the order metrics of common/order (docs/order-metrics.md).

#include "order/order_metrics.hpp"
#include "schema/field_table.hpp"

#include <optional>
#include <string>

namespace sbpack {

/// What the order group records.
struct OrderFigures {
    OrderMetrics metrics;
    OrderVerdict verdict;
    double majorAxis = 0.0; ///< D = 2 R, the second length unit of g2's distances
    double seconds = 0.0;
};

namespace order_fields {
using namespace schema::columns;
using R = OrderFigures;
using M = OrderMetrics;
using G = PairCorrelationResult;

/// A number of an optional part of the metrics (absent where the part is).
template <auto Part, class Read> Optional partOf(const R& r, Read read) {
    const auto& part = r.metrics.*Part;
    return part ? Optional(Value(read(*part))) : std::nullopt;
}

/// Q_l and the mean local q_l over one neighbour definition (`suffix` names it).
template <auto Part>
constexpr std::array<schema::Column<R>, 4>
bondColumns(std::string_view q4, std::string_view q6, std::string_view q4Local,
            std::string_view q6Local, std::string_view bonds) {
    return {{
        {{q4, A, F, "1", bonds, Mean, true},
         +[](const R& r, const Scales&) {
             return partOf<Part>(r, [](const BondOrder& b) { return b.q4.globalOrder; });
         }},
        {{q6, A, F, "1", bonds, Mean, true},
         +[](const R& r, const Scales&) {
             return partOf<Part>(r, [](const BondOrder& b) { return b.q6.globalOrder; });
         }},
        {{q4Local, A, F, "1", "mean over the bonded particles of the local q4(i), same bonds", Mean,
          true},
         +[](const R& r, const Scales&) {
             return partOf<Part>(r, [](const BondOrder& b) { return b.q4.meanLocalOrder; });
         }},
        {{q6Local, A, F, "1", "mean over the bonded particles of the local q6(i), same bonds", Mean,
          true},
         +[](const R& r, const Scales&) {
             return partOf<Part>(r, [](const BondOrder& b) { return b.q6.meanLocalOrder; });
         }},
    }};
}

inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 5>{{
        {{"ordered", A, I, "1",
          "1 if the metrics say the packing has ordered (docs/order-metrics.md §5), else 0"},
         member<&R::verdict, &OrderVerdict::ordered>},
        {{"ordered_reason", A, S, "", "why it is called ordered; \"\" when it is not"},
         member<&R::verdict, &OrderVerdict::reason>},
        {{"number_density_w3", A, F, "1", "rho w^3, rho = N / L^3"},
         member<&R::metrics, &M::pairCorrelation, &G::numberDensity>},
        {{"cutoff_w", A, F, "1",
          "first minimum of g2 after its main peak, r / w: the neighbour cutoff (absent where "
          "g2 has none within L / 2)",
          Mean, true},
         member<&R::metrics, &M::cutoff>},
        {{"g2_bin_width_w", A, F, "1", "bin width of g2, dr / w"},
         member<&R::metrics, &M::pairCorrelation, &G::parameters,
                &PairCorrelationParameters::binWidth>},
    }},
    bondColumns<&M::cutoffBonds>("Q4", "Q6", "q4_local_mean", "q6_local_mean",
                                 "Steinhardt Q_l (Eq. 2.1) over the bonds shorter than cutoff_w"),
    bondColumns<&M::contactBonds>(
        "Q4_contacts", "Q6_contacts", "q4_local_mean_contacts", "q6_local_mean_contacts",
        "Steinhardt Q_l over the contact network's bonds (gap < --tolerance D, rattlers included)"),
    std::array<schema::Column<R>, 8>{{
        {{"T", A, F, "1",
          "translational order T (Eq. 3.1): 0 ideal gas, 1 fcc, over T_shells fcc shells", Mean,
          true},
         +[](const R& r, const Scales&) {
             return partOf<&M::translational>(
                 r, [](const TranslationalOrderResult& t) { return t.order; });
         }},
        {{"T_ideal_gas_error", A, F, "1", "standard deviation of T for an ideal gas (Eq. 3.3)", No,
          true},
         +[](const R& r, const Scales&) {
             return partOf<&M::translational>(
                 r, [](const TranslationalOrderResult& t) { return t.idealGasError; });
         }},
        {{"T_shells", A, I, "1", "fcc shells of T: the first 12, or those within L / 2", No, true},
         +[](const R& r, const Scales&) {
             return partOf<&M::translational>(r, [](const TranslationalOrderResult& t) {
                 return static_cast<std::int64_t>(t.parameters.shellCount);
             });
         }},
        {{"P4", A, F, "1",
          "cubatic order of the particles' axes (Eq. 4.1): 1 aligned, 0 random; not for spheres",
          Mean, true},
         +[](const R& r, const Scales&) {
             return partOf<&M::cubatic>(r, [](const CubaticOrderResult& c) { return c.order; });
         }},
        {{"P4_random_error", A, F, "1",
          "standard deviation of P4 for random orientations, sqrt(2 / (9 N (N - 1))) (Eq. 4.4)", No,
          true},
         +[](const R& r, const Scales&) {
             return partOf<&M::cubatic>(
                 r, [](const CubaticOrderResult& c) { return c.randomOrientationError; });
         }},
        {{"runtime_s", A, F, "s", kRuntime}, member<&R::seconds>},
        {{"r_w", D, F, "1", "bin centres of g2, r / w"},
         member<&R::metrics, &M::pairCorrelation, &G::r>},
        {{"r_D", D, F, "1", "bin centres of g2, r / D (D = 2 semi_axis)"},
         +[](const R& r, const Scales& s) -> Optional {
             std::vector<double> x = r.metrics.pairCorrelation.r;
             for (double& v : x)
                 v *= s.meanWidth / r.majorAxis;
             return Value(std::move(x));
         }},
    }},
    std::array<schema::Column<R>, 4>{{
        {{"solid_like_fraction", A, F, "1",
          "fraction of the particles solid-like: enough crystal-like bonds among their SANN bonds "
          "(ten Wolde et al.; docs/order-metrics.md §5); absent where a SANN shell does not "
          "close within L / 2",
          Mean, true},
         +[](const R& r, const Scales&) {
             return partOf<&M::solidLike>(r,
                                          [](const SolidLikeResult& s) { return s.solidFraction; });
         }},
        {{"crystal_cluster", A, I, "1",
          "particles in the largest cluster of solid-like particles joined by crystal-like bonds",
          No, true},
         +[](const R& r, const Scales&) {
             return partOf<&M::solidLike>(r, [](const SolidLikeResult& s) {
                 return static_cast<std::int64_t>(s.largestClusterSize);
             });
         }},
        {{"crystal_cluster_fraction", A, F, "1",
          "the largest crystalline cluster over N, crystal_cluster / N", Mean, true},
         +[](const R& r, const Scales&) {
             return partOf<&M::solidLike>(
                 r, [](const SolidLikeResult& s) { return s.largestClusterFraction; });
         }},
        {{"sann_neighbours_mean", A, F, "1",
          "mean number of SANN bonds of a particle (van Meel et al. 2012; fcc 12, bcc 14, sc 18)",
          Mean, true},
         +[](const R& r, const Scales&) { // each bond counts at both ends
             return partOf<&M::solidLike>(r, [](const SolidLikeResult& s) {
                 return 2.0 * static_cast<double>(s.bondCorrelation.size()) /
                        static_cast<double>(s.neighbourCount.size());
             });
         }},
    }},
    std::array<schema::Column<R>, 4>{{
        {{"g2", D, F, "1",
          "pair correlation g2(r) of the centroids, 2 n_pairs / (N rho V_shell) (Eq. 1.1)"},
         member<&R::metrics, &M::pairCorrelation, &G::g2>},
        {{"g2_ideal_gas_error", D, F, "1",
          "standard deviation of g2 per bin for an ideal gas of the same N and rho (Eq. 1.2)"},
         member<&R::metrics, &M::pairCorrelation, &G::idealGasError>},
        {{"q6_local", D, F, "1", "local q6(i) per particle over the cutoff bonds (NaN: no bond)",
          No, true},
         +[](const R& r, const Scales&) -> Optional {
             const auto& b = r.metrics.cutoffBonds;
             return b ? Optional(Value(b->q6.localOrder)) : std::nullopt;
         }},
        {{"crystal_bonds", D, I, "1",
          "crystal-like bonds xi(i) of each particle among its SANN bonds (docs/order-metrics.md "
          "§5)",
          No, true},
         +[](const R& r, const Scales&) {
             return partOf<&M::solidLike>(r, [](const SolidLikeResult& s) {
                 return std::vector<std::int64_t>(s.crystalBonds.begin(), s.crystalBonds.end());
             });
         }},
    }})};
} // namespace order_fields

inline constexpr schema::Group kOrderGroup{
    "order", "files/<i>/order",
    "order metrics: g2, Q4 and Q6, T, the cubatic P4, the solid-like particles and the verdict "
    "(order; "
    "docs/order-metrics.md)",
    order_fields::kTable.fields()};

} // namespace sbpack

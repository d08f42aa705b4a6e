#pragma once
// The results group of contacts, declared once (schema/field_table.hpp, docs/results-schema.md):
// the contact network of common/contacts, whether its tolerance resolves the contacts, and where
// on the particles the contacts sit (docs/contact-types.md), and the distribution of the contact
// forces sbgen stored with the packing (docs/jamming.md §8).

#include "contacts/contact_network.hpp"
#include "contacts/contact_resolution.hpp"
#include "contacts/contact_types.hpp"
#include "packing/contact_forces.hpp"
#include "schema/field_table.hpp"

#include <limits>
#include <optional>

namespace sbpack {

/// What the contacts group records.
struct ContactFigures {
    ContactResult network;
    ContactResolution resolution;
    ContactTypeDistribution types{}; ///< of the contacts among the non-rattlers
    /// P(f / <f>) of sbgen's stored contact forces, where the packing has them.
    std::optional<ForceDistribution> forces{};
    double seconds = 0.0;

    /// Z and phi_R are undetermined when the tolerance cuts through the load-bearing gaps
    /// (docs/design.md §3, "Honest contacts"): NaN, and the gap distribution instead.
    bool undetermined() const { return !resolution.resolved.value_or(true); }
};

namespace contacts_fields {
using namespace schema::columns;
using R = ContactFigures;
using N = ContactResult;
using T = ContactTypeDistribution;

/// `value` where the contacts are resolved, NaN where they are not.
inline Value unlessUndetermined(const R& r, double value) {
    return Value(r.undetermined() ? std::numeric_limits<double>::quiet_NaN() : value);
}

/// Fraction K of the contact types' `Fractions`: NaN if not resolved, or without contacts.
template <auto Fractions, std::size_t K> Optional typeFraction(const R& r, const Scales&) {
    return unlessUndetermined(r, (r.types.*Fractions)[K]);
}
inline constexpr auto kRegion = &T::regionFractions;
inline constexpr auto kPair = &T::pairTypeFractions;

/// Where on the particles the contacts sit (docs/contact-types.md): regions, pair types, theta.
inline constexpr std::array<schema::Column<R>, 13> kTypeColumns{{
    {{"axis_fraction", A, F, "1",
      "fraction of the contact ends (non-rattlers) whose body-frame normal is nearest a <100> "
      "body axis: the cube's face (p > 1), the octahedron's vertex (p < 1) "
      "(docs/contact-types.md; NaN if not resolved, if no contact joins two non-rattlers, or for "
      "a shape without the cube's symmetry)",
      Mean},
     typeFraction<kRegion, 0>},
    {{"edge_fraction", A, F, "1", "the same, nearest a <110> direction: an edge", Mean},
     typeFraction<kRegion, 1>},
    {{"diagonal_fraction", A, F, "1",
      "the same, nearest a <111> direction: the cube's vertex, the octahedron's face", Mean},
     typeFraction<kRegion, 2>},
    {{"axis_axis_fraction", A, F, "1",
      "fraction of the contacts (non-rattlers) whose two ends are both axis ends", Mean},
     typeFraction<kPair, 0>},
    {{"axis_edge_fraction", A, F, "1", "the same, one axis end and one edge end", Mean},
     typeFraction<kPair, 1>},
    {{"axis_diagonal_fraction", A, F, "1", "the same, axis and diagonal", Mean},
     typeFraction<kPair, 2>},
    {{"edge_edge_fraction", A, F, "1", "the same, edge and edge", Mean}, typeFraction<kPair, 3>},
    {{"edge_diagonal_fraction", A, F, "1", "the same, edge and diagonal", Mean},
     typeFraction<kPair, 4>},
    {{"diagonal_diagonal_fraction", A, F, "1", "the same, diagonal and diagonal", Mean},
     typeFraction<kPair, 5>},
    {{"axis_angle_mean", A, F, "deg",
      "mean over the contact ends of theta, the angle of the body-frame normal to the nearest "
      "body axis, arccos max_k |n_k| (NaN as the fractions)",
      Mean},
     +[](const R& r, const Scales&) -> Optional {
         return unlessUndetermined(r, r.types.meanAxisAngleDegrees);
     }},
    {{"axis_angle_edges", D, F, "deg",
      "edges of the equal bins of theta over [0, arccos(1 / sqrt 3)] = [0, 54.74 deg]", Same},
     member<&R::types, &T::axisAngleEdges>},
    {{"axis_angle_density", D, F, "1/deg",
      "probability density of theta over the contact ends, per bin (NaN as the fractions)",
      Pointwise},
     +[](const R& r, const Scales&) -> Optional {
         std::vector<double> density = r.types.axisAngleDensity;
         if (r.undetermined())
             density.assign(density.size(), std::numeric_limits<double>::quiet_NaN());
         return Value(std::move(density));
     }},
    {{"axis_angle_uniform", D, F, "1/deg",
      "the density of theta for normals uniform on the sphere, in the same bins (the sphere's, "
      "docs/contact-types.md Eq. 2.2)",
      Same},
     member<&R::types, &T::uniformAngleDensity>},
}};

/// A member of the stored forces' distribution, where the packing has them.
template <auto Member> Optional forceField(const R& r, const Scales&) {
    if (!r.forces) return std::nullopt;
    return Value((*r.forces).*Member);
}
using FD = ForceDistribution;

/// The distribution of sbgen's stored contact forces (docs/jamming.md §8), optional: packings
/// from elsewhere have none.
inline constexpr std::array<schema::Column<R>, 6> kForceColumns{{
    {{"force_count", A, I, "1",
      "contacts with a force stored by sbgen (the packing's contact_forces; only where it has "
      "them)",
      Mean, true},
     forceField<&FD::count>},
    {{"force_mean", A, F, "kT/D", "mean stored contact force <f> (only with stored forces)", Mean,
      true},
     forceField<&FD::mean>},
    {{"force_second_moment", A, F, "1",
      "<x^2> of x = f / <f> over the stored forces (<x> = 1; 2 for an exponential P(x))", Mean,
      true},
     forceField<&FD::secondMoment>},
    {{"force_tail_fraction", A, F, "1",
      "fraction of the stored forces with f / <f> >= the last force edge (only with stored "
      "forces)",
      Mean, true},
     forceField<&FD::tailFraction>},
    {{"force_edges", D, F, "1", "edges of the equal bins of x = f / <f> over [0, 4]", Same, true},
     forceField<&FD::edges>},
    {{"force_density", D, F, "1",
      "probability density P(x) of x = f / <f> per bin over the stored forces (it integrates "
      "to 1 - force_tail_fraction)",
      Pointwise, true},
     forceField<&FD::density>},
}};

inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 13>{{
        {{"z_mean", A, F, "1", "mean contact number Z over the non-rattlers (NaN if not resolved)",
          Mean},
         +[](const R& r, const Scales&) -> Optional {
             return unlessUndetermined(r, r.network.meanContactNumber);
         }},
        {{"rattler_fraction", A, F, "1", "fraction of rattlers phi_R (NaN if not resolved)", Mean},
         +[](const R& r, const Scales&) -> Optional {
             return unlessUndetermined(r, r.network.rattlerFraction);
         }},
        {{"tolerance", A, F, "D", "contact: gap < tolerance D (--tolerance)"},
         member<&R::network, &N::parameters, &ContactParameters::tolerance>},
        {{"resolved", A, I, "1",
          "1 if tolerance >= tolerance_needed (contacts separated), 0 if not, -1 without a "
          "pressure"},
         +[](const R& r, const Scales&) -> Optional {
             const std::optional<bool> resolved = r.resolution.resolved;
             return Value(resolved ? std::int64_t{*resolved} : std::int64_t{-1});
         }},
        {{"tolerance_needed", A, F, "D", "100 / P: load-bearing gaps at the reduced pressure P"},
         member<&R::resolution, &ContactResolution::neededTolerance>},
        {{"rattler_threshold", A, I, "1", "rattler: fewer contacts, removed iteratively"},
         member<&R::network, &N::parameters, &ContactParameters::rattlerThreshold>},
        {{"n_contacts", A, I, "1", "contacts (pairs)"},
         +[](const R& r, const Scales&)
             -> Optional { return Value(static_cast<std::int64_t>(r.network.contacts.size())); }},
        {{"overlapping_pairs", A, I, "1", "pairs that overlap"},
         member<&R::network, &N::overlappingPairs>},
        {{"runtime_s", A, F, "s", kRuntime}, member<&R::seconds>},
        {{"counts", D, I, "1", "contacts of each particle"}, member<&R::network, &N::counts>},
        {{"rattler", D, I, "1", "1 for a rattler, else 0, per particle"},
         member<&R::network, &N::rattler>},
        {{"gap_edges", D, F, "D", "if not resolved: decade edges of gap / D, 1e-16 .. 1e-2", No,
          true},
         +[](const R& r, const Scales&) -> Optional {
             return r.resolution.gaps ? Optional(r.resolution.gaps->edges) : std::nullopt;
         }},
        {{"gap_counts", D, I, "1",
          "if not resolved: pairs per decade (the first bin holds every gap below 1e-15 D)", No,
          true},
         +[](const R& r, const Scales&) -> Optional {
             if (!r.resolution.gaps) return std::nullopt;
             const auto& counts = r.resolution.gaps->counts;
             return Value(std::vector<std::int64_t>(counts.begin(), counts.end()));
         }},
    }},
    kTypeColumns, kForceColumns)};
} // namespace contacts_fields

inline constexpr schema::Group kContactsGroup{"contacts", "files/<i>/contacts",
                                              "contact network (contacts)",
                                              contacts_fields::kTable.fields()};

} // namespace sbpack

#pragma once
// The results group of contacts, declared once (schema/field_table.hpp, docs/results-schema.md):
// the contact network of common/contacts and whether its tolerance resolves the contacts.

#include "contacts/contact_network.hpp"
#include "contacts/contact_resolution.hpp"
#include "schema/field_table.hpp"

#include <limits>

namespace sbpack {

/// What the contacts group records.
struct ContactFigures {
    ContactResult network;
    ContactResolution resolution;
    double seconds = 0.0;

    /// Z and phi_R are undetermined when the tolerance cuts through the load-bearing gaps
    /// (docs/design.md §3, "Honest contacts"): NaN, and the gap distribution instead.
    bool undetermined() const { return !resolution.resolved.value_or(true); }
};

namespace contacts_fields {
using namespace schema::columns;
using R = ContactFigures;
using N = ContactResult;

/// `value` where the contacts are resolved, NaN where they are not.
inline Value unlessUndetermined(const R& r, double value) {
    return Value(r.undetermined() ? std::numeric_limits<double>::quiet_NaN() : value);
}

inline constexpr schema::FieldTable kTable{std::array<schema::Column<R>, 13>{{
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
      "1 if tolerance >= tolerance_needed (contacts separated), 0 if not, -1 without a pressure"},
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
    {{"gap_edges", D, F, "D", "if not resolved: decade edges of gap / D, 1e-16 .. 1e-2", No, true},
     +[](const R& r, const Scales&) -> Optional {
         return r.resolution.gaps ? Optional(r.resolution.gaps->edges) : std::nullopt;
     }},
    {{"gap_counts", D, I, "1",
      "if not resolved: pairs per decade (the first bin holds every gap below 1e-15 D)", No, true},
     +[](const R& r, const Scales&) -> Optional {
         if (!r.resolution.gaps) return std::nullopt;
         const auto& counts = r.resolution.gaps->counts;
         return Value(std::vector<std::int64_t>(counts.begin(), counts.end()));
     }},
}}};
} // namespace contacts_fields

inline constexpr schema::Group kContactsGroup{"contacts", "files/<i>/contacts",
                                              "contact network (contacts)",
                                              contacts_fields::kTable.fields()};

} // namespace sbpack

#pragma once
// `sbanalyze info`: validation and a one-screen summary of a stored packing.

#include "contacts/contact_network.hpp"
#include "contacts/contact_resolution.hpp"
#include "contacts/jam_check.hpp"
#include "jamming/jamming_categories.hpp"
#include "order/order_metrics.hpp"
#include "packing/packing.hpp"

#include <filesystem>
#include <iosfwd>
#include <optional>

namespace sbpack {

struct PackingInfo {
    Packing packing;
    double meanWidth;
    /// Packing::analysisLengthUnit: the contacts, jam check and order are of the packing in it.
    double lengthUnit;
    ContactResult contacts; ///< Z, phi_R and the worst overlap
    /// Whether the tolerance separates the contacts at the file's pressure (else no Z).
    ContactResolution resolution;
    /// sbgen's jam check at the file's reduced pressure (docs/design.md §3, "Jam check");
    /// absent when the file has no reduced pressure.
    std::optional<JamCheck> jam;
    /// The order metrics over the contact network and whether the packing has ordered
    /// (docs/order-metrics.md §5).
    OrderMetrics order;
    OrderVerdict verdict;
    /// The jamming categories (info --jamming; docs/jamming.md); absent without.
    std::optional<PackingJamming> jamming;
};

/// Reads and validates FILE (throws with its name on bad input), then analyses contacts and,
/// given `jamming`, tests the jamming categories.
PackingInfo packingInfo(const std::filesystem::path& file, const ContactParameters& parameters,
                        const JammingSettings* jamming = nullptr);

/// Human-readable report; overlaps are a warning naming the worst pair and its depth.
void printPackingInfo(const std::filesystem::path& file, const PackingInfo& info,
                      std::ostream& out);

} // namespace sbpack

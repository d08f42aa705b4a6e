#pragma once
// `sbanalyze info`: validation and a one-screen summary of a stored packing.

#include "contacts/contact_network.hpp"
#include "packing/packing.hpp"

#include <filesystem>
#include <iosfwd>

namespace sbpack {

struct PackingInfo {
    Packing packing;
    double meanWidth;
    ContactResult contacts; ///< Z, phi_R and the worst overlap
};

/// Reads and validates FILE (throws with its name on bad input), then analyses contacts.
PackingInfo packingInfo(const std::filesystem::path& file, const ContactParameters& parameters);

/// Human-readable report; overlaps are a warning naming the worst pair and its depth.
void printPackingInfo(const std::filesystem::path& file, const PackingInfo& info,
                      std::ostream& out);

} // namespace sbpack

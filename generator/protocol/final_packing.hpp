#pragma once
// What sbgen writes at the end of a run (README, "Output"), shared with the Python module's
// sbpack.generate (docs/python.md).

#include "packing/packing.hpp"
#include "protocol/jamming_protocol.hpp"

namespace sbpack {

/// The finished protocol's checkpoint with the contact analysis of common/ (at the jam check's
/// tolerance max(1e-10, 100 / P) D) and the jam check in its provenance, and the contact forces
/// of its recorded windows where it has any (JammingProtocol::forceWindows). Needs a run that
/// finished (run() returned true: Phase::Done or the cost limit).
Packing finalPacking(const JammingProtocol& protocol);

} // namespace sbpack

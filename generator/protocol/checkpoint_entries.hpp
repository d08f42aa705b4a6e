#pragma once
// sbgen's checkpoint, declared once (docs/design.md §4): every entry sbgen writes into a packing
// file's `provenance` and `resume_state` groups, how it is written from a run and read back into
// one, and what a file written before the entry existed means. JammingProtocol::checkpoint()
// writes this table and the resume constructor reads it; no other code names a key.

#include "engine/growth_clock.hpp"
#include "packing/packing.hpp"
#include "protocol/jamming_protocol.hpp"

#include <string>
#include <vector>

namespace sbpack {

/// What a checkpoint holds of a run besides its particles.
struct CheckpointFields {
    ProtocolParameters parameters;
    ProtocolStatus status;
    GrowthClock clock;
    /// The engine's pair records as a checkpoint's rows (shapes/registry: pairRecordRows; none
    /// for spheres), read into the engine, and checked there, by restorePairRecords.
    std::vector<double> pairRecords;
};

/// The checkpoint's format name, resume_state/format (a reader refuses any other).
inline constexpr const char* kCheckpointFormat = "sbgen.state/1";

/// One entry as the docs and tests see it.
struct CheckpointKey {
    std::string group; ///< "provenance" or "resume_state"
    std::string key;
    /// Read back on resume; else written for the reader only (derived, e.g. "events").
    bool read = true;
    /// Absent from files of earlier versions (then the field keeps its default).
    bool optional = false;
};

/// Every entry of the table, in the order written.
std::vector<CheckpointKey> checkpointKeys();

/// Writes every entry of the run's fields into packing.provenance and packing.resumeState, and
/// the pair records into packing.pairRecords.
void writeCheckpoint(const CheckpointFields& fields, Packing& packing);

/// The run's fields from a checkpoint, everything validated before a protocol exists: every
/// entry the table reads, of its type and present unless optional, the format, the phase and
/// the counters; the parameters (the packing's size and p) as a fresh run's; the growth clock
/// positive and agreeing with the packing's semi_axis (the pair records are the engine's to
/// check: restorePairRecords). Throws std::invalid_argument naming `source` and the entry.
CheckpointFields readCheckpoint(const Packing& packing, const std::string& source);

} // namespace sbpack

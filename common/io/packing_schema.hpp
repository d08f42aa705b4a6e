#pragma once
// The packing file, declared once (docs/design.md §4, docs/packing-schema.md): every attribute,
// dataset and group of the HDF5 packing file that sbgen, `sbanalyze convert` and Python write
// (io/packing_io.cpp) and every tool reads, with its type, units, description, whether a file
// may lack it and the format_version that introduced it; and the names an earlier file used, as
// migration rows that the reader applies. io/packing_io.cpp reads and writes by the names below;
// `sbanalyze schema --packing` prints the table (analysis/schema/packing_schema_docs.cpp). The
// entries sbgen keeps in `provenance` and `resume_state` are declared in its own table,
// generator/protocol/checkpoint_entries.

#include "geometry/particle_shape.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace sbpack {

inline constexpr const char* kPackingFormat = "sbpack.packing";
inline constexpr std::int64_t kPackingFormatVersion = 1;

/// The names of the packing file's entries, as they are in the file.
namespace packing_file {
inline constexpr const char* kFormat = "format";
inline constexpr const char* kFormatVersion = "format_version";
/// The shape family's name (ShapeSpec::info); absent: superball. The family's parameters follow
/// under their own names (ShapeParameter::name, e.g. "p").
inline constexpr const char* kShape = kShapeFamilyKey;
inline constexpr const char* kBoxLength = "box_length";
inline constexpr const char* kSemiAxis = "semi_axis";
inline constexpr const char* kParticles = "n_particles";
inline constexpr const char* kPhi = "phi";
inline constexpr const char* kReducedPressure = "reduced_pressure";
inline constexpr const char* kSeed = "seed";
inline constexpr const char* kGeneratorVersion = "generator_version";
inline constexpr const char* kPositions = "positions";
inline constexpr const char* kOrientations = "orientations";
inline constexpr const char* kSemiAxes = "semi_axes";
inline constexpr const char* kVelocities = "velocities";
inline constexpr const char* kAngularVelocities = "angular_velocities";
inline constexpr const char* kProvenance = "provenance";
inline constexpr const char* kResumeState = "resume_state";
/// In resume_state: the attribute that counts the rows, and the dataset of the pair records.
inline constexpr const char* kPairRecords = "pair_records";
/// sbgen's contact forces: the group, its attributes (with kReducedPressure), the attribute
/// that counts the contacts, the datasets, and each dataset's units attribute.
inline constexpr const char* kContactForces = "contact_forces";
inline constexpr const char* kWindows = "windows";
inline constexpr const char* kDuration = "duration";
inline constexpr const char* kContacts = "contacts";
inline constexpr const char* kPairs = "pairs";
inline constexpr const char* kPoints = "points";
inline constexpr const char* kNormals = "normals";
inline constexpr const char* kForces = "forces";
inline constexpr const char* kNetForces = "net_forces";
inline constexpr const char* kNetTorques = "net_torques";
inline constexpr const char* kUnits = "units";
} // namespace packing_file

enum class PackingKind { Attribute, Dataset, Group };
enum class PackingType { Float64, Int64, UInt64, String, None };

struct PackingEntry {
    std::string_view group = {}; ///< "" at the root, else the group the entry is in
    std::string_view name = {};
    PackingKind kind = PackingKind::Attribute;
    PackingType type = PackingType::None; ///< a dataset's element type; None for a group
    /// "1" dimensionless, "length" (the packing's), "time", "length/time" and "1/time" (sbgen's
    /// time, docs/design.md §3), "kT/D" and "kT" (the contact forces, docs/jamming.md); "" for
    /// strings and groups.
    std::string_view units = {};
    std::string_view description = {};
    bool optional = false;      ///< a file may lack it (said in the description when)
    std::int64_t since = 1;     ///< the format_version that introduced it
    std::string_view rows = {}; ///< a dataset's rows: "N" or the attribute that counts them
    std::size_t columns = 0;    ///< a dataset's columns
};

/// A name an earlier file used, read as today's: in a file of format_version `version` that has
/// no group `toGroup`, the attributes of group `fromGroup` named `fromPrefix` + NAME are moved
/// into `toGroup` as NAME.
struct PackingMigration {
    std::int64_t version;
    std::string_view fromGroup;
    std::string_view fromPrefix;
    std::string_view toGroup;
    std::string_view description;
};

/// Every entry, in the order the writer writes them.
std::span<const PackingEntry> packingEntries();
/// Every migration row, oldest first.
std::span<const PackingMigration> packingMigrations();

} // namespace sbpack

#include "io/packing_schema.hpp"

#include "geometry/particle_shape.hpp"
#include "packing/packing.hpp"

#include <iterator>
#include <vector>

namespace sbpack {

namespace {

using namespace packing_file;

constexpr PackingKind A = PackingKind::Attribute;
constexpr PackingKind D = PackingKind::Dataset;
constexpr PackingKind G = PackingKind::Group;
constexpr PackingType F = PackingType::Float64;
constexpr PackingType I = PackingType::Int64;
constexpr PackingType U = PackingType::UInt64;
constexpr PackingType S = PackingType::String;

// The root's attributes, its datasets, then the groups (docs/design.md §4).
constexpr PackingEntry kLeading[] = {
    {.name = kFormat, .kind = A, .type = S, .description = "\"sbpack.packing\""},
    {.name = kFormatVersion,
     .kind = A,
     .type = I,
     .units = "1",
     .description = "1 (this layout); a reader refuses any other"},
};

// Then the shape's (from geometry/particle_shape), then these.
constexpr PackingEntry kEntries[] = {
    {.name = kBoxLength,
     .kind = A,
     .type = F,
     .units = "length",
     .description = "cubic box edge L"},
    {.name = kSemiAxis,
     .kind = A,
     .type = F,
     .units = "length",
     .description = "semi-axis R of every particle (major-axis length D = 2 R <= L); of a "
                    "mixture, the largest"},
    {.name = kParticles,
     .kind = A,
     .type = I,
     .units = "1",
     .description = "N > 0, the rows of each per-particle dataset"},
    {.name = kPhi,
     .kind = A,
     .type = F,
     .units = "1",
     .description =
         "packing fraction N v1 / L^3 (of a mixture sum_i v_i / L^3); a reader refuses one "
         "off by more than 1e-9 of it"},
    {.name = kReducedPressure,
     .kind = A,
     .type = F,
     .units = "1",
     .description = "P = PV / (N kT) when the packing was written (sbgen; docs/design.md §3), > "
                    "0; the contact tolerance that resolves the network follows it",
     .optional = true},
    {.name = kSeed,
     .kind = A,
     .type = U,
     .units = "1",
     .description = "sbgen: the run's random seed (--seed)",
     .optional = true},
    {.name = kGeneratorVersion,
     .kind = A,
     .type = S,
     .description = "sbgen: the version of the program that wrote the packing",
     .optional = true},
    {.name = kPositions,
     .kind = D,
     .type = F,
     .units = "length",
     .description = "centroids r, wrapped into [0, L) on writing and on reading",
     .rows = "N",
     .columns = 3},
    {.name = kOrientations,
     .kind = D,
     .type = F,
     .units = "1",
     .description = "unit quaternions (w, x, y, z) rotating body to lab frame, x_lab = r + R_b(q) "
                    "x_body; normalised on reading",
     .rows = "N",
     .columns = 4},
    {.name = kSemiAxes,
     .kind = D,
     .type = F,
     .units = "length",
     .description =
         "a mixture's semi-axis R_i of each particle (docs/mixtures.md), semi_axis their "
         "largest; absent where every particle has semi_axis (a reader that does not "
         "know it refuses the file: its phi is then not N v1 / L^3)",
     .optional = true,
     .rows = "N",
     .columns = 1},
    {.name = kVelocities,
     .kind = D,
     .type = F,
     .units = "length/time",
     .description = "sbgen: velocities (m = kT = 1)",
     .optional = true,
     .rows = "N",
     .columns = 3},
    {.name = kAngularVelocities,
     .kind = D,
     .type = F,
     .units = "1/time",
     .description = "sbgen, p != 1: angular velocities in the lab frame",
     .optional = true,
     .rows = "N",
     .columns = 3},
    {.name = kProvenance,
     .kind = G,
     .description = "scalar attributes (int64, float64 or string): the generator's parameters and "
                    "run log; sbgen's are declared in generator/protocol/checkpoint_entries",
     .optional = true},
    {.name = kResumeState,
     .kind = G,
     .description = "what sbgen --resume needs beyond the particles, none of it provenance: scalar "
                    "attributes as provenance's (the format \"sbgen.state/1\", the phase, the jam "
                    "watches and the growth clock; declared in generator/protocol/"
                    "checkpoint_entries)",
     .optional = true},
    {.group = kResumeState,
     .name = kPairRecords,
     .kind = A,
     .type = I,
     .units = "1",
     .description = "a superball run's checkpoint: the rows of the dataset pair_records, at most "
                    "1000 N (none without it)",
     .optional = true},
    {.group = kResumeState,
     .name = kPairRecords,
     .kind = D,
     .type = F,
     .units = "1",
     .description = "the predictor's pair records (docs/design.md §3, \"Witness-point "
                    "certificates\"), ascending pairs: i, j (particle indices, i < j), the last "
                    "normal from i to j (unit, or zero where none), the witness points in i's and "
                    "j's body frames at semi-axis 1, the bodies' accumulated rotation angles since "
                    "the checkpoint's state (negative, or NaN where the record has no witness)",
     .optional = true,
     .rows = kPairRecords,
     .columns = kPairRecordColumns},
    {.name = kContactForces,
     .kind = G,
     .description = "sbgen: each contact's force, the momentum its pair exchanged in collisions "
                    "averaged over the run's last windows (docs/jamming.md, \"Contact forces\"); "
                    "each dataset has a string attribute units",
     .optional = true},
    {.group = kContactForces,
     .name = kWindows,
     .kind = A,
     .type = I,
     .units = "1",
     .description = "the windows the forces average over (sbgen's force_windows, fewer where the "
                    "run or its resume recorded fewer)",
     .optional = true},
    {.group = kContactForces,
     .name = kDuration,
     .kind = A,
     .type = F,
     .units = "time",
     .description = "those windows' summed duration",
     .optional = true},
    {.group = kContactForces,
     .name = kReducedPressure,
     .kind = A,
     .type = F,
     .units = "1",
     .description = "sbgen's reduced pressure over those windows (their duration-weighted mean); "
                    "the forces' virial 1 + sum_c f_c (r_ij . n_c) / (3 N D) reproduces it",
     .optional = true},
    {.group = kContactForces,
     .name = kContacts,
     .kind = A,
     .type = I,
     .units = "1",
     .description = "the rows of the per-contact datasets, at most 1000 N",
     .optional = true},
    {.group = kContactForces,
     .name = kPairs,
     .kind = D,
     .type = F,
     .units = "1",
     .description = "the particles i < j of each contact, ascending",
     .optional = true,
     .rows = kContacts,
     .columns = 2},
    {.group = kContactForces,
     .name = kPoints,
     .kind = D,
     .type = F,
     .units = "length",
     .description = "contact points x, the impulse-weighted mean of the collisions', in [0, L)",
     .optional = true,
     .rows = kContacts,
     .columns = 3},
    {.group = kContactForces,
     .name = kNormals,
     .kind = D,
     .type = F,
     .units = "1",
     .description = "unit normals n from i to j, the direction of the summed impulse",
     .optional = true,
     .rows = kContacts,
     .columns = 3},
    {.group = kContactForces,
     .name = kForces,
     .kind = D,
     .type = F,
     .units = "kT/D",
     .description = "f >= 0: i pushes j with f n (the summed impulses over kT, over the windows' "
                    "duration, times D = 2 semi_axis)",
     .optional = true,
     .rows = kContacts,
     .columns = 1},
    {.group = kContactForces,
     .name = kNetForces,
     .kind = D,
     .type = F,
     .units = "kT/D",
     .description = "the check: the net force on each particle, sum of f n over its contacts (n "
                    "into it); written, not read",
     .optional = true,
     .rows = "N",
     .columns = 3},
    {.group = kContactForces,
     .name = kNetTorques,
     .kind = D,
     .type = F,
     .units = "kT",
     .description = "the check: the net torque on each particle, sum of ((x - r) / D) x f n over "
                    "its contacts (minimum image); written, not read",
     .optional = true,
     .rows = "N",
     .columns = 3},
};

constexpr PackingMigration kMigrations[] = {
    {1, kProvenance, "state_", kResumeState,
     "files written before the group resume_state (issue 17) kept its attributes in provenance "
     "as state_*"},
};

} // namespace

std::span<const PackingEntry> packingEntries() {
    static const std::vector<PackingEntry> entries = [] {
        std::vector<PackingEntry> all(std::begin(kLeading), std::end(kLeading));
        for (const ShapeField& shape : shapeFields())
            all.push_back({.name = shape.name,
                           .kind = A,
                           .type = shape.text ? S : F,
                           .units = shape.units,
                           .description = shape.description,
                           .optional = shape.optional});
        all.insert(all.end(), std::begin(kEntries), std::end(kEntries));
        return all;
    }();
    return entries;
}

std::span<const PackingMigration> packingMigrations() {
    return kMigrations;
}

} // namespace sbpack

#include "io/packing_io.hpp"

#include "io/atomic_file.hpp"
#include "io/hdf5_handles.hpp"
#include "io/read_guard.hpp"
#include "packing/contact_forces.hpp"
#include "packing/validation.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace sbpack {

namespace fs = std::filesystem;

namespace {

using namespace packing_file;

/// Relative tolerance between the stored phi and N v1 / L^3 recomputed on reading.
constexpr double kPhiTolerance = 1e-9;

/// Shortest text that reads back as the same double.
std::string exact(double x) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
}

std::vector<double> flatten(const std::vector<Vector3d>& rows) {
    std::vector<double> values;
    values.reserve(3 * rows.size());
    for (const Vector3d& r : rows)
        values.insert(values.end(), {r.x(), r.y(), r.z()});
    return values;
}

std::vector<Vector3d> unflatten(const std::vector<double>& values) {
    std::vector<Vector3d> rows(values.size() / 3);
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = Vector3d(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
    return rows;
}

/// A group of scalar attributes (`provenance`, `resume_state`).
void writeAttributeGroup(hid_t root, const std::string& groupName,
                         const std::map<std::string, ProvenanceValue>& provenance) {
    const Hdf5Handle group = createGroup(root, groupName);
    for (const auto& [name, value] : provenance) {
        std::visit(
            [&, &name = name](const auto& v) {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, std::int64_t>)
                    writeInt64Attribute(group.get(), name, v);
                else if constexpr (std::is_same_v<T, double>)
                    writeDoubleAttribute(group.get(), name, v);
                else
                    writeStringAttribute(group.get(), name, v);
            },
            value);
    }
}

std::map<std::string, ProvenanceValue> readAttributeGroup(hid_t root, const std::string& groupName,
                                                          const std::string& file) {
    std::map<std::string, ProvenanceValue> provenance;
    const Hdf5Handle group = openGroup(root, groupName);
    for (const std::string& name : attributeNames(group.get())) {
        switch (attributeKind(group.get(), name)) {
        case AttributeKind::Integer:
            provenance[name] = readInt64Attribute(group.get(), name);
            break;
        case AttributeKind::Float:
            provenance[name] = readDoubleAttribute(group.get(), name);
            break;
        case AttributeKind::String:
            provenance[name] = readStringAttribute(group.get(), name);
            break;
        case AttributeKind::Other:
            throw PackingFileError("'" + file + "': " + groupName + " attribute '" + name +
                                   "' has an unsupported type (need integer, float or string)");
        }
    }
    return provenance;
}

/// resume_state/pair_records, as many rows as resumeState["pair_records"] says (none without
/// it), at most 1000 a particle.
std::vector<double> readPairRecords(hid_t root, const std::map<std::string, ProvenanceValue>& state,
                                    std::size_t particles, const std::string& file) {
    const auto count = state.find(kPairRecords);
    if (count == state.end()) return {};
    const auto* rows = std::get_if<std::int64_t>(&count->second);
    if (rows == nullptr || *rows < 0 || *rows > 1000 * static_cast<std::int64_t>(particles))
        throw PackingFileError("'" + file + "': " + kResumeState + " attribute '" + kPairRecords +
                               "' must be an integer in [0, 1000 n_particles]");
    if (*rows == 0) return {};
    return readMatrixDataset(openGroup(root, kResumeState).get(), kPairRecords,
                             static_cast<std::size_t>(*rows), kPairRecordColumns);
}

/// The group contact_forces (docs/jamming.md, "Contact forces"): the contacts, the per-particle
/// residuals (forceBalance) and on each dataset its units from the table.
void writeContactForces(hid_t root, const Packing& packing) {
    const ContactForces& forces = *packing.contactForces;
    const Hdf5Handle group = createGroup(root, kContactForces);
    const hid_t g = group.get();
    writeInt64Attribute(g, kWindows, forces.windows);
    writeDoubleAttribute(g, kDuration, forces.duration);
    writeDoubleAttribute(g, kReducedPressure, forces.reducedPressure);
    writeInt64Attribute(g, kContacts, static_cast<std::int64_t>(forces.contacts.size()));
    std::vector<double> pairs, magnitudes;
    std::vector<Vector3d> points, normals;
    for (const ContactForce& c : forces.contacts) {
        pairs.insert(pairs.end(), {static_cast<double>(c.i), static_cast<double>(c.j)});
        points.push_back(wrapIntoBox(c.point, packing.boxLength));
        normals.push_back(c.normal);
        magnitudes.push_back(c.force);
    }
    writeMatrixDataset(g, kPairs, pairs, 2);
    writeMatrixDataset(g, kPoints, flatten(points), 3);
    writeMatrixDataset(g, kNormals, flatten(normals), 3);
    writeMatrixDataset(g, kForces, magnitudes, 1);
    const ForceBalance balance = forceBalance(packing, forces);
    writeMatrixDataset(g, kNetForces, flatten(balance.netForces), 3);
    writeMatrixDataset(g, kNetTorques, flatten(balance.netTorques), 3);
    for (const PackingEntry& e : packingEntries())
        if (e.group == kContactForces && e.kind == PackingKind::Dataset)
            writeStringAttribute(openDataset(g, std::string(e.name)).get(), kUnits,
                                 std::string(e.units));
}

/// Row k of the contact forces' datasets, refused (naming the row) unless i < j are particles,
/// the point finite, the normal unit and the force finite and non-negative.
ContactForce contactForceRow(const std::vector<double>& pairs, const std::vector<double>& points,
                             const std::vector<double>& normals, const std::vector<double>& forces,
                             std::size_t k, std::size_t particles, const std::string& file) {
    const auto refuse = [&](const std::string& problem) {
        throw PackingFileError("'" + file + "': " + kContactForces + " row " + std::to_string(k) +
                               ": " + problem);
    };
    const double i = pairs[2 * k], j = pairs[2 * k + 1];
    if (!(i >= 0.0 && i < j && j < static_cast<double>(particles) && std::floor(i) == i &&
          std::floor(j) == j))
        refuse("the particles must be indices i < j < n_particles");
    const ContactForce c{static_cast<int>(i), static_cast<int>(j),
                         Vector3d(points[3 * k], points[3 * k + 1], points[3 * k + 2]),
                         Vector3d(normals[3 * k], normals[3 * k + 1], normals[3 * k + 2]),
                         forces[k]};
    if (!c.point.allFinite()) refuse("the contact point must be finite");
    if (!(std::abs(c.normal.norm() - 1.0) <= 1e-9)) refuse("the normal must be a unit vector");
    if (!(std::isfinite(c.force) && c.force >= 0.0))
        refuse("the force must be finite and non-negative");
    return c;
}

/// The group contact_forces, as many contacts as its attribute says, at most 1000 a particle
/// (its residuals are not read: forceBalance recomputes them).
ContactForces readContactForces(hid_t root, std::size_t particles, const std::string& file) {
    const Hdf5Handle group = openGroup(root, kContactForces);
    const hid_t g = group.get();
    ContactForces forces;
    forces.windows = readInt64Attribute(g, kWindows);
    forces.duration = readDoubleAttribute(g, kDuration);
    forces.reducedPressure = readDoubleAttribute(g, kReducedPressure);
    const std::int64_t rows = readInt64Attribute(g, kContacts);
    if (rows < 0 || rows > 1000 * static_cast<std::int64_t>(particles))
        throw PackingFileError("'" + file + "': " + kContactForces + " attribute '" + kContacts +
                               "' must be an integer in [0, 1000 n_particles]");
    const auto n = static_cast<std::size_t>(rows);
    if (n == 0) return forces;
    const std::vector<double> pairs = readMatrixDataset(g, kPairs, n, 2),
                              points = readMatrixDataset(g, kPoints, n, 3),
                              normals = readMatrixDataset(g, kNormals, n, 3),
                              magnitudes = readMatrixDataset(g, kForces, n, 1);
    for (std::size_t k = 0; k < n; ++k)
        forces.contacts.push_back(
            contactForceRow(pairs, points, normals, magnitudes, k, particles, file));
    return forces;
}

/// The attribute group `group` of `packing` (provenance or resume_state).
std::map<std::string, ProvenanceValue>& attributeGroup(Packing& packing, std::string_view group) {
    if (group == kProvenance) return packing.provenance;
    if (group == kResumeState) return packing.resumeState;
    throw std::logic_error("packing file: no attribute group '" + std::string(group) + "'");
}

/// The migration rows (io/packing_schema.hpp) of a file of `version` that lacks their group.
void migrate(hid_t root, std::int64_t version, Packing& packing) {
    for (const PackingMigration& m : packingMigrations()) {
        if (m.version != version || hasLink(root, std::string(m.toGroup))) continue;
        auto& from = attributeGroup(packing, m.fromGroup);
        auto& to = attributeGroup(packing, m.toGroup);
        for (auto entry = from.begin(); entry != from.end();) {
            if (entry->first.starts_with(m.fromPrefix)) {
                to[entry->first.substr(m.fromPrefix.size())] = entry->second;
                entry = from.erase(entry);
            } else {
                ++entry;
            }
        }
    }
}

/// The shape's family (only where it is not the superball, so that every superball file is as
/// before) and its parameters by name.
void writeShape(hid_t root, const ShapeSpec& shape) {
    if (const std::optional<std::string_view> family = shape.writtenFamily())
        writeStringAttribute(root, kShape, std::string(*family));
    for (const auto& [name, value] : shape.namedValues())
        writeDoubleAttribute(root, std::string(name), value);
}

ShapeSpec readShape(hid_t root, const std::string& file) {
    std::optional<std::string> family;
    if (hasAttribute(root, kShape)) family = readStringAttribute(root, kShape);
    if (family && findShapeFamily(*family) == nullptr)
        throw PackingFileError("'" + file + "': shape '" + *family +
                               "' is not a shape family this build knows (" + shapeFamilyNames() +
                               ")");
    return ShapeSpec::read(family, [&](std::string_view name) {
        return readDoubleAttribute(root, std::string(name));
    });
}

/// The packing file's bytes (built in memory; docs/design.md §4).
std::string fileContents(const Packing& packing, const std::string& name) {
    Hdf5Handle file = createFile(name);
    const hid_t root = file.get();
    writeStringAttribute(root, kFormat, kPackingFormat);
    writeInt64Attribute(root, kFormatVersion, kPackingFormatVersion);
    writeShape(root, packing.shapeSpec);
    writeDoubleAttribute(root, kBoxLength, packing.boxLength);
    writeDoubleAttribute(root, kSemiAxis, packing.semiAxis);
    writeInt64Attribute(root, kParticles, static_cast<std::int64_t>(packing.size()));
    writeDoubleAttribute(root, kPhi, packing.packingFraction());
    if (packing.reducedPressure)
        writeDoubleAttribute(root, kReducedPressure, *packing.reducedPressure);
    if (packing.seed) writeUint64Attribute(root, kSeed, *packing.seed);
    if (!packing.generatorVersion.empty())
        writeStringAttribute(root, kGeneratorVersion, packing.generatorVersion);

    std::vector<Vector3d> wrapped(packing.positions);
    for (Vector3d& r : wrapped)
        r = wrapIntoBox(r, packing.boxLength);
    writeMatrixDataset(root, kPositions, flatten(wrapped), 3);
    std::vector<double> quaternions;
    quaternions.reserve(4 * packing.size());
    for (const Quaterniond& q : packing.orientations)
        quaternions.insert(quaternions.end(), {q.w(), q.x(), q.y(), q.z()});
    writeMatrixDataset(root, kOrientations, quaternions, 4);
    if (packing.isMixture()) writeMatrixDataset(root, kSemiAxes, packing.semiAxes, 1);
    if (!packing.velocities.empty())
        writeMatrixDataset(root, kVelocities, flatten(packing.velocities), 3);
    if (!packing.angularVelocities.empty())
        writeMatrixDataset(root, kAngularVelocities, flatten(packing.angularVelocities), 3);
    if (!packing.provenance.empty()) writeAttributeGroup(root, kProvenance, packing.provenance);
    if (!packing.resumeState.empty()) writeAttributeGroup(root, kResumeState, packing.resumeState);
    if (!packing.pairRecords.empty())
        writeMatrixDataset(openGroup(root, kResumeState).get(), kPairRecords, packing.pairRecords,
                           kPairRecordColumns);
    if (packing.contactForces) writeContactForces(root, packing);
    return fileImage(file, name);
}

Packing readContents(hid_t root, const std::string& file) {
    const std::string format = readStringAttribute(root, kFormat);
    if (format != kPackingFormat)
        throw PackingFileError("'" + file + "': format is '" + format + "', expected '" +
                               kPackingFormat + "' (not an sbpack packing file)");
    const std::int64_t version = readInt64Attribute(root, kFormatVersion);
    if (version != kPackingFormatVersion)
        throw PackingFileError("'" + file + "': format_version " + std::to_string(version) +
                               " is not supported (this build reads version " +
                               std::to_string(kPackingFormatVersion) + ")");

    Packing packing;
    packing.shapeSpec = readShape(root, file);
    packing.boxLength = readDoubleAttribute(root, kBoxLength);
    packing.semiAxis = readDoubleAttribute(root, kSemiAxis);
    const std::int64_t n = readInt64Attribute(root, kParticles);
    if (n <= 0)
        throw InvalidPacking("'" + file + "': invalid packing: n_particles = " + std::to_string(n) +
                             " (no particles)");
    const double phi = readDoubleAttribute(root, kPhi);
    if (hasAttribute(root, kReducedPressure))
        packing.reducedPressure = readDoubleAttribute(root, kReducedPressure);
    if (hasAttribute(root, kSeed)) packing.seed = readUint64Attribute(root, kSeed);
    if (hasAttribute(root, kGeneratorVersion))
        packing.generatorVersion = readStringAttribute(root, kGeneratorVersion);

    const auto rows = static_cast<std::size_t>(n);
    packing.positions = unflatten(readMatrixDataset(root, kPositions, rows, 3));
    const std::vector<double> q = readMatrixDataset(root, kOrientations, rows, 4);
    packing.orientations.resize(rows);
    for (std::size_t i = 0; i < rows; ++i)
        packing.orientations[i] = Quaterniond(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);
    if (hasLink(root, kSemiAxes)) packing.semiAxes = readMatrixDataset(root, kSemiAxes, rows, 1);
    if (hasLink(root, kVelocities))
        packing.velocities = unflatten(readMatrixDataset(root, kVelocities, rows, 3));
    if (hasLink(root, kAngularVelocities))
        packing.angularVelocities = unflatten(readMatrixDataset(root, kAngularVelocities, rows, 3));
    if (hasLink(root, kProvenance))
        packing.provenance = readAttributeGroup(root, kProvenance, file);
    if (hasLink(root, kResumeState)) {
        packing.resumeState = readAttributeGroup(root, kResumeState, file);
        packing.pairRecords = readPairRecords(root, packing.resumeState, rows, file);
    }
    if (hasLink(root, kContactForces)) packing.contactForces = readContactForces(root, rows, file);
    migrate(root, version, packing);

    validatePacking(packing, file);
    const double expectedPhi = packing.packingFraction();
    if (!(std::abs(phi - expectedPhi) <= kPhiTolerance * expectedPhi))
        throw InvalidPacking("'" + file + "': invalid packing: phi = " + exact(phi) +
                             " disagrees with N v1 / L^3 = " + exact(expectedPhi));
    canonicalizePacking(packing);
    return packing;
}

} // namespace

void checkInputFile(const fs::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status)) throw PackingFileError("'" + name + "': no such file");
    if (fs::is_directory(status))
        throw PackingFileError("'" + name + "': is a directory, not a packing file");
    if (!fs::is_regular_file(status))
        throw PackingFileError("'" + name +
                               "': is not a regular file (a FIFO, device or socket); "
                               "packings are read from regular files only");
}

Packing readPacking(const fs::path& file) {
    const std::string name = file.string();
    checkInputFile(file);
    if (!std::ifstream(file)) throw PackingFileError("'" + name + "': cannot open for reading");
    if (!isHdf5File(file)) {
        const std::string extension = file.extension().string();
        throw PackingFileError(
            "'" + name + "': not an HDF5 file (no HDF5 signature)" +
            (extension == ".txt" || extension == ".xyz"
                 ? std::string("; a text or extended-XYZ packing is read by its extension "
                               "(readPackingFile)")
                 : std::string()));
    }
    const ReadGuard guard(file); // armed by the programs only (io/read_guard.hpp)
    try {
        Hdf5Handle h5;
        try {
            h5 = openFileReadOnly(file);
        } catch (const Hdf5Error& e) {
            throw PackingFileError(std::string(e.what()) + "; the file is truncated or corrupt");
        }
        return readContents(h5.get(), name);
    } catch (const Hdf5Error& e) {
        throw PackingFileError(e.what());
    }
}

void writePacking(const Packing& packing, const fs::path& file) {
    validatePacking(packing, file.string());
    AtomicOutput output(file);
    output.write(fileContents(packing, file.string()));
    output.commit();
}

} // namespace sbpack

#include "io/lammps_io.hpp"

#include "io/text_lines.hpp"
#include "packing/validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace sbpack {

namespace fs = std::filesystem;
using namespace text;

namespace {

/// One particle's line of either format, before the particles are put in the order of their ids.
struct Particle {
    long long id = 0;
    Vector3d position = Vector3d::Zero();
    Quaterniond orientation = Quaterniond::Identity();
    double semiAxis = 0.0; ///< its own (a mixture's: docs/mixtures.md)
};

/// Every particle in the order of its id (wrapped into [0, L) by canonicalizePacking), with its
/// size (identical particles where all agree); fails on a repeated id.
void sortedInto(std::vector<Particle> particles, Packing& packing, const LineReader& reader) {
    std::sort(particles.begin(), particles.end(),
              [](const Particle& a, const Particle& b) { return a.id < b.id; });
    std::vector<double> semiAxes;
    for (std::size_t k = 0; k < particles.size(); ++k) {
        if (k > 0 && particles[k].id == particles[k - 1].id)
            reader.fail("atom id " + std::to_string(particles[k].id) + " appears twice");
        if (!(particles[k].semiAxis > 0.0))
            reader.fail("atom id " + std::to_string(particles[k].id) +
                        " has no shape (its Ellipsoids line)");
        packing.positions.push_back(particles[k].position);
        packing.orientations.push_back(particles[k].orientation);
        semiAxes.push_back(particles[k].semiAxis);
    }
    readSemiAxes(semiAxes, std::nullopt, packing, reader, "the shape columns");
    canonicalizePacking(packing);
    validatePacking(packing, reader.name());
}

/// The edge of a cubic box from three "lo hi" pairs; fails where the edges differ.
double cubicEdge(const std::array<std::array<double, 2>, 3>& bounds, const LineReader& reader) {
    const double edge = bounds[0][1] - bounds[0][0];
    for (const auto& b : bounds)
        if (!(edge > 0.0) || std::abs(b[1] - b[0] - edge) > 1e-12 * edge)
            reader.fail("the box is not cubic (its three edges must be equal): sbpack's boxes are");
    return edge;
}

/// LAMMPS's shape of particle i: its diameters 2a 2b 2c, at its own size (a mixture's:
/// docs/mixtures.md).
std::string diameters(const Packing& packing, const Superquadric& shape, std::size_t i) {
    const double twice = 2.0 * packing.semiAxisOf(i);
    return full(twice * shape.axes.x()) + ' ' + full(twice * shape.axes.y()) + ' ' +
           full(twice * shape.axes.z());
}

/// The columns of a dump's ATOMS line, and the lookups of one particle's values.
class DumpColumns {
  public:
    DumpColumns(const std::vector<std::string>& names, const LineReader& reader) {
        for (std::size_t k = 0; k < names.size(); ++k)
            index_[names[k]] = k;
        if (!has("id")) reader.fail("the ATOMS line has no id column");
        for (const char* set : {"x", "xu", "xs"})
            if (has(set)) position_ = set;
        if (position_.empty()) reader.fail("the ATOMS line has no x y z (or xu, xs) columns");
        if (!has("shapex")) reader.fail("the ATOMS line has no shapex shapey shapez columns");
    }
    bool has(const std::string& name) const { return index_.count(name) != 0; }
    const std::string& token(const std::vector<std::string>& tokens, const std::string& name,
                             const LineReader& reader) const {
        const auto it = index_.find(name);
        if (it == index_.end()) reader.fail("the ATOMS line has no " + name + " column");
        return tokens[it->second];
    }
    double value(const std::vector<std::string>& tokens, const std::string& name,
                 const LineReader& reader) const {
        return reader.parseDouble(token(tokens, name, reader));
    }
    /// "x", "xu" or "xs" with its y and z.
    std::array<std::string, 3> positionNames() const {
        const std::string tail = position_.substr(1);
        return {"x" + tail, "y" + tail, "z" + tail};
    }
    bool scaled() const { return position_ == "xs"; }
    std::size_t size() const { return index_.size(); }

  private:
    std::map<std::string, std::size_t> index_;
    std::string position_;
};

/// A dump's shape columns beyond each particle's own size: the proportions and OVITO's two
/// roundnesses (SuperquadricRoundness.Phi and .Theta).
struct DumpShape {
    AxesColumns axes;
    UniformColumn phi{"SuperquadricRoundness.Phi", {}}, theta{"SuperquadricRoundness.Theta", {}};
    /// The shape (a roundness written in single precision repaired); without the roundness
    /// columns, 1 (the ellipsoid's: the sphere where a = b = c).
    ShapeSpec shape(const LineReader& reader) const {
        return superquadricShape(
            {axes.proportions(), 2.0 / phi.valueOr(1.0), 2.0 / theta.valueOr(1.0)}, true, reader);
    }
};

/// The particle of one ATOMS line, feeding the dump's shape.
Particle dumpParticle(const std::vector<std::string>& tokens, const DumpColumns& columns,
                      const std::array<std::array<double, 2>, 3>& bounds, DumpShape& shape,
                      const LineReader& reader) {
    if (tokens.size() != columns.size())
        reader.fail(fmt::format("{} values for {} columns", tokens.size(), columns.size()));
    Particle particle;
    particle.id = reader.parseCount(columns.token(tokens, "id", reader));
    const auto names = columns.positionNames();
    for (int k = 0; k < 3; ++k) {
        const double v = columns.value(tokens, names[k], reader);
        particle.position[k] =
            columns.scaled() ? v * (bounds[k][1] - bounds[k][0]) : v - bounds[k][0];
    }
    if (columns.has("quatw"))
        particle.orientation = Quaterniond(
            columns.value(tokens, "quatw", reader), columns.value(tokens, "quati", reader),
            columns.value(tokens, "quatj", reader), columns.value(tokens, "quatk", reader));
    particle.semiAxis = shape.axes.size(0.5 * Vector3d(columns.value(tokens, "shapex", reader),
                                                       columns.value(tokens, "shapey", reader),
                                                       columns.value(tokens, "shapez", reader)),
                                        reader);
    if (columns.has("SuperquadricRoundness.Phi")) {
        shape.phi.column(columns.value(tokens, "SuperquadricRoundness.Phi", reader), reader);
        shape.theta.column(columns.value(tokens, "SuperquadricRoundness.Theta", reader), reader);
    }
    return particle;
}

} // namespace

void writeLammpsDump(const Packing& packing, const fs::path& file) {
    validatePacking(packing, file.string());
    const std::string length = full(packing.boxLength);
    const Superquadric shape = packing.shapeSpec.superquadric();
    const std::string roundness = // OVITO's (phi, theta) = 2 / blockiness
        full(2.0 / shape.eastWest) + ' ' + full(2.0 / shape.northSouth);
    writeTextFile(file, [&](std::ostream& out) {
        out << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n"
            << packing.size() << "\nITEM: BOX BOUNDS pp pp pp\n";
        for (int k = 0; k < 3; ++k)
            out << "0 " << length << '\n';
        out << "ITEM: ATOMS id type x y z quatw quati quatj quatk shapex shapey shapez "
               "SuperquadricRoundness.Phi SuperquadricRoundness.Theta\n";
        for (std::size_t i = 0; i < packing.size(); ++i) {
            const Vector3d r = wrapIntoBox(packing.positions[i], packing.boxLength);
            const Quaterniond q = packing.orientations[i].normalized();
            out << i + 1 << " 1 " << full(r.x()) << ' ' << full(r.y()) << ' ' << full(r.z()) << ' '
                << full(q.w()) << ' ' << full(q.x()) << ' ' << full(q.y()) << ' ' << full(q.z())
                << ' ' << diameters(packing, shape, i) << ' ' << roundness << '\n';
        }
    });
}

Packing readLammpsDump(const fs::path& file) {
    LineReader reader(file);
    std::string line;
    long long count = 0;
    std::array<std::array<double, 2>, 3> bounds{};
    bool boxRead = false;
    std::vector<Particle> particles;
    DumpShape shape;
    while (particles.empty() && reader.next(line)) {
        if (!line.starts_with("ITEM: "))
            reader.fail("expected an 'ITEM:' line, got '" + line + "'");
        const std::vector<std::string> words = splitWhitespace(line.substr(6));
        if (line.starts_with("ITEM: NUMBER OF ATOMS")) {
            if (!reader.next(line)) break;
            count = reader.parseCount(line);
        } else if (line.starts_with("ITEM: BOX BOUNDS")) {
            if (words.size() != 5 || words[2] != "pp" || words[3] != "pp" || words[4] != "pp")
                reader.fail("the box must be periodic and orthogonal ('BOX BOUNDS pp pp pp')");
            for (auto& b : bounds) {
                if (!reader.next(line)) break;
                const auto pair = splitWhitespace(line);
                if (pair.size() != 2) reader.fail("expected 'lo hi'");
                b = {reader.parseDouble(pair[0]), reader.parseDouble(pair[1])};
            }
            boxRead = true;
        } else if (line.starts_with("ITEM: ATOMS")) {
            if (count == 0 || !boxRead) reader.fail("ATOMS before NUMBER OF ATOMS and BOX BOUNDS");
            const DumpColumns columns({words.begin() + 1, words.end()}, reader);
            for (long long i = 0; i < count; ++i) {
                if (!reader.next(line)) reader.fail(fmt::format("{} of {} atoms", i, count));
                particles.push_back(
                    dumpParticle(splitWhitespace(line), columns, bounds, shape, reader));
            }
        } else if (!reader.next(line)) { // TIMESTEP and the others: one value line
            break;
        }
    }
    if (particles.empty()) reader.fail("no ITEM: ATOMS frame");
    Packing packing;
    packing.boxLength = cubicEdge(bounds, reader);
    packing.shapeSpec = shape.shape(reader);
    sortedInto(std::move(particles), packing, reader);
    return packing;
}

namespace {

/// The header of a data file: its counts and box, up to the first section's keyword (returned).
struct DataHeader {
    long long atoms = 0, ellipsoids = 0;
    std::array<std::array<double, 2>, 3> bounds{};
    int boxLines = 0;
};

std::string readDataHeader(LineReader& reader, DataHeader& header) {
    std::string line;
    if (!reader.next(line)) reader.fail("empty file"); // the title line
    while (reader.next(line)) {
        const std::vector<std::string> t = splitWhitespace(line.substr(0, line.find('#')));
        if (t.empty()) continue;
        if (t.size() == 1) return t[0]; // a section: Atoms, Ellipsoids, ...
        const std::string& key = t.back();
        if (key == "atoms")
            header.atoms = reader.parseCount(t[0]);
        else if (key == "ellipsoids")
            header.ellipsoids = reader.parseCount(t[0]);
        else if (key == "yz")
            reader.fail("a triclinic box (xy xz yz): sbpack's boxes are cubic");
        else if (key == "xhi" || key == "yhi" || key == "zhi") {
            header.bounds[key[0] - 'x'] = {reader.parseDouble(t[0]), reader.parseDouble(t[1])};
            ++header.boxLines;
        }
    }
    reader.fail("no Atoms section");
}

/// The `count` lines of a section after its blank line.
std::vector<std::vector<std::string>> sectionLines(LineReader& reader, long long count) {
    std::vector<std::vector<std::string>> lines;
    std::string line;
    while (static_cast<long long>(lines.size()) < count && reader.next(line)) {
        std::vector<std::string> t = splitWhitespace(line.substr(0, line.find('#')));
        if (!t.empty()) lines.push_back(std::move(t));
    }
    if (static_cast<long long>(lines.size()) < count)
        reader.fail(fmt::format("the section ends after {} of {} lines", lines.size(), count));
    return lines;
}

/// A data file's shape columns beyond each particle's own size: the proportions and the
/// superellipsoid's two blockinesses (absent: 2, the ellipsoid's).
struct DataShape {
    AxesColumns axes;
    UniformColumn eastWest{"blockiness n1", {}}, northSouth{"blockiness n2", {}};
    ShapeSpec shape(const LineReader& reader) const {
        return superquadricShape(
            {axes.proportions(), eastWest.valueOr(2.0), northSouth.valueOr(2.0)}, false, reader);
    }
};

/// One line of the Atoms (`atom`) or Ellipsoids section into its particle and the shape.
void readDataLine(const std::vector<std::string>& t, bool atom, Particle& particle,
                  const DataHeader& header, DataShape& shape, const LineReader& reader) {
    if (atom) {
        if (t.size() != 7 && t.size() != 10) reader.fail("expected id type 1 density x y z");
        for (int k = 0; k < 3; ++k)
            particle.position[k] = reader.parseDouble(t[4 + k]) - header.bounds[k][0];
        return;
    }
    if (t.size() != 8 && t.size() != 10)
        reader.fail("expected id shapex shapey shapez quatw quati quatj quatk [n1 n2]");
    particle.semiAxis =
        shape.axes.size(0.5 * Vector3d(reader.parseDouble(t[1]), reader.parseDouble(t[2]),
                                       reader.parseDouble(t[3])),
                        reader);
    particle.orientation = Quaterniond(reader.parseDouble(t[4]), reader.parseDouble(t[5]),
                                       reader.parseDouble(t[6]), reader.parseDouble(t[7]));
    if (t.size() == 10) {
        shape.eastWest.column(reader.parseDouble(t[8]), reader);
        shape.northSouth.column(reader.parseDouble(t[9]), reader);
    }
}

} // namespace

void writeLammpsData(const Packing& packing, const fs::path& file) {
    validatePacking(packing, file.string());
    const Superquadric shape = packing.shapeSpec.superquadric();
    const bool blocky = shape.eastWest != 2.0 || shape.northSouth != 2.0;
    const std::string length = full(packing.boxLength);
    const std::string blockiness =
        blocky ? ' ' + full(shape.eastWest) + ' ' + full(shape.northSouth) : std::string();
    writeTextFile(file, [&](std::ostream& out) {
        out << "LAMMPS data file from sbpack: " << packing.shapeSpec.info().name << "s";
        for (const auto& [name, value] : packing.shapeSpec.namedValues())
            out << ' ' << name << " = " << full(value) << ',';
        out << " semi-axis " << full(packing.semiAxis)
            << (packing.isMixture() ? " (the largest of a mixture)" : "")
            << (blocky ? " (atom_style ellipsoid superellipsoid, LAMMPS 30Mar2026 and later)\n\n"
                       : " (atom_style ellipsoid)\n\n")
            << packing.size() << " atoms\n1 atom types\n"
            << packing.size() << " ellipsoids\n\n";
        for (const char* axis : {"x", "y", "z"})
            out << "0 " << length << ' ' << axis << "lo " << axis << "hi\n";
        out << "\nAtoms # ellipsoid\n\n";
        for (std::size_t i = 0; i < packing.size(); ++i) {
            const Vector3d r = wrapIntoBox(packing.positions[i], packing.boxLength);
            out << i + 1 << " 1 1 1 " << full(r.x()) << ' ' << full(r.y()) << ' ' << full(r.z())
                << '\n';
        }
        out << "\nEllipsoids\n\n";
        for (std::size_t i = 0; i < packing.size(); ++i) {
            const Quaterniond q = packing.orientations[i].normalized();
            out << i + 1 << ' ' << diameters(packing, shape, i) << ' ' << full(q.w()) << ' '
                << full(q.x()) << ' ' << full(q.y()) << ' ' << full(q.z()) << blockiness << '\n';
        }
    });
}

Packing readLammpsData(const fs::path& file) {
    LineReader reader(file);
    DataHeader header;
    const std::string section = readDataHeader(reader, header);
    if (header.boxLines != 3) reader.fail("the header lacks xlo xhi, ylo yhi or zlo zhi");
    if (header.ellipsoids != header.atoms)
        reader.fail("every atom must be an ellipsoid (atom_style ellipsoid)");
    std::map<long long, Particle> particles;
    DataShape shape;
    std::string line = section;
    do { // the sections by their keyword lines; others (Masses, Velocities) are passed over
        const std::vector<std::string> words = splitWhitespace(line.substr(0, line.find('#')));
        if (words.size() != 1 || (words[0] != "Atoms" && words[0] != "Ellipsoids")) continue;
        for (const auto& t : sectionLines(reader, header.atoms))
            readDataLine(t, words[0] == "Atoms", particles[reader.parseCount(t[0])], header, shape,
                         reader);
    } while (reader.next(line));
    if (static_cast<long long>(particles.size()) != header.atoms)
        reader.fail("the Atoms and Ellipsoids sections name different atoms");
    Packing packing;
    packing.boxLength = cubicEdge(header.bounds, reader);
    packing.shapeSpec = shape.shape(reader);
    std::vector<Particle> ordered;
    for (auto& [id, particle] : particles) {
        particle.id = id;
        ordered.push_back(particle);
    }
    sortedInto(std::move(ordered), packing, reader);
    return packing;
}

} // namespace sbpack

#include "io/text_io.hpp"

#include "io/atomic_file.hpp"
#include "io/text_lines.hpp"
#include "packing/validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace sbpack {

namespace fs = std::filesystem;

using namespace text;

namespace {

constexpr const char* kTextMagic = "# sbpack text packing v1";

} // namespace

void writeTextPacking(const Packing& packing, const fs::path& file) {
    validatePacking(packing, file.string());
    writeTextFile(file, [&](std::ostream& out) {
        // The shape as the packing file writes it (ShapeSpec::namedValues): "# p 1.5".
        out << kTextMagic << '\n';
        if (const auto family = packing.shapeSpec.writtenFamily())
            out << "# " << kShapeFamilyKey << ' ' << *family << '\n';
        for (const auto& [name, value] : packing.shapeSpec.namedValues())
            out << "# " << name << ' ' << full(value) << '\n';
        out << "# semi_axis " << full(packing.semiAxis) << "\n# box_length "
            << full(packing.boxLength) << "\n# n_particles " << packing.size() << '\n';
        if (packing.reducedPressure)
            out << "# reduced_pressure " << full(*packing.reducedPressure) << '\n';
        if (packing.seed) out << "# seed " << *packing.seed << '\n';
        // A mixture's lines end with each particle's semi-axis (docs/mixtures.md).
        out << "# columns x y z qw qx qy qz" << (packing.isMixture() ? " semi_axis\n" : "\n");
        for (std::size_t i = 0; i < packing.size(); ++i) {
            const Vector3d r = wrapIntoBox(packing.positions[i], packing.boxLength);
            const Quaterniond& q = packing.orientations[i];
            out << full(r.x()) << ' ' << full(r.y()) << ' ' << full(r.z()) << ' ' << full(q.w())
                << ' ' << full(q.x()) << ' ' << full(q.y()) << ' ' << full(q.z());
            if (packing.isMixture()) out << ' ' << full(packing.semiAxes[i]);
            out << '\n';
        }
    });
}

namespace {

/// The header of a text packing: "# key value" lines before the first particle line.
class TextHeader {
  public:
    /// Reads a comment line's key if it is a header key (others are free comments).
    void read(const std::vector<std::string>& tokens, LineReader& reader) {
        if (tokens.front() != "#" || tokens.size() != 3) return;
        const std::string& key = tokens[1];
        if (key == kShapeFamilyKey) {
            if (family_) reader.fail("header key '" + key + "' is repeated");
            family_ = tokens[2];
            if (!findShapeFamily(*family_))
                reader.fail("unknown shape family '" + *family_ +
                            "' (known: " + shapeFamilyNames() + ")");
        } else if (key == "n_particles") {
            if (count_) reader.fail("header key 'n_particles' is repeated");
            count_ = reader.parseCount(tokens[2]);
        } else if (key == "seed") {
            if (seed_) reader.fail("header key 'seed' is repeated");
            seed_ = reader.parseSeed(tokens[2]);
        } else if (key == "reduced_pressure") {
            if (reducedPressure_) reader.fail("header key 'reduced_pressure' is repeated");
            reducedPressure_ = reader.parseDouble(tokens[2]);
        } else if (const auto it = values_.find(key); it != values_.end()) {
            if (it->second) reader.fail("header key '" + key + "' is repeated");
            it->second = reader.parseDouble(tokens[2]);
            lines_[key] = reader.line();
        }
    }
    /// Fails naming the first key missing: the shape's parameters, semi_axis, box_length and
    /// n_particles.
    void requireComplete(LineReader& reader) const {
        const ShapeFamily& family = *writtenShapeFamily(family_);
        for (const ShapeParameter& parameter : family.parameters)
            if (!values_.at(std::string(parameter.name)))
                reader.fail("missing header key '" + std::string(parameter.name) +
                            "' before the particles");
        for (const char* key : {"semi_axis", "box_length"})
            if (!values_.at(key))
                reader.fail("missing header key '" + std::string(key) + "' before the particles");
        if (!count_) reader.fail("missing header key 'n_particles' before the particles");
    }
    long long count() const { return *count_; }
    double value(const std::string& key) const { return *values_.at(key); }
    /// The line a key was read from.
    int lineOf(const std::string& key) const { return lines_.at(key); }
    /// The shape of the header's family (the superball where it names none) and parameters.
    ShapeSpec shape() const {
        return ShapeSpec::read(family_,
                               [&](std::string_view name) { return value(std::string(name)); });
    }
    /// The optional keys, where given.
    void setOptional(Packing& packing) const {
        packing.reducedPressure = reducedPressure_;
        packing.seed = seed_;
    }

  private:
    std::optional<double> reducedPressure_;
    std::optional<std::uint64_t> seed_;
    std::optional<std::string> family_;
    /// The numbers a header may give: every family's parameters (its family, named or the
    /// superball, requires its own), semi_axis and box_length.
    std::map<std::string, std::optional<double>> values_ = [] {
        std::map<std::string, std::optional<double>> keys = {{"semi_axis", std::nullopt},
                                                             {"box_length", std::nullopt}};
        for (const ShapeFamily& family : shapeFamilies())
            for (const ShapeParameter& parameter : family.parameters)
                keys.try_emplace(std::string(parameter.name));
        return keys;
    }();
    std::map<std::string, int> lines_;
    std::optional<long long> count_;
};

/// One particle line, x y z qw qx qy qz, and a mixture's semi-axis where the first particle
/// line has eight numbers (every line as many), appended to `packing` and `semiAxes`.
void readParticle(const std::vector<std::string>& tokens, LineReader& reader, Packing& packing,
                  std::vector<double>& semiAxes) {
    const bool first = packing.positions.empty();
    const bool sized = first ? tokens.size() == 8 : !semiAxes.empty();
    if (tokens.size() != (sized ? 8u : 7u))
        reader.fail(sized ? "expected 8 numbers (x y z qw qx qy qz semi_axis) as on the first "
                            "particle line, found " +
                                std::to_string(tokens.size())
                          : "expected 7 numbers (x y z qw qx qy qz), or 8 with a mixture's "
                            "semi_axis on every line, found " +
                                std::to_string(tokens.size()));
    double v[8];
    for (std::size_t k = 0; k < tokens.size(); ++k)
        v[k] = reader.parseDouble(tokens[k]);
    packing.positions.emplace_back(v[0], v[1], v[2]);
    packing.orientations.emplace_back(v[3], v[4], v[5], v[6]);
    if (sized) semiAxes.push_back(v[7]);
}

} // namespace

Packing readTextPacking(const fs::path& file) {
    LineReader reader(file);
    std::string line;
    if (!reader.next(line) || line != kTextMagic)
        reader.fail("not an sbpack text packing (the first line must be '" +
                    std::string(kTextMagic) + "')");
    TextHeader header;
    Packing packing;
    std::vector<double> semiAxes; // a mixture's, from an eighth column
    while (reader.next(line)) {
        const std::vector<std::string> tokens = splitWhitespace(line);
        if (tokens.empty()) continue;
        if (tokens.front().starts_with('#')) {
            if (packing.positions.empty()) header.read(tokens, reader); // else a free comment
            continue;
        }
        if (packing.positions.empty()) header.requireComplete(reader);
        readParticle(tokens, reader, packing, semiAxes);
    }
    header.requireComplete(reader);
    if (static_cast<long long>(packing.positions.size()) != header.count())
        throw PackingFileError("'" + reader.name() + "': header says n_particles " +
                               std::to_string(header.count()) + " but the file has " +
                               std::to_string(packing.positions.size()) +
                               " particle lines (wrong particle count)");
    packing.shapeSpec = header.shape();
    readSemiAxes(semiAxes, header.value("semi_axis"), packing, reader, "the semi_axis column",
                 header.lineOf("semi_axis"));
    packing.boxLength = header.value("box_length");
    header.setOptional(packing);
    validatePacking(packing, reader.name());
    canonicalizePacking(packing);
    return packing;
}

void writeExtendedXyz(const Packing& packing, const fs::path& file) {
    validatePacking(packing, file.string());
    const std::string length = full(packing.boxLength);
    const std::string semiAxis = full(packing.semiAxis);
    // OVITO's superquadric (howto "Non-spherical particle shapes", ShapeSpec::superquadric):
    // (phi, theta) the "Superquadric Roundness", (a, b, c) the "Aspherical Shape" semi-axes.
    // OVITO's "Orientation" is the quaternion (x, y, z, w) rotating the shape into the lab frame.
    const Superquadric shape = packing.shapeSpec.superquadric();
    const std::string roundness = full(2.0 / shape.eastWest) + ' ' + full(2.0 / shape.northSouth);
    std::string species(packing.shapeSpec.info().name);
    species[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(species[0])));
    writeTextFile(file, [&](std::ostream& out) {
        out << packing.size() << "\nLattice=\"" << length << " 0 0 0 " << length << " 0 0 0 "
            << length << "\" Origin=\"0 0 0\" pbc=\"T T T\" "
            << "Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:"
            << "superquadric_roundness:R:2";
        if (const auto family = packing.shapeSpec.writtenFamily())
            out << ' ' << kShapeFamilyKey << '=' << *family;
        for (const auto& [name, value] : packing.shapeSpec.namedValues())
            out << ' ' << name << '=' << full(value);
        out << " semi_axis=" << semiAxis << "\n";
        for (std::size_t i = 0; i < packing.size(); ++i) {
            const Vector3d r = wrapIntoBox(packing.positions[i], packing.boxLength);
            const Quaterniond q = packing.orientations[i].normalized();
            // A mixture's particle at its own size (docs/mixtures.md); the header's the largest.
            const double own = packing.semiAxisOf(i);
            out << species << ' ' << full(r.x()) << ' ' << full(r.y()) << ' ' << full(r.z()) << ' '
                << full(q.x()) << ' ' << full(q.y()) << ' ' << full(q.z()) << ' ' << full(q.w())
                << ' ' << full(own * shape.axes.x()) << ' ' << full(own * shape.axes.y()) << ' '
                << full(own * shape.axes.z()) << ' ' << roundness << '\n';
        }
    });
}

namespace {

/// The comment line of an extended-XYZ frame as key=value pairs, keys in lower case, values
/// unquoted ("..." may hold blanks).
std::map<std::string, std::string> xyzKeys(const std::string& line, const LineReader& reader) {
    std::map<std::string, std::string> keys;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        if (i == line.size()) break;
        const std::size_t equals = line.find('=', i);
        if (equals == std::string::npos) reader.fail("'" + line.substr(i) + "' is not key=value");
        std::string key = line.substr(i, equals - i);
        for (char& c : key)
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        i = equals + 1;
        std::string value;
        if (i < line.size() && line[i] == '"') {
            const std::size_t close = line.find('"', i + 1);
            if (close == std::string::npos) reader.fail("the value of '" + key + "' is not closed");
            value = line.substr(i + 1, close - i - 1);
            i = close + 1;
        } else {
            const std::size_t end = line.find_first_of(" \t", i);
            value = line.substr(i, end == std::string::npos ? std::string::npos : end - i);
            i = end == std::string::npos ? line.size() : end;
        }
        keys[key] = value;
    }
    return keys;
}

/// The columns of the Properties key: name (lower case, without '_': OVITO writes
/// SuperquadricRoundness for superquadric_roundness) to its first column and width.
struct XyzColumns {
    std::map<std::string, std::pair<std::size_t, std::size_t>> at;
    std::size_t count = 0;
};

XyzColumns xyzColumns(const std::string& properties, const LineReader& reader) {
    XyzColumns c;
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
        const std::size_t colon = properties.find(':', start);
        parts.push_back(properties.substr(start, colon - start));
        if (colon == std::string::npos) break;
        start = colon + 1;
    }
    if (parts.size() % 3 != 0)
        reader.fail("Properties='" + properties + "' is not name:type:count");
    for (std::size_t k = 0; k < parts.size(); k += 3) {
        std::string name;
        for (char ch : parts[k])
            if (ch != '_') name += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        const long long width = reader.parseCount(parts[k + 2]);
        c.at[name] = {c.count, static_cast<std::size_t>(width)};
        c.count += static_cast<std::size_t>(width);
    }
    for (const char* required : {"pos"})
        if (!c.at.count(required)) reader.fail("Properties has no '" + std::string(required) + "'");
    return c;
}

/// L of a cubic Lattice="L 0 0 0 L 0 0 0 L"; fails on any other cell.
double cubicLattice(const std::string& lattice, const LineReader& reader) {
    const std::vector<std::string> tokens = splitWhitespace(lattice);
    if (tokens.size() != 9) reader.fail("Lattice=\"" + lattice + "\" is not 9 numbers");
    std::vector<double> v;
    for (const std::string& t : tokens)
        v.push_back(reader.parseDouble(t));
    for (int k : {1, 2, 3, 5, 6, 7})
        if (v[k] != 0.0) reader.fail("Lattice is not a cube (only cubic periodic boxes are read)");
    if (v[0] != v[4] || v[0] != v[8])
        reader.fail("Lattice is not a cube (edges " + tokens[0] + ", " + tokens[4] + ", " +
                    tokens[8] + ")");
    return v[0];
}

/// The comment line's shape: the family `shape=` names (the superball where none) with each of
/// its parameters under its own key; nothing where one is missing (the roundness column gives
/// the shape then).
template <class Key, class Number>
std::optional<ShapeSpec> xyzHeaderShape(const Key& key, const Number& number,
                                        const LineReader& reader) {
    const std::optional<std::string> family = key(kShapeFamilyKey);
    if (!writtenShapeFamily(family))
        reader.failAt(2, fmt::format("{}={} is no shape family sbpack knows ({})", kShapeFamilyKey,
                                     *family, shapeFamilyNames()));
    return ShapeSpec::readIfGiven(family,
                                  [&](std::string_view name) { return number(std::string(name)); });
}

/// Refuses aspherical_shape columns whose proportions are not those of the header's shape.
void refuseOtherProportions(const ShapeSpec& header, const Vector3d& proportions,
                            const LineReader& reader) {
    const Vector3d own = header.superquadric().axes;
    if ((proportions - own).cwiseAbs().maxCoeff() <= 1e-12) return;
    reader.failAt(2, fmt::format("aspherical_shape's proportions {}:{}:{} are not those of the "
                                 "header's shape, {} ({}:{}:{})",
                                 proportions.x(), proportions.y(), proportions.z(),
                                 header.describe(), own.x(), own.y(), own.z()));
}

} // namespace

Packing readExtendedXyz(const fs::path& file) {
    LineReader reader(file);
    std::string line;
    if (!reader.next(line)) reader.fail("empty: extended XYZ starts with the particle count");
    const long long count = reader.parseCount(line);
    if (!reader.next(line)) reader.fail("no comment line (Lattice, Properties)");
    const std::map<std::string, std::string> keys = xyzKeys(line, reader);
    auto key = [&](const std::string& name) {
        const auto it = keys.find(name);
        return it == keys.end() ? std::optional<std::string>() : std::optional(it->second);
    };
    if (!key("lattice")) reader.fail("no Lattice: the periodic box is needed");
    if (!key("properties")) reader.fail("no Properties");
    const XyzColumns columns = xyzColumns(*key("properties"), reader);
    auto number = [&](const std::string& name) {
        return key(name) ? std::optional(reader.parseDouble(*key(name))) : std::nullopt;
    };
    const std::optional<ShapeSpec> headerShape = xyzHeaderShape(key, number, reader);
    const auto headerRoundness = [&](double Superquadric::*blockiness) {
        return headerShape ? std::optional(2.0 / (headerShape->superquadric().*blockiness))
                           : std::nullopt;
    };
    UniformColumn phi("superquadric_roundness (phi)", headerRoundness(&Superquadric::eastWest));
    UniformColumn theta("superquadric_roundness (theta)",
                        headerRoundness(&Superquadric::northSouth));
    AxesColumns axes;
    const std::optional<double> headerSemiAxis = number("semi_axis");
    std::vector<double> semiAxes; // each particle's, from aspherical_shape
    Packing packing;
    packing.boxLength = cubicLattice(*key("lattice"), reader);
    const auto column = [&](const char* name) {
        const auto it = columns.at.find(name);
        return it == columns.at.end() ? nullptr : &it->second;
    };
    while (static_cast<long long>(packing.positions.size()) < count && reader.next(line)) {
        const std::vector<std::string> tokens = splitWhitespace(line);
        if (tokens.size() != columns.count)
            reader.fail(std::to_string(tokens.size()) + " columns, Properties gives " +
                        std::to_string(columns.count));
        auto value = [&](const std::pair<std::size_t, std::size_t>& c, std::size_t k) {
            return reader.parseDouble(tokens[c.first + k]);
        };
        const auto& pos = *column("pos");
        packing.positions.emplace_back(value(pos, 0), value(pos, 1), value(pos, 2));
        if (const auto* q = column("orientation"))
            packing.orientations.emplace_back(value(*q, 3), value(*q, 0), value(*q, 1),
                                              value(*q, 2)); // OVITO's (x, y, z, w)
        else
            packing.orientations.push_back(Quaterniond::Identity());
        if (const auto* r = column("superquadricroundness")) {
            phi.column(value(*r, 0), reader); // one column: phi = theta
            theta.column(value(*r, r->second - 1), reader);
        }
        if (const auto* a = column("asphericalshape")) {
            if (a->second != 3) reader.fail("aspherical_shape needs its three semi-axes");
            semiAxes.push_back(
                axes.size(Vector3d(value(*a, 0), value(*a, 1), value(*a, 2)), reader));
        }
    }
    if (static_cast<long long>(packing.positions.size()) != count)
        reader.fail("the header says " + std::to_string(count) + " particles but the file has " +
                    std::to_string(packing.positions.size()));
    // The header's parameters as written, its proportions those of the particles' axes where
    // they are given; only a shape from the roundness column is inverted and repaired.
    if (headerShape) refuseOtherProportions(*headerShape, axes.proportions(), reader);
    if (!headerShape && !phi.has())
        reader.failAt(2, "no shape: give the header's parameters (p=...) or the "
                         "superquadric_roundness column");
    packing.shapeSpec = headerShape ? *headerShape
                                    : superquadricShape({axes.proportions(), 2.0 / phi.valueOr(1.0),
                                                         2.0 / theta.valueOr(1.0)},
                                                        true, reader);
    readSemiAxes(semiAxes, headerSemiAxis, packing, reader, "aspherical_shape");
    if (!column("orientation") && !packing.shapeSpec.isSphere())
        reader.failAt(
            2, "no orientation column: particles other than spheres need their orientations");
    validatePacking(packing, reader.name());
    canonicalizePacking(packing);
    return packing;
}

} // namespace sbpack

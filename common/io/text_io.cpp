#include "io/text_io.hpp"

#include "io/atomic_file.hpp"
#include "packing/validation.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace sbpack {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTextMagic = "# sbpack text packing v1";

/// 17 significant digits (%.17g): every double reads back bit for bit.
std::string full(double x) {
    char buffer[32];
    return std::string(
        buffer,
        std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, 17).ptr);
}

/// Writes what `body` puts into a stream through AtomicOutput (checked writes).
template <typename Body> void writeTextFile(const fs::path& file, Body body) {
    AtomicOutput output(file);
    std::ostringstream out;
    body(out);
    output.write(out.str());
    output.commit();
}

std::vector<std::string> splitWhitespace(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> tokens;
    for (std::string token; in >> token;)
        tokens.push_back(token);
    return tokens;
}

/// Reads the text file line by line and names the file and line in every error.
class LineReader {
  public:
    /// The file is checked (checkInputFile) before it is opened.
    explicit LineReader(const fs::path& file)
        : name_((checkInputFile(file), file.string())), in_(file) {
        if (!in_) throw PackingFileError("'" + name_ + "': cannot open for reading");
    }

    /// The next line without its line end (LF or CRLF) and trailing blanks, and on the first line
    /// without a UTF-8 byte-order mark (issue 65 item 8: editors on Windows add both).
    bool next(std::string& line) {
        if (!std::getline(in_, line)) return false;
        if (number_ == 0 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
            line.pop_back();
        ++number_;
        return true;
    }

    [[noreturn]] void fail(const std::string& problem) const {
        throw PackingFileError("'" + name_ + "', line " + std::to_string(number_) + ": " + problem);
    }

    double parseDouble(std::string token) const {
        if (!token.empty() && token.front() == '+') token.erase(0, 1);
        double value = 0.0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec != std::errc() || end != token.data() + token.size())
            fail("'" + token + "' is not a number");
        return value;
    }

    long long parseCount(const std::string& token) const {
        long long value = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec != std::errc() || end != token.data() + token.size() || value <= 0)
            fail("'" + token + "' is not a positive particle count");
        return value;
    }

    std::uint64_t parseSeed(const std::string& token) const {
        std::uint64_t value = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec != std::errc() || end != token.data() + token.size())
            fail("'" + token + "' is not a seed (an integer in [0, 2^64))");
        return value;
    }

    const std::string& name() const { return name_; }

  private:
    std::string name_;
    std::ifstream in_;
    int number_ = 0;
};

} // namespace

void writeTextPacking(const Packing& packing, const fs::path& file) {
    validatePacking(packing, file.string());
    writeTextFile(file, [&](std::ostream& out) {
        out << kTextMagic << "\n# p " << full(packing.p) << "\n# semi_axis "
            << full(packing.semiAxis) << "\n# box_length " << full(packing.boxLength)
            << "\n# n_particles " << packing.size() << '\n';
        if (packing.reducedPressure)
            out << "# reduced_pressure " << full(*packing.reducedPressure) << '\n';
        if (packing.seed) out << "# seed " << *packing.seed << '\n';
        out << "# columns x y z qw qx qy qz\n";
        for (std::size_t i = 0; i < packing.size(); ++i) {
            const Vector3d r = wrapIntoBox(packing.positions[i], packing.boxLength);
            const Quaterniond& q = packing.orientations[i];
            out << full(r.x()) << ' ' << full(r.y()) << ' ' << full(r.z()) << ' ' << full(q.w())
                << ' ' << full(q.x()) << ' ' << full(q.y()) << ' ' << full(q.z()) << '\n';
        }
    });
}

Packing readPackingFile(const fs::path& file) {
    return file.extension() == ".txt" ? readTextPacking(file) : readPacking(file);
}

namespace {

/// The header of a text packing: "# key value" lines before the first particle line.
class TextHeader {
  public:
    /// Reads a comment line's key if it is a header key (others are free comments).
    void read(const std::vector<std::string>& tokens, LineReader& reader) {
        if (tokens.front() != "#" || tokens.size() != 3) return;
        const std::string& key = tokens[1];
        if (key == "n_particles") {
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
        }
    }
    /// Fails naming the first key missing.
    void requireComplete(LineReader& reader) const {
        for (const auto& [key, value] : values_)
            if (!value) reader.fail("missing header key '" + key + "' before the particles");
        if (!count_) reader.fail("missing header key 'n_particles' before the particles");
    }
    long long count() const { return *count_; }
    double value(const std::string& key) const { return *values_.at(key); }
    /// The optional keys, where given.
    void setOptional(Packing& packing) const {
        packing.reducedPressure = reducedPressure_;
        packing.seed = seed_;
    }

  private:
    std::optional<double> reducedPressure_;
    std::optional<std::uint64_t> seed_;
    std::map<std::string, std::optional<double>> values_ = {
        {"p", std::nullopt}, {"semi_axis", std::nullopt}, {"box_length", std::nullopt}};
    std::optional<long long> count_;
};

/// One particle line, x y z qw qx qy qz, appended to `packing`.
void readParticle(const std::vector<std::string>& tokens, LineReader& reader, Packing& packing) {
    if (tokens.size() != 7)
        reader.fail("expected 7 numbers (x y z qw qx qy qz), found " +
                    std::to_string(tokens.size()));
    double v[7];
    for (int k = 0; k < 7; ++k)
        v[k] = reader.parseDouble(tokens[k]);
    packing.positions.emplace_back(v[0], v[1], v[2]);
    packing.orientations.emplace_back(v[3], v[4], v[5], v[6]);
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
    while (reader.next(line)) {
        const std::vector<std::string> tokens = splitWhitespace(line);
        if (tokens.empty()) continue;
        if (tokens.front().starts_with('#')) {
            if (packing.positions.empty()) header.read(tokens, reader); // else a free comment
            continue;
        }
        if (packing.positions.empty()) header.requireComplete(reader);
        readParticle(tokens, reader, packing);
    }
    header.requireComplete(reader);
    if (static_cast<long long>(packing.positions.size()) != header.count())
        throw PackingFileError("'" + reader.name() + "': header says n_particles " +
                               std::to_string(header.count()) + " but the file has " +
                               std::to_string(packing.positions.size()) +
                               " particle lines (wrong particle count)");
    packing.p = header.value("p");
    packing.semiAxis = header.value("semi_axis");
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
    // OVITO's superquadric (howto "Non-spherical particle shapes"):
    // (|x/a|^(2/phi) + |y/b|^(2/phi))^(phi/theta) + |z/c|^(2/theta) = 1, with (phi, theta) the
    // "Superquadric Roundness" and (a, b, c) the "Aspherical Shape" semi-axes; our superball
    // |x|^2p + |y|^2p + |z|^2p = R^2p is phi = theta = 1/p, a = b = c = R. OVITO's
    // "Orientation" is the quaternion (x, y, z, w) rotating the shape into the lab frame.
    const std::string roundness = full(1.0 / packing.p);
    writeTextFile(file, [&](std::ostream& out) {
        out << packing.size() << "\nLattice=\"" << length << " 0 0 0 " << length << " 0 0 0 "
            << length << "\" Origin=\"0 0 0\" pbc=\"T T T\" "
            << "Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:"
            << "superquadric_roundness:R:2 p=" << full(packing.p) << " semi_axis=" << semiAxis
            << "\n";
        for (std::size_t i = 0; i < packing.size(); ++i) {
            const Vector3d r = wrapIntoBox(packing.positions[i], packing.boxLength);
            const Quaterniond q = packing.orientations[i].normalized();
            out << "Superball " << full(r.x()) << ' ' << full(r.y()) << ' ' << full(r.z()) << ' '
                << full(q.x()) << ' ' << full(q.y()) << ' ' << full(q.z()) << ' ' << full(q.w())
                << ' ' << semiAxis << ' ' << semiAxis << ' ' << semiAxis << ' ' << roundness << ' '
                << roundness << '\n';
        }
    });
}

std::vector<std::string> notCarriedBy(const Packing& packing, bool extendedXyz) {
    std::vector<std::string> left;
    if (extendedXyz && packing.reducedPressure) left.emplace_back("reduced_pressure");
    if (extendedXyz && packing.seed) left.emplace_back("seed");
    if (!packing.velocities.empty()) left.emplace_back("velocities");
    if (!packing.angularVelocities.empty()) left.emplace_back("angular velocities");
    if (!packing.provenance.empty() || !packing.generatorVersion.empty())
        left.emplace_back("provenance");
    if (packing.contactForces) left.emplace_back("contact forces");
    if (!packing.resumeState.empty() || !packing.pairRecords.empty())
        left.emplace_back("resume state (a checkpoint's)");
    return left;
}

} // namespace sbpack

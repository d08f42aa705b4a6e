#pragma once
// Line-oriented text files, shared by the text formats' readers and writers (io/text_io.cpp,
// io/lammps_io.cpp): full-precision numbers, atomic writes, and a line reader whose every error
// names the file and line.

#include "io/atomic_file.hpp"
#include "io/packing_io.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sbpack::text {

namespace fs = std::filesystem;

/// 17 significant digits (%.17g): every double reads back bit for bit.
inline std::string full(double x) {
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

inline std::vector<std::string> splitWhitespace(const std::string& line) {
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

    /// The number of the line last read (1 for the first).
    int line() const { return number_; }
    [[noreturn]] void fail(const std::string& problem) const { failAt(number_, problem); }
    /// Names an earlier line (a header's problem found at the end).
    [[noreturn]] void failAt(int line, const std::string& problem) const {
        throw PackingFileError("'" + name_ + "', line " + std::to_string(line) + ": " + problem);
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

/// One shape value of a text file (a superquadric roundness or blockiness): the header's where
/// there is one, else the column's value, the same in every particle (the header and the columns
/// must agree to 1e-12).
class UniformColumn {
  public:
    UniformColumn(std::string key, std::optional<double> header)
        : key_(std::move(key)), value_(header) {}
    void column(double v, const LineReader& reader) {
        if (!value_) value_ = v;
        if (std::abs(v - *value_) > 1e-12 * std::abs(*value_))
            reader.fail("the particles differ in " + key_ +
                        " (only particles of one shape, at their own sizes, are read)");
    }
    bool has() const { return value_.has_value(); }
    /// The value, or `absent` where there is none.
    double valueOr(double absent) const { return value_.value_or(absent); }

  private:
    std::string key_;
    std::optional<double> value_;
};

/// The particles' semi-axes (a, b, c) as a file's shape columns give them: each particle's size
/// (its largest) and the shape's proportions (a, b, c over the size), which every particle must
/// share to 1e-12.
class AxesColumns {
  public:
    double size(const Vector3d& axes, const LineReader& reader) {
        const double largest = axes.maxCoeff();
        if (!(largest > 0.0)) return largest; // refused by the packing's validation
        const Vector3d proportions = axes / largest;
        if (!proportions_) proportions_ = proportions;
        if ((proportions - *proportions_).cwiseAbs().maxCoeff() > 1e-12)
            reader.fail("the particles' semi-axes differ in proportion, not only in size (only "
                        "particles of one shape, at their own sizes, are read)");
        return largest;
    }
    /// The proportions (1, 1, 1 where no particle gave its axes).
    Vector3d proportions() const { return proportions_.value_or(Vector3d::Ones()); }

  private:
    std::optional<Vector3d> proportions_;
};

/// A parameter from a value written in single precision (OVITO's export: 1 / 0.6666667008 =
/// 1.49999992): the value of 6 significant digits within 1e-7 of it, else the value itself.
inline double singlePrecisionRepaired(double value) {
    const double scale = std::pow(10.0, 5 - static_cast<int>(std::floor(std::log10(value))));
    const double rounded = std::round(value * scale) / scale;
    return std::abs(rounded - value) <= 1e-7 * value ? rounded : value;
}

/// The shape whose superquadric `q` is (ShapeSpec::fromSuperquadric), failing with the file and
/// line where no family has it; `repaired`: each parameter through singlePrecisionRepaired (a
/// roundness written in single precision).
inline ShapeSpec superquadricShape(const Superquadric& q, bool repaired, const LineReader& reader) {
    try {
        const ShapeSpec shape = ShapeSpec::fromSuperquadric(q);
        if (!repaired) return shape;
        std::vector<double> values = shape.values();
        for (double& v : values)
            v = singlePrecisionRepaired(v);
        return ShapeSpec::fromValues(shape.info().name, values);
    } catch (const std::invalid_argument& e) {
        reader.fail(e.what());
    }
}

/// The packing's sizes from each particle's semi-axis (may be none), read from `column`, and the
/// header's semi_axis (may be none; on line `headerLine`): identical particles where all agree
/// to 1e-12, else a mixture (docs/mixtures.md) whose largest is the header's where given (text,
/// extended XYZ, LAMMPS).
inline void readSemiAxes(const std::vector<double>& semiAxes, std::optional<double> header,
                         Packing& packing, const LineReader& reader, const std::string& column,
                         int headerLine = 2) {
    if (semiAxes.empty()) {
        if (!header) reader.failAt(headerLine, "no semi_axis: give the header key or " + column);
        packing.semiAxis = *header;
        return;
    }
    const auto [smallest, largest] = std::minmax_element(semiAxes.begin(), semiAxes.end());
    const double reference = header.value_or(*largest);
    if (std::abs(*largest - reference) > 1e-12 * reference)
        reader.failAt(headerLine, "the header's semi_axis is not the largest of " + column);
    packing.semiAxis = reference;
    if (*largest - *smallest > 1e-12 * *largest) packing.semiAxes = semiAxes;
}

} // namespace sbpack::text

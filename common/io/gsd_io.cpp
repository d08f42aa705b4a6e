#include "io/gsd_io.hpp"

#include "io/atomic_file.hpp"
#include "io/packing_io.hpp"
#include "packing/validation.hpp"

#include "third_party/gsd/gsd.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace fs = std::filesystem;

namespace sbpack {

namespace {

constexpr const char* kLog = "log/sbpack/";
constexpr const char* kParticleLog = "log/particles/sbpack/";

/// A gsd call's status as PackingFileError naming the file and what was done.
void check(int status, const fs::path& file, const std::string& what) {
    if (status != GSD_SUCCESS)
        throw PackingFileError(
            fmt::format("'{}': GSD: {} failed (gsd error {})", file.string(), what, status));
}

/// Points on the surface of the superquadric `q` at size `size` by its parametrisation
/// (a sgn(c) |c|^(2/n) ...; ShapeSpec::superquadric), dense at the edges of near-cubes as at
/// the poles; the hull OVITO builds from them is the shape.
std::vector<Vector3d> surfacePoints(const Superquadric& q, double size) {
    const auto power = [](double t, double n) {
        return std::copysign(std::pow(std::abs(t), 2.0 / n), t);
    };
    const Vector3d a = size * q.axes;
    constexpr int kLatitudes = 12, kLongitudes = 24;
    std::vector<Vector3d> points{{0.0, 0.0, a.z()}, {0.0, 0.0, -a.z()}};
    for (int i = 1; i < kLatitudes; ++i) {
        const double eta = std::numbers::pi * (static_cast<double>(i) / kLatitudes - 0.5);
        const double ring = power(std::cos(eta), q.northSouth);
        for (int j = 0; j < kLongitudes; ++j) {
            const double omega = 2.0 * std::numbers::pi * j / kLongitudes;
            points.emplace_back(a.x() * ring * power(std::cos(omega), q.eastWest),
                                a.y() * ring * power(std::sin(omega), q.eastWest),
                                a.z() * power(std::sin(eta), q.northSouth));
        }
    }
    return points;
}

/// The type_shapes JSON of the shape at size `size` (GSD's shape specification:
/// ConvexPolyhedron).
std::string shapeJson(const ShapeSpec& shape, double size) {
    std::string json = R"({"type": "ConvexPolyhedron", "rounding_radius": 0, "vertices": [)";
    const std::vector<Vector3d> points = surfacePoints(shape.superquadric(), size);
    for (std::size_t k = 0; k < points.size(); ++k)
        json += fmt::format("{}[{:.9g}, {:.9g}, {:.9g}]", k ? ", " : "", points[k].x(),
                            points[k].y(), points[k].z());
    return json + "]}";
}

/// A writer of one frame's chunks on an open handle.
class FrameWriter {
  public:
    FrameWriter(gsd_handle& handle, const fs::path& file) : handle_(handle), file_(file) {}

    template <class T>
    void chunk(const std::string& name, gsd_type type, std::uint64_t rows, std::uint32_t columns,
               const std::vector<T>& data) {
        check(gsd_write_chunk(&handle_, name.c_str(), type, rows, columns, 0, data.data()), file_,
              "writing " + name);
    }
    void scalar(const std::string& name, double value) {
        chunk(name, GSD_TYPE_DOUBLE, 1, 1, std::vector<double>{value});
    }
    /// NUL-terminated strings as int8 rows of one width.
    void strings(const std::string& name, const std::vector<std::string>& values) {
        std::size_t width = 1;
        for (const std::string& v : values)
            width = std::max(width, v.size() + 1);
        std::vector<std::int8_t> rows(values.size() * width, 0);
        for (std::size_t k = 0; k < values.size(); ++k)
            std::memcpy(rows.data() + k * width, values[k].data(), values[k].size());
        chunk(name, GSD_TYPE_INT8, values.size(), static_cast<std::uint32_t>(width), rows);
    }

  private:
    gsd_handle& handle_;
    fs::path file_;
};

/// The schema's single-precision position: centred on the origin, in [-L/2, L/2) after
/// rounding (a value that rounds onto L/2 goes to -L/2).
std::vector<float> centredPositions(const Packing& packing) {
    const double half = 0.5 * packing.boxLength;
    const float halfFloat = static_cast<float>(half);
    std::vector<float> out;
    out.reserve(3 * packing.size());
    for (const Vector3d& r : packing.positions) {
        const Vector3d centred = wrapIntoBox(r, packing.boxLength) - Vector3d::Constant(half);
        for (int k = 0; k < 3; ++k) {
            const auto x = static_cast<float>(centred[k]);
            out.push_back(x >= halfFloat ? -halfFloat : x);
        }
    }
    return out;
}

/// The chunks of one frame of an open file (the last; frame 0 for what the last lacks, as the
/// schema says), checked for type and size before they are read.
class FrameReader {
  public:
    explicit FrameReader(const fs::path& file) : file_(file) {
        check(gsd_open(&handle_, file.string().c_str(), GSD_OPEN_READONLY), file,
              "opening the file (not a GSD file, or truncated)");
        const std::uint64_t frames = gsd_get_nframes(&handle_);
        if (frames == 0) {
            gsd_close(&handle_);
            throw PackingFileError("'" + file.string() + "': GSD file without a frame");
        }
        frame_ = frames - 1;
        fileBytes_ = fs::file_size(file);
    }
    FrameReader(const FrameReader&) = delete;
    FrameReader& operator=(const FrameReader&) = delete;
    ~FrameReader() { gsd_close(&handle_); }

    /// The chunk as doubles (stored as float or double), rows x columns (rows 0: any); nullopt
    /// where absent.
    std::optional<std::vector<double>> numbers(const std::string& name, std::uint64_t rows,
                                               std::uint32_t columns) {
        const gsd_index_entry* e = find(name);
        if (!e) return std::nullopt;
        if ((e->type != GSD_TYPE_FLOAT && e->type != GSD_TYPE_DOUBLE) ||
            (rows != 0 && e->N != rows) || e->M != columns)
            fail(name, fmt::format("{} x {} floating-point numbers", rows ? rows : e->N, columns),
                 e);
        std::vector<double> out;
        if (e->type == GSD_TYPE_DOUBLE) {
            read(e, name, out);
            return out;
        }
        std::vector<float> single;
        read(e, name, single);
        return std::vector<double>(single.begin(), single.end());
    }
    /// An unsigned integer chunk of `rows` x 1 (uint8 to uint64) as uint64; nullopt if absent.
    std::optional<std::vector<std::uint64_t>> counts(const std::string& name, std::uint64_t rows);
    /// NUL-terminated int8 rows as strings; empty where absent.
    std::vector<std::string> strings(const std::string& name);

  private:
    const gsd_index_entry* find(const std::string& name) {
        const gsd_index_entry* e = gsd_find_chunk(&handle_, frame_, name.c_str());
        return e || frame_ == 0 ? e : gsd_find_chunk(&handle_, 0, name.c_str());
    }
    /// Reads the chunk into `out`, sized to it here: a chunk that claims more bytes than the
    /// file holds (a corrupt or hostile index, whose N x M the library does not check for
    /// overflow) is refused before anything is allocated.
    template <class T>
    void read(const gsd_index_entry* e, const std::string& name, std::vector<T>& out) {
        const std::uint64_t width = gsd_sizeof_type(static_cast<gsd_type>(e->type));
        if (width == 0 || e->M == 0 || e->N > fileBytes_ / e->M / width ||
            e->N * e->M * width % sizeof(T) != 0)
            throw PackingFileError(fmt::format("'{}': GSD chunk {} claims {} x {} values of type "
                                               "{}, more than the file holds",
                                               file_.string(), name, e->N, e->M, e->type));
        out.resize(e->N * e->M * width / sizeof(T));
        check(gsd_read_chunk(&handle_, out.data(), e), file_, "reading " + name);
    }
    [[noreturn]] void fail(const std::string& name, const std::string& expected,
                           const gsd_index_entry* e) const {
        throw PackingFileError(fmt::format("'{}': GSD chunk {} holds {} x {} of type {}, "
                                           "expected {}",
                                           file_.string(), name, e->N, e->M, e->type, expected));
    }

    gsd_handle handle_{};
    fs::path file_;
    std::uint64_t frame_ = 0;
    std::uint64_t fileBytes_ = 0;
};

std::optional<std::vector<std::uint64_t>> FrameReader::counts(const std::string& name,
                                                              std::uint64_t rows) {
    const gsd_index_entry* e = find(name);
    if (!e) return std::nullopt;
    if (e->type < GSD_TYPE_UINT8 || e->type > GSD_TYPE_UINT64 || e->N != rows || e->M != 1)
        fail(name, fmt::format("{} x 1 unsigned integers", rows), e);
    std::vector<std::uint8_t> bytes;
    read(e, name, bytes);
    std::vector<std::uint64_t> out(e->N);
    const std::size_t width = bytes.size() / e->N;
    for (std::size_t k = 0; k < out.size(); ++k) {
        std::uint64_t v = 0;
        std::memcpy(&v, bytes.data() + k * width, width); // little-endian, as GSD is
        out[k] = v;
    }
    return out;
}

std::vector<std::string> FrameReader::strings(const std::string& name) {
    const gsd_index_entry* e = find(name);
    if (!e) return {};
    if (e->type != GSD_TYPE_INT8 && e->type != GSD_TYPE_UINT8) fail(name, "int8 strings", e);
    std::vector<char> bytes;
    read(e, name, bytes);
    std::vector<std::string> out;
    for (std::size_t k = 0; k < e->N; ++k)
        out.emplace_back(bytes.data() + k * e->M, strnlen(bytes.data() + k * e->M, e->M));
    return out;
}

/// The shape sbpack's log gives: the family the first type names ("superball", "superball_0";
/// the superball where it names none), each parameter a scalar under its own name; nothing where
/// one is missing.
std::optional<ShapeSpec> loggedShape(FrameReader& frame) {
    const std::vector<std::string> types = frame.strings("particles/types");
    std::optional<std::string> family;
    if (!types.empty()) {
        std::string type = types.front();
        const std::size_t cut = type.find_last_of('_'); // a mixture's size index
        if (cut != std::string::npos && cut + 1 < type.size() &&
            type.find_first_not_of("0123456789", cut + 1) == std::string::npos)
            type.resize(cut);
        if (findShapeFamily(type)) family = type;
    }
    return ShapeSpec::readIfGiven(family, [&](std::string_view name) {
        const auto value = frame.numbers(std::string(kLog) + std::string(name), 1, 1);
        return value ? std::optional(value->front()) : std::nullopt;
    });
}

/// The shape and the semi-axis: sbpack's scalars, else one Sphere shape shared by every type.
std::pair<ShapeSpec, double> shapeOf(FrameReader& frame, const fs::path& file) {
    const auto a = frame.numbers(std::string(kLog) + "semi_axis", 1, 1);
    const std::optional<ShapeSpec> logged = loggedShape(frame);
    if (logged && a) return {*logged, a->front()};
    std::optional<double> diameter;
    for (const std::string& text : frame.strings("particles/type_shapes")) {
        const nlohmann::json shape = nlohmann::json::parse(text, nullptr, false);
        if (shape.is_discarded() || shape.value("type", "") != "Sphere" ||
            !shape.contains("diameter") || !shape["diameter"].is_number() ||
            (diameter && *diameter != shape["diameter"].get<double>()))
            throw PackingFileError(fmt::format(
                "'{}': GSD file without a shape sbpack reads: neither {}semi_axis with the "
                "shape's parameters (p) nor one Sphere type_shape shared by every type (found "
                "'{}')",
                file.string(), kLog, text.substr(0, 80)));
        diameter = shape["diameter"].get<double>();
    }
    if (!diameter)
        throw PackingFileError(fmt::format("'{}': GSD file without a shape: neither {}semi_axis "
                                           "with the shape's parameters (p) nor "
                                           "particles/type_shapes",
                                           file.string(), kLog));
    return {ShapeSpec::superball(1.0), 0.5 * *diameter};
}

/// The cubic box's edge: sbpack's scalar, else configuration/box with equal edges, no tilt.
double boxLengthOf(FrameReader& frame, const fs::path& file) {
    if (const auto l = frame.numbers(std::string(kLog) + "box_length", 1, 1)) return l->front();
    const auto box = frame.numbers("configuration/box", 6, 1);
    if (!box) throw PackingFileError("'" + file.string() + "': GSD file without configuration/box");
    const std::vector<double>& b = *box;
    if (b[1] != b[0] || b[2] != b[0] || b[3] != 0.0 || b[4] != 0.0 || b[5] != 0.0)
        throw PackingFileError(fmt::format("'{}': GSD box [{}] is not cubic (equal edges, no "
                                           "tilt): sbpack's boxes are",
                                           file.string(), fmt::join(b, ", ")));
    return b[0];
}

/// The particle types, named by the shape's family: one ("superball") of identical particles; a
/// mixture's one per distinct size ("superball_0", ... largest first), each its own shape, and
/// each particle's exact semi-axis in sbpack's log (docs/mixtures.md).
void writeTypes(const Packing& packing, FrameWriter& w) {
    const auto n = static_cast<std::uint32_t>(packing.size());
    const std::string family(packing.shapeSpec.info().name);
    if (!packing.isMixture()) {
        w.strings("particles/types", {family});
        w.strings("particles/type_shapes", {shapeJson(packing.shapeSpec, packing.semiAxis)});
        w.chunk("particles/typeid", GSD_TYPE_UINT32, n, 1, std::vector<std::uint32_t>(n, 0));
        return;
    }
    std::vector<double> sizes = packing.semiAxes;
    std::sort(sizes.begin(), sizes.end(), std::greater<>());
    sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
    std::vector<std::string> names, shapes;
    for (std::size_t t = 0; t < sizes.size(); ++t) {
        names.push_back(family + "_" + std::to_string(t));
        shapes.push_back(shapeJson(packing.shapeSpec, sizes[t]));
    }
    std::vector<std::uint32_t> typeId;
    for (const double r : packing.semiAxes)
        typeId.push_back(
            static_cast<std::uint32_t>(std::find(sizes.begin(), sizes.end(), r) - sizes.begin()));
    w.strings("particles/types", names);
    w.strings("particles/type_shapes", shapes);
    w.chunk("particles/typeid", GSD_TYPE_UINT32, n, 1, typeId);
    w.chunk(std::string(kParticleLog) + "semi_axis", GSD_TYPE_DOUBLE, n, 1, packing.semiAxes);
}

void writeFrame(const Packing& packing, FrameWriter& w) {
    const auto n = static_cast<std::uint32_t>(packing.size());
    const auto length = static_cast<float>(packing.boxLength);
    w.chunk("configuration/step", GSD_TYPE_UINT64, 1, 1, std::vector<std::uint64_t>{0});
    w.chunk("configuration/box", GSD_TYPE_FLOAT, 6, 1,
            std::vector<float>{length, length, length, 0.0F, 0.0F, 0.0F});
    w.chunk("particles/N", GSD_TYPE_UINT32, 1, 1, std::vector<std::uint32_t>{n});
    writeTypes(packing, w);
    w.chunk("particles/position", GSD_TYPE_FLOAT, n, 3, centredPositions(packing));
    std::vector<float> q;
    std::vector<double> exactPositions, exactOrientations;
    for (std::size_t i = 0; i < packing.size(); ++i) {
        const Quaterniond o = packing.orientations[i];
        for (const double c : {o.w(), o.x(), o.y(), o.z()}) {
            q.push_back(static_cast<float>(c));
            exactOrientations.push_back(c);
        }
        for (int k = 0; k < 3; ++k)
            exactPositions.push_back(packing.positions[i][k]);
    }
    w.chunk("particles/orientation", GSD_TYPE_FLOAT, n, 4, q);
    w.chunk(std::string(kParticleLog) + "position", GSD_TYPE_DOUBLE, n, 3, exactPositions);
    w.chunk(std::string(kParticleLog) + "orientation", GSD_TYPE_DOUBLE, n, 4, exactOrientations);
    for (const auto& [name, value] : packing.shapeSpec.namedValues())
        w.scalar(std::string(kLog) + std::string(name), value);
    w.scalar(std::string(kLog) + "semi_axis", packing.semiAxis);
    w.scalar(std::string(kLog) + "box_length", packing.boxLength);
    if (packing.reducedPressure)
        w.scalar(std::string(kLog) + "reduced_pressure", *packing.reducedPressure);
    if (packing.seed)
        w.chunk(std::string(kLog) + "seed", GSD_TYPE_UINT64, 1, 1,
                std::vector<std::uint64_t>{*packing.seed});
}

} // namespace

void writeGsd(const Packing& packing, const fs::path& file) {
    validatePacking(packing, file.string());
    AtomicOutput output(file);
    const std::string temporary = output.temporaryPath().string();
    // Made here first, so that it gets the permissions of every other sbpack output (0666 less
    // the umask); gsd would create it 0660 (group-writable, not readable by others).
    std::ofstream(output.temporaryPath()).close();
    gsd_handle handle{};
    check(gsd_create_and_open(&handle, temporary.c_str(), "sbpack", "hoomd", gsd_make_version(1, 4),
                              GSD_OPEN_APPEND, 0),
          file, "creating the file");
    try {
        FrameWriter writer(handle, file);
        writeFrame(packing, writer);
        check(gsd_end_frame(&handle), file, "ending the frame");
    } catch (...) {
        gsd_close(&handle);
        throw;
    }
    check(gsd_close(&handle), file, "closing the file");
    output.commit();
}

Packing readGsd(const fs::path& file) {
    checkInputFile(file);
    FrameReader frame(file);
    Packing packing;
    std::tie(packing.shapeSpec, packing.semiAxis) = shapeOf(frame, file);
    packing.boxLength = boxLengthOf(frame, file);
    const auto n = frame.counts("particles/N", 1);
    if (!n || n->front() == 0)
        throw PackingFileError("'" + file.string() + "': GSD file without particles (particles/N)");
    const std::uint64_t count = n->front();
    const auto exact = frame.numbers(std::string(kParticleLog) + "position", count, 3);
    const auto single = exact ? exact : frame.numbers("particles/position", count, 3);
    if (!single)
        throw PackingFileError("'" + file.string() + "': GSD file without particles/position");
    const double shift = exact ? 0.0 : 0.5 * packing.boxLength; // the schema's box is centred
    for (std::uint64_t i = 0; i < count; ++i) // wrapped into [0, L) by canonicalizePacking
        packing.positions.push_back(
            Vector3d((*single)[3 * i], (*single)[3 * i + 1], (*single)[3 * i + 2]) +
            Vector3d::Constant(shift));
    auto q = frame.numbers(std::string(kParticleLog) + "orientation", count, 4);
    if (!q) q = frame.numbers("particles/orientation", count, 4);
    for (std::uint64_t i = 0; i < count; ++i)
        packing.orientations.push_back(
            q ? Quaterniond((*q)[4 * i], (*q)[4 * i + 1], (*q)[4 * i + 2], (*q)[4 * i + 3])
              : Quaterniond::Identity()); // normalised by canonicalizePacking
    if (const auto sizes = frame.numbers(std::string(kParticleLog) + "semi_axis", count, 1))
        packing.semiAxes = *sizes; // a mixture's (docs/mixtures.md)
    if (const auto pressure = frame.numbers(std::string(kLog) + "reduced_pressure", 1, 1))
        packing.reducedPressure = pressure->front();
    if (const auto seed = frame.counts(std::string(kLog) + "seed", 1)) packing.seed = seed->front();
    canonicalizePacking(packing);
    validatePacking(packing, file.string());
    return packing;
}

} // namespace sbpack

#include "io/hdf5_handles.hpp"

#include <limits>
#include <utility>

namespace sbpack {

namespace fs = std::filesystem;

namespace {

herr_t keepInnermost(unsigned n, const H5E_error2_t* error, void* reason) {
    if (n == 0 && error->desc != nullptr) *static_cast<std::string*>(reason) = error->desc;
    return 0;
}

/// HDF5's innermost reason for the failure that just happened; read it before any other call,
/// since every API call clears the error stack.
std::string hdf5Reason() {
    std::string reason;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keepInnermost, &reason);
    return reason.empty() ? std::string("unknown HDF5 error") : reason;
}

void silenceHdf5ErrorPrinting() {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

std::string nameFrom(ssize_t (*query)(hid_t, char*, size_t), hid_t id) {
    const ssize_t n = query(id, nullptr, 0);
    if (n <= 0) return "?";
    std::string name(static_cast<std::size_t>(n) + 1, '\0');
    query(id, name.data(), name.size());
    name.resize(static_cast<std::size_t>(n));
    return name;
}

ssize_t fileNameQuery(hid_t id, char* buffer, size_t size) {
    return H5Fget_name(id, buffer, size);
}
ssize_t objectNameQuery(hid_t id, char* buffer, size_t size) {
    return H5Iget_name(id, buffer, size);
}

/// "'file.h5': dataset '/positions'" or "'file.h5': attribute 'p' of '/'".
std::string describe(hid_t location, const std::string& name, const std::string& kind) {
    const std::string file = nameFrom(fileNameQuery, location);
    const std::string parent = nameFrom(objectNameQuery, location);
    if (kind == "attribute") return "'" + file + "': attribute '" + name + "' of '" + parent + "'";
    const std::string path = parent == "/" ? "/" + name : parent + "/" + name;
    return "'" + file + "': " + kind + " '" + path + "'";
}

/// Returns `result` unless it signals failure, in which case throws naming the object.
template <typename T>
T checked(T result, hid_t location, const std::string& name, const std::string& kind,
          const std::string& action) {
    if (result >= 0) return result;
    const std::string reason = hdf5Reason();
    throw Hdf5Error(describe(location, name, kind) + ": cannot " + action + " (" + reason + ")");
}

[[noreturn]] void fail(hid_t location, const std::string& name, const std::string& kind,
                       const std::string& problem) {
    throw Hdf5Error(describe(location, name, kind) + ": " + problem);
}

Hdf5Handle openAttribute(hid_t object, const std::string& name) {
    if (!hasAttribute(object, name)) fail(object, name, "attribute", "missing");
    return Hdf5Handle(
        checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), object, name, "attribute", "open"),
        H5Aclose);
}

/// Opens a scalar attribute of the given class and returns (attribute, its file type).
std::pair<Hdf5Handle, Hdf5Handle> openScalarAttribute(hid_t object, const std::string& name,
                                                      H5T_class_t wanted,
                                                      const std::string& wantedWord) {
    Hdf5Handle attribute = openAttribute(object, name);
    Hdf5Handle space(checked(H5Aget_space(attribute.get()), object, name, "attribute", "read"),
                     H5Sclose);
    if (H5Sget_simple_extent_npoints(space.get()) != 1)
        fail(object, name, "attribute", "is not a scalar");
    Hdf5Handle type(checked(H5Aget_type(attribute.get()), object, name, "attribute", "read"),
                    H5Tclose);
    const H5T_class_t found = H5Tget_class(type.get());
    const bool integerForFloat = wanted == H5T_FLOAT && found == H5T_INTEGER;
    if (found != wanted && !integerForFloat)
        fail(object, name, "attribute", "is not " + wantedWord);
    return {std::move(attribute), std::move(type)};
}

template <typename T>
T readNumber(const Hdf5Handle& attribute, hid_t memoryType, hid_t object, const std::string& name) {
    T value{};
    checked(H5Aread(attribute.get(), memoryType, &value), object, name, "attribute", "read");
    return value;
}

template <typename T>
void writeScalar(hid_t object, const std::string& name, hid_t fileType, hid_t memoryType,
                 const T* value) {
    if (hasAttribute(object, name))
        checked(H5Adelete(object, name.c_str()), object, name, "attribute", "replace");
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle attribute(
        checked(H5Acreate2(object, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                object, name, "attribute", "create"),
        H5Aclose);
    checked(H5Awrite(attribute.get(), memoryType, value), object, name, "attribute", "write");
}

Hdf5Handle stringType(size_t size, H5T_cset_t charset) {
    Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), size);
    H5Tset_cset(type.get(), charset);
    return type;
}

} // namespace

Hdf5Handle::Hdf5Handle(Hdf5Handle&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
        if (id_ >= 0) closer_(id_);
        id_ = std::exchange(other.id_, H5I_INVALID_HID);
        closer_ = other.closer_;
    }
    return *this;
}

Hdf5Handle::~Hdf5Handle() {
    if (id_ >= 0) closer_(id_);
}

void Hdf5Handle::close() {
    if (id_ < 0) return;
    const std::string file = nameFrom(fileNameQuery, id_);
    const std::string object = nameFrom(objectNameQuery, id_);
    const herr_t status = closer_(std::exchange(id_, H5I_INVALID_HID));
    if (status < 0) {
        const std::string reason = hdf5Reason();
        throw Hdf5Error("'" + file + "': cannot close '" + object + "' (" + reason + ")");
    }
}

bool isHdf5File(const fs::path& file) {
    silenceHdf5ErrorPrinting();
    return H5Fis_hdf5(file.c_str()) > 0;
}

Hdf5Handle createFile(const std::string& name) {
    silenceHdf5ErrorPrinting();
    Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    // In memory, grown by 1 MiB. The earliest file format: the widest compatibility, and its
    // superblock is complete in the image of an open file (the later formats' superblock carries a
    // checksum and status flags that are finished only at the close).
    H5Pset_fapl_core(access.get(), std::size_t{1} << 20, 0);
    const hid_t id = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
    if (id < 0) throw Hdf5Error("'" + name + "': cannot create (" + hdf5Reason() + ")");
    return Hdf5Handle(id, H5Fclose);
}

std::string fileImage(Hdf5Handle& file, const std::string& name) {
    if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0)
        throw Hdf5Error("'" + name + "': cannot flush (" + hdf5Reason() + ")");
    const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
    if (size < 0) throw Hdf5Error("'" + name + "': no file image (" + hdf5Reason() + ")");
    std::string bytes(static_cast<std::size_t>(size), '\0');
    if (H5Fget_file_image(file.get(), bytes.data(), bytes.size()) != size)
        throw Hdf5Error("'" + name + "': cannot copy the file image (" + hdf5Reason() + ")");
    file.close();
    return bytes;
}

Hdf5Handle openFileReadOnly(const fs::path& file) {
    silenceHdf5ErrorPrinting();
    const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) throw Hdf5Error("'" + file.string() + "': cannot open (" + hdf5Reason() + ")");
    return Hdf5Handle(id, H5Fclose);
}

Hdf5Handle createGroup(hid_t parent, const std::string& name) {
    return Hdf5Handle(
        checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), parent,
                name, "group", "create"),
        H5Gclose);
}

Hdf5Handle openGroup(hid_t parent, const std::string& name) {
    if (!hasLink(parent, name)) fail(parent, name, "group", "missing");
    return Hdf5Handle(
        checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), parent, name, "group", "open"),
        H5Gclose);
}

Hdf5Handle openDataset(hid_t parent, const std::string& name) {
    if (!hasLink(parent, name)) fail(parent, name, "dataset", "missing");
    return Hdf5Handle(
        checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), parent, name, "dataset", "open"),
        H5Dclose);
}

bool hasLink(hid_t parent, const std::string& name) {
    if (checked(H5Lexists(parent, name.c_str(), H5P_DEFAULT), parent, name, "link", "look up") <= 0)
        return false;
    // An external (or user-defined) link leaves the file: to another file, or to a FIFO that would
    // block the open. sbpack's files are self-contained; such a link is refused, never followed.
    H5L_info_t info{};
    checked(H5Lget_info(parent, name.c_str(), &info, H5P_DEFAULT), parent, name, "link", "look up");
    if (info.type != H5L_TYPE_HARD && info.type != H5L_TYPE_SOFT)
        fail(parent, name, "link",
             "is an external link to another file; sbpack reads self-contained files only "
             "(h5repack or h5copy can bring its target in)");
    return true;
}

bool hasAttribute(hid_t object, const std::string& name) {
    return checked(H5Aexists(object, name.c_str()), object, name, "attribute", "look up") > 0;
}

std::vector<std::string> attributeNames(hid_t object) {
    std::vector<std::string> names;
    const auto collect = [](hid_t, const char* name, const H5A_info_t*, void* out) -> herr_t {
        static_cast<std::vector<std::string>*>(out)->emplace_back(name);
        return 0;
    };
    checked(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names), object, "*",
            "attribute", "list");
    return names;
}

AttributeKind attributeKind(hid_t object, const std::string& name) {
    Hdf5Handle attribute = openAttribute(object, name);
    Hdf5Handle type(checked(H5Aget_type(attribute.get()), object, name, "attribute", "read"),
                    H5Tclose);
    switch (H5Tget_class(type.get())) {
    case H5T_INTEGER:
        return AttributeKind::Integer;
    case H5T_FLOAT:
        return AttributeKind::Float;
    case H5T_STRING:
        return AttributeKind::String;
    default:
        return AttributeKind::Other;
    }
}

void writeDoubleAttribute(hid_t object, const std::string& name, double value) {
    writeScalar(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void writeInt64Attribute(hid_t object, const std::string& name, std::int64_t value) {
    writeScalar(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void writeUint64Attribute(hid_t object, const std::string& name, std::uint64_t value) {
    writeScalar(object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, &value);
}

void writeStringAttribute(hid_t object, const std::string& name, const std::string& value) {
    const Hdf5Handle type = stringType(H5T_VARIABLE, H5T_CSET_UTF8);
    const char* text = value.c_str();
    writeScalar(object, name, type.get(), type.get(), &text);
}

double readDoubleAttribute(hid_t object, const std::string& name) {
    const auto [attribute, type] = openScalarAttribute(object, name, H5T_FLOAT, "a number");
    return readNumber<double>(attribute, H5T_NATIVE_DOUBLE, object, name);
}

std::int64_t readInt64Attribute(hid_t object, const std::string& name) {
    const auto [attribute, type] = openScalarAttribute(object, name, H5T_INTEGER, "an integer");
    if (H5Tget_sign(type.get()) == H5T_SGN_NONE) {
        const auto value = readNumber<std::uint64_t>(attribute, H5T_NATIVE_UINT64, object, name);
        if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            fail(object, name, "attribute", "value " + std::to_string(value) + " exceeds int64");
        return static_cast<std::int64_t>(value);
    }
    return readNumber<std::int64_t>(attribute, H5T_NATIVE_INT64, object, name);
}

std::uint64_t readUint64Attribute(hid_t object, const std::string& name) {
    const auto [attribute, type] = openScalarAttribute(object, name, H5T_INTEGER, "an integer");
    if (H5Tget_sign(type.get()) != H5T_SGN_NONE) {
        const auto value = readNumber<std::int64_t>(attribute, H5T_NATIVE_INT64, object, name);
        if (value < 0)
            fail(object, name, "attribute", "value " + std::to_string(value) + " is negative");
        return static_cast<std::uint64_t>(value);
    }
    return readNumber<std::uint64_t>(attribute, H5T_NATIVE_UINT64, object, name);
}

std::string readStringAttribute(hid_t object, const std::string& name) {
    const auto [attribute, type] = openScalarAttribute(object, name, H5T_STRING, "a string");
    const H5T_cset_t charset = H5Tget_cset(type.get());
    if (H5Tis_variable_str(type.get()) > 0) {
        const Hdf5Handle memoryType = stringType(H5T_VARIABLE, charset);
        char* text = nullptr;
        checked(H5Aread(attribute.get(), memoryType.get(), &text), object, name, "attribute",
                "read");
        std::string value = text != nullptr ? text : "";
        H5free_memory(text);
        return value;
    }
    // The raw bytes, in the file's own string type: HDF5's conversion to a NUL-terminated type
    // would stop at the first NUL and hide what follows it.
    const size_t size = H5Tget_size(type.get());
    const Hdf5Handle memoryType(H5Tcopy(type.get()), H5Tclose);
    std::string buffer(size, '\0');
    checked(H5Aread(attribute.get(), memoryType.get(), buffer.data()), object, name, "attribute",
            "read");
    // Padding is trailing spaces (SPACEPAD) or NULs; a NUL left before other characters would
    // silently cut the string short (e.g. "sbpack.packing\0..." read as the format): refused.
    const bool spaces = H5Tget_strpad(type.get()) == H5T_STR_SPACEPAD;
    const std::size_t end = buffer.find_last_not_of(spaces ? ' ' : '\0');
    buffer.resize(end == std::string::npos ? 0 : end + 1);
    if (buffer.find('\0') != std::string::npos)
        fail(object, name, "attribute", "a fixed-length string with an embedded NUL character");
    return buffer;
}

void writeMatrixDataset(hid_t parent, const std::string& name, std::span<const double> values,
                        std::size_t cols) {
    if (hasLink(parent, name))
        checked(H5Ldelete(parent, name.c_str(), H5P_DEFAULT), parent, name, "dataset", "replace");
    const hsize_t dims[2] = {values.size() / cols, cols};
    Hdf5Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
    Hdf5Handle dataset(checked(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space.get(),
                                          H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                               parent, name, "dataset", "create"),
                       H5Dclose);
    checked(
        H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
        parent, name, "dataset", "write");
}

std::vector<double> readMatrixDataset(hid_t parent, const std::string& name, std::size_t rows,
                                      std::size_t cols) {
    if (!hasLink(parent, name)) fail(parent, name, "dataset", "missing");
    Hdf5Handle dataset(
        checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), parent, name, "dataset", "open"),
        H5Dclose);
    Hdf5Handle type(checked(H5Dget_type(dataset.get()), parent, name, "dataset", "read"), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_FLOAT)
        fail(parent, name, "dataset", "is not floating point");
    // HDF5's widest number (a long double) has 16 bytes. libhdf5 allocates a conversion buffer
    // of one value's size before it finds the data missing: a 16 KB file whose positions claimed
    // 4 GB a value took 4 GB (found by tests/fuzz/fuzz_checkpoint_reader).
    if (const std::size_t bytes = H5Tget_size(type.get()); bytes > 16)
        fail(parent, name, "dataset",
             "has values of " + std::to_string(bytes) +
                 " bytes, wider than any number (at most 16): the file is corrupt");
    Hdf5Handle space(checked(H5Dget_space(dataset.get()), parent, name, "dataset", "read"),
                     H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    hsize_t dims[2] = {0, 0};
    if (rank == 2) H5Sget_simple_extent_dims(space.get(), dims, nullptr);
    if (rank != 2 || dims[0] != rows || dims[1] != cols) {
        std::string shape = "rank " + std::to_string(rank);
        if (rank == 2) shape = std::to_string(dims[0]) + " x " + std::to_string(dims[1]);
        fail(parent, name, "dataset",
             "has shape " + shape + ", expected " + std::to_string(rows) + " x " +
                 std::to_string(cols));
    }
    // A huge extent with little behind it (unallocated chunks) is refused before the allocation:
    // the stored bytes must be at least 1/1000 of the values' (more than any compression of
    // coordinates).
    const double needed = static_cast<double>(rows) * static_cast<double>(cols) * sizeof(double);
    const auto stored = static_cast<double>(H5Dget_storage_size(dataset.get()));
    if (needed > 1e6 && 1000.0 * stored < needed)
        fail(parent, name, "dataset",
             "claims " + std::to_string(rows) + " x " + std::to_string(cols) +
                 " values but stores only " + std::to_string(static_cast<long long>(stored)) +
                 " bytes");
    std::vector<double> values(rows * cols);
    checked(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
            parent, name, "dataset", "read");
    return values;
}

} // namespace sbpack

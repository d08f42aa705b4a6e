#pragma once
// Minimal RAII over the HDF5 C API for the packing and results files (docs/design.md §4, §6).
// HDF5's automatic error printing is switched off; every failure becomes an Hdf5Error whose
// message names the file, the object and HDF5's own reason.

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

/// A failed HDF5 operation; the message names the file and the object.
class Hdf5Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Owns one hid_t (file, group, dataset, dataspace, attribute or type) and closes it with the
/// matching H5*close function.
class Hdf5Handle {
  public:
    using Closer = herr_t (*)(hid_t);

    Hdf5Handle() = default;
    Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    Hdf5Handle(Hdf5Handle&& other) noexcept;
    Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
    Hdf5Handle(const Hdf5Handle&) = delete;
    Hdf5Handle& operator=(const Hdf5Handle&) = delete;
    ~Hdf5Handle();

    hid_t get() const { return id_; }
    /// Closes now and reports failure (a file's close flushes it); the destructor cannot throw.
    void close();

  private:
    hid_t id_ = H5I_INVALID_HID;
    Closer closer_ = nullptr;
};

/// True if `file` carries the HDF5 signature.
bool isHdf5File(const std::filesystem::path& file);
/// Creates (truncating) a file in the HDF5 1.8 format, which h5py and every current reader open
/// and which stores attributes larger than 64 KiB (long provenance logs).
/// A new HDF5 file held in memory (the core driver, no backing store); `name` is for messages.
/// fileImage() closes it and returns its bytes, which the caller writes (AtomicOutput::write):
/// HDF5 itself never writes to disk, so a full disk is a checked write error, never a failure
/// inside HDF5's close.
Hdf5Handle createFile(const std::string& name);
/// Flushes and closes an in-memory file from createFile() and returns its bytes.
std::string fileImage(Hdf5Handle& file, const std::string& name);
Hdf5Handle openFileReadOnly(const std::filesystem::path& file);

Hdf5Handle createGroup(hid_t parent, const std::string& name);
Hdf5Handle openGroup(hid_t parent, const std::string& name);
Hdf5Handle openDataset(hid_t parent, const std::string& name);
/// True if `parent` has a link (dataset or group) called `name`.
bool hasLink(hid_t parent, const std::string& name);

bool hasAttribute(hid_t object, const std::string& name);
/// Names of the attributes of `object`, in name order.
std::vector<std::string> attributeNames(hid_t object);

enum class AttributeKind { Integer, Float, String, Other };
AttributeKind attributeKind(hid_t object, const std::string& name);

void writeDoubleAttribute(hid_t object, const std::string& name, double value);
void writeInt64Attribute(hid_t object, const std::string& name, std::int64_t value);
void writeUint64Attribute(hid_t object, const std::string& name, std::uint64_t value);
/// A scalar variable-length UTF-8 string (h5py reads it as str).
void writeStringAttribute(hid_t object, const std::string& name, const std::string& value);

/// Readers throw Hdf5Error when the attribute is missing, is not a scalar, or has the wrong
/// class (an integer attribute is accepted where a double is asked for).
double readDoubleAttribute(hid_t object, const std::string& name);
std::int64_t readInt64Attribute(hid_t object, const std::string& name);
/// Also accepts a non-negative signed integer.
std::uint64_t readUint64Attribute(hid_t object, const std::string& name);
/// Fixed-length or variable-length strings.
std::string readStringAttribute(hid_t object, const std::string& name);

/// Writes a rows x cols float64 dataset from row-major values (values.size() = rows * cols).
void writeMatrixDataset(hid_t parent, const std::string& name, std::span<const double> values,
                        std::size_t cols);
/// Reads a float64 dataset that must have shape rows x cols; row-major.
std::vector<double> readMatrixDataset(hid_t parent, const std::string& name, std::size_t rows,
                                      std::size_t cols);

} // namespace sbpack

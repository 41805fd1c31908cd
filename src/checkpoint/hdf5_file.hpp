// Internal to src/checkpoint: the two halves of how checkpoint files use HDF5.
// H5Writer creates a file of datasets that each carry an "xxh3_64" attribute (XXH3-64 of the
// dataset's raw little-endian bytes) plus scalar attributes, and one root attribute
// "attributes_xxh3_64" covering every other attribute (see attributeLedgerHash), then flushes,
// closes and fsyncs it. H5Reader opens one, verifies the attribute checksum before any value can
// be read, checks every object's type and shape before reading it, never allocates more than the
// file could hold, and verifies each dataset's checksum; every failure is an
// InputError(file, "/dataset/name" or "/object@attribute", what).
// Objects are created without modification times, so the same state gives the same file bytes.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "checkpoint/hdf5_handles.hpp"

namespace shapevo::h5 {

/// Name of the checksum attribute every dataset carries.
inline constexpr const char* kChecksumAttribute = "xxh3_64";
/// Name of the root attribute that covers all other attributes of the file.
inline constexpr const char* kAttributesChecksum = "attributes_xxh3_64";

/// One attribute as the attribute checksum sees it: the object's absolute path ("/",
/// "/config/text"), the attribute's name and its raw (little-endian, NUL-padded) bytes.
struct AttributeRecord {
    std::string object, name;
    std::vector<std::uint8_t> bytes;
};
/// XXH3-64 over the records sorted by (object, name), each as object, NUL, name, NUL, u64 size,
/// bytes. Records of the checksum attributes themselves are left out.
std::uint64_t attributeLedgerHash(std::vector<AttributeRecord> records);

class H5Writer {
public:
    /// Create (truncate) `path`. Throws std::runtime_error.
    explicit H5Writer(std::string path);
    hid_t root() const { return file_.get(); }
    Handle group(hid_t parent, const char* name);
    /// A dataset of little-endian type `type` (e.g. H5T_STD_U32LE) holding `bytes`, with shape
    /// `dims`. extendible: first dimension unlimited, chunked by 64 rows. Returned open so
    /// attributes can be added.
    Handle dataset(hid_t parent, const char* name, hid_t type, std::span<const std::uint8_t> bytes,
                 std::span<const hsize_t> dims, bool extendible = false);
    /// A scalar fixed-length UTF-8 string dataset (null padded; h5dump prints it as text).
    /// Returns it open so attributes can be added.
    Handle text(hid_t parent, const char* name, const std::string& text);
    void attribute(hid_t object, const char* name, std::uint32_t v);
    void attribute(hid_t object, const char* name, std::int32_t v);
    void attribute(hid_t object, const char* name, std::uint64_t v);
    void attribute(hid_t object, const char* name, double v);
    void attribute(hid_t object, const char* name, const std::string& v);
    /// Flush, close and fsync. Without it the file is closed but not guaranteed on disk.
    void finish();

private:
    [[noreturn]] void fail(const std::string& what) const;
    void scalarAttribute(hid_t object, const char* name, hid_t fileType, hid_t memType, const void* v, std::size_t bytes);
    std::string path_;
    Handle file_;
    std::vector<AttributeRecord> attributes_;  ///< every attribute written so far, for the ledger
};

class H5Reader {
public:
    /// Open `path` read-only, check that its root attribute schema_version is in
    /// [oldest, newest] (else "checkpoint schema N is not supported (this shapevo reads M)" or
    /// "reads O to M"), then the attribute checksum. Throws InputError if it is missing, not an
    /// HDF5 file, of another schema or altered.
    H5Reader(std::string path, std::uint32_t oldest, std::uint32_t newest);
    /// The file's schema_version.
    std::uint32_t schema() const { return schema_; }
    const std::string& path() const { return path_; }
    std::uint64_t fileSize() const { return fileSize_; }
    /// Raw bytes of dataset `name` (absolute path), which must have exactly type `type`, rank
    /// `rank` and, if lastDim != 0, that many columns; its checksum is verified.
    std::vector<std::uint8_t> dataset(const char* name, hid_t type, int rank, hsize_t lastDim = 0) const;
    /// A scalar string dataset's text (trailing NUL padding removed); checksum verified.
    std::string text(const char* name) const;
    std::uint32_t u32(const char* object, const char* name) const;
    std::int32_t i32(const char* object, const char* name) const;
    std::uint64_t u64(const char* object, const char* name) const;
    double f64(const char* object, const char* name) const;
    std::string string(const char* object, const char* name) const;

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const;
    void scalarAttribute(const char* object, const char* name, hid_t fileType, hid_t memType, void* out) const;
    void verifyChecksum(const char* name, std::span<const std::uint8_t> bytes) const;
    /// Reads every attribute of every object and checks them against kAttributesChecksum.
    void verifyAttributes() const;
    std::string path_;
    std::uint64_t fileSize_ = 0;
    std::uint32_t schema_ = 0;
    Handle file_;
};

}  // namespace shapevo::h5

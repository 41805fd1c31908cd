// H5Reader: reads checkpoint HDF5 files defensively (see hdf5_file.hpp). Each object's type,
// rank and shape are checked before it is read, a dataset may not claim more bytes than it
// stores or than the file holds, and each dataset's bytes must match its "xxh3_64" attribute.
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>

#include "checkpoint/hdf5_file.hpp"
#include "base/hash.hpp"
#include "base/input_error.hpp"

namespace shapevo::h5 {

namespace {

std::string typeName(hid_t t) {
    if (H5Tequal(t, H5T_STD_U32LE) > 0) return "u32 little-endian";
    if (H5Tequal(t, H5T_STD_I32LE) > 0) return "i32 little-endian";
    if (H5Tequal(t, H5T_STD_U64LE) > 0) return "u64 little-endian";
    if (H5Tequal(t, H5T_IEEE_F64LE) > 0) return "f64 little-endian";
    return "another type";
}

std::string attributeWhere(const char* object, const char* name) {
    return std::string(object) + "@" + name;  // "/@generation", "/config/text@path"
}

std::string hex(std::uint64_t v) {
    std::ostringstream s;
    s << "0x" << std::hex << v;
    return s.str();
}

/// Remove the NUL padding of a fixed-length string.
std::string unpad(std::string s) {
    while (!s.empty() && s.back() == '\0') s.pop_back();
    return s;
}

}  // namespace

H5Reader::H5Reader(std::string path, std::uint32_t oldest, std::uint32_t newest) : path_(std::move(path)) {
    silenceErrorPrinting();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path_, ec)) throw InputError(path_, "", "no such file");
    fileSize_ = std::filesystem::file_size(path_, ec);
    if (ec) throw InputError(path_, "", "cannot read its size: " + ec.message());
    file_ = fileHandle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!file_.valid()) throw InputError(path_, "", "not a readable HDF5 file: " + takeErrorMessage());
    const std::uint32_t stored = u32("/", "schema_version");
    if (stored < oldest || stored > newest)
        fail("/@schema_version", "checkpoint schema " + std::to_string(stored) + " is not supported (this shapevo reads " +
                                     (oldest == newest ? "" : std::to_string(oldest) + " to ") + std::to_string(newest) + ")");
    schema_ = stored;
    verifyAttributes();
}

namespace {

struct AttributeWalk {
    hid_t file;
    std::uint64_t fileSize;
    std::string object;  ///< absolute path of the object being walked
    std::vector<AttributeRecord> records;
    std::uint64_t totalBytes = 0;
    std::string problem;  ///< "where: what" of the first failure
};

herr_t onAttribute(hid_t object, const char* name, const H5A_info_t*, void* data) {
    auto& w = *static_cast<AttributeWalk*>(data);
    if (std::strcmp(name, kChecksumAttribute) == 0 || (w.object == "/" && std::strcmp(name, kAttributesChecksum) == 0))
        return 0;
    const std::string where = w.object + "@" + name;
    Handle a = attributeHandle(H5Aopen(object, name, H5P_DEFAULT));
    Handle type = a.valid() ? typeHandle(H5Aget_type(a.get())) : Handle();
    Handle space = a.valid() ? spaceHandle(H5Aget_space(a.get())) : Handle();
    if (!type.valid() || !space.valid() || H5Sget_simple_extent_type(space.get()) != H5S_SCALAR ||
        H5Tis_variable_str(type.get()) != 0) {
        w.problem = where + ": not a scalar attribute of fixed size";
        return -1;
    }
    const std::uint64_t bytes = H5Tget_size(type.get());
    w.totalBytes += bytes;
    if (bytes == 0 || w.totalBytes > w.fileSize) {
        w.problem = where + ": claims more bytes than the file holds";
        return -1;
    }
    std::vector<std::uint8_t> raw(bytes);
    if (H5Aread(a.get(), type.get(), raw.data()) < 0) {
        w.problem = where + ": cannot read";
        return -1;
    }
    w.records.push_back({w.object, name, std::move(raw)});
    return 0;
}

herr_t onObject(hid_t file, const char* name, const H5O_info_t* info, void* data) {
    auto& w = *static_cast<AttributeWalk*>(data);
    w.object.assign(1, '/');
    if (std::strcmp(name, ".") != 0) w.object.append(name);
    if (info->num_attrs == 0) return 0;
    return H5Aiterate_by_name(file, name, H5_INDEX_NAME, H5_ITER_INC, nullptr, onAttribute, data, H5P_DEFAULT) < 0 ? -1 : 0;
}

}  // namespace

void H5Reader::verifyAttributes() const {
    std::uint64_t stored = 0;
    scalarAttribute("/", kAttributesChecksum, H5T_STD_U64LE, H5T_NATIVE_UINT64, &stored);
    AttributeWalk walk{file_.get(), fileSize_, "/", {}, 0, {}};
    if (H5Ovisit2(file_.get(), H5_INDEX_NAME, H5_ITER_INC, onObject, &walk, H5O_INFO_NUM_ATTRS) < 0)
        fail(walk.problem.empty() ? "/" : walk.problem.substr(0, walk.problem.find(": ")),
             walk.problem.empty() ? "cannot walk the file's objects: " + takeErrorMessage()
                                  : walk.problem.substr(walk.problem.find(": ") + 2));
    const std::uint64_t actual = attributeLedgerHash(std::move(walk.records));
    if (stored != actual)
        fail(std::string("/@") + kAttributesChecksum,
             "attribute checksum mismatch: the attributes hash to " + hex(actual) + " but " + kAttributesChecksum +
                 " says " + hex(stored) + " (an attribute was altered or damaged)");
}

void H5Reader::fail(const std::string& where, const std::string& what) const {
    H5Eclear2(H5E_DEFAULT);
    throw InputError(path_, where, what);
}

std::vector<std::uint8_t> H5Reader::dataset(const char* name, hid_t type, int rank, hsize_t lastDim) const {
    if (H5Lexists(file_.get(), name, H5P_DEFAULT) <= 0) {
        // H5Lexists fails (rather than answering no) when a parent group is missing.
        fail(name, "missing dataset");
    }
    Handle d = datasetHandle(H5Dopen2(file_.get(), name, H5P_DEFAULT));
    if (!d.valid()) fail(name, "not a dataset: " + takeErrorMessage());
    Handle ftype = typeHandle(H5Dget_type(d.get()));
    if (!ftype.valid() || H5Tequal(ftype.get(), type) <= 0)
        fail(name, "has type " + typeName(ftype.get()) + ", expected " + typeName(type));
    Handle space = spaceHandle(H5Dget_space(d.get()));
    if (!space.valid() || H5Sget_simple_extent_type(space.get()) != H5S_SIMPLE ||
        H5Sget_simple_extent_ndims(space.get()) != rank)
        fail(name, "is not a " + std::to_string(rank) + "-dimensional array");
    hsize_t dims[H5S_MAX_RANK];
    H5Sget_simple_extent_dims(space.get(), dims, nullptr);
    if (lastDim != 0 && dims[rank - 1] != lastDim)
        fail(name, "has " + std::to_string(dims[rank - 1]) + " columns, expected " + std::to_string(lastDim));
    const std::uint64_t element = H5Tget_size(type);
    std::uint64_t bytes = element;
    for (int k = 0; k < rank; ++k) {
        if (dims[k] != 0 && bytes > std::numeric_limits<std::uint64_t>::max() / dims[k])
            fail(name, "impossibly large shape");
        bytes *= dims[k];
    }
    // A dataset whose storage is not all written would read back fill values: refuse a shape
    // larger than what is stored, and storage larger than the file.
    const std::uint64_t stored = H5Dget_storage_size(d.get());
    if (bytes > stored || stored > fileSize_)
        fail(name, "claims " + std::to_string(bytes) + " bytes of data but the file stores " + std::to_string(stored) +
                       " (file size " + std::to_string(fileSize_) + ")");
    std::vector<std::uint8_t> out(bytes);
    if (bytes != 0 && H5Dread(d.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
        fail(name, "cannot read: " + takeErrorMessage());
    verifyChecksum(name, out);
    return out;
}

std::string H5Reader::text(const char* name) const {
    if (H5Lexists(file_.get(), name, H5P_DEFAULT) <= 0) fail(name, "missing dataset");
    Handle d = datasetHandle(H5Dopen2(file_.get(), name, H5P_DEFAULT));
    if (!d.valid()) fail(name, "not a dataset: " + takeErrorMessage());
    Handle ftype = typeHandle(H5Dget_type(d.get()));
    if (!ftype.valid() || H5Tget_class(ftype.get()) != H5T_STRING || H5Tis_variable_str(ftype.get()) != 0)
        fail(name, "is not a fixed-length string");
    Handle space = spaceHandle(H5Dget_space(d.get()));
    if (!space.valid() || H5Sget_simple_extent_type(space.get()) != H5S_SCALAR) fail(name, "is not a scalar string");
    const std::uint64_t bytes = H5Tget_size(ftype.get());
    const std::uint64_t stored = H5Dget_storage_size(d.get());
    if (bytes > stored || stored > fileSize_)
        fail(name, "claims " + std::to_string(bytes) + " bytes of text but the file stores " + std::to_string(stored));
    std::string out(bytes, '\0');
    if (H5Dread(d.get(), ftype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
        fail(name, "cannot read: " + takeErrorMessage());
    verifyChecksum(name, {reinterpret_cast<const std::uint8_t*>(out.data()), out.size()});
    return unpad(std::move(out));
}

void H5Reader::verifyChecksum(const char* name, std::span<const std::uint8_t> bytes) const {
    std::uint64_t stored = 0;
    scalarAttribute(name, kChecksumAttribute, H5T_STD_U64LE, H5T_NATIVE_UINT64, &stored);
    const std::uint64_t actual = hash64(bytes.data(), bytes.size());
    if (stored != actual)
        fail(name, "checksum mismatch: the data hashes to " + hex(actual) + " but its " + kChecksumAttribute +
                       " attribute says " + hex(stored) + " (the file was altered or damaged)");
}

void H5Reader::scalarAttribute(const char* object, const char* name, hid_t fileType, hid_t memType, void* out) const {
    const std::string where = attributeWhere(object, name);
    if (H5Aexists_by_name(file_.get(), object, name, H5P_DEFAULT) <= 0) fail(where, "missing attribute");
    Handle a = attributeHandle(H5Aopen_by_name(file_.get(), object, name, H5P_DEFAULT, H5P_DEFAULT));
    if (!a.valid()) fail(where, "cannot open attribute: " + takeErrorMessage());
    Handle ftype = typeHandle(H5Aget_type(a.get()));
    if (!ftype.valid() || H5Tequal(ftype.get(), fileType) <= 0)
        fail(where, "has type " + typeName(ftype.get()) + ", expected " + typeName(fileType));
    Handle space = spaceHandle(H5Aget_space(a.get()));
    if (!space.valid() || H5Sget_simple_extent_type(space.get()) != H5S_SCALAR) fail(where, "is not a scalar");
    if (H5Aread(a.get(), memType, out) < 0) fail(where, "cannot read: " + takeErrorMessage());
}

std::uint32_t H5Reader::u32(const char* object, const char* name) const {
    std::uint32_t v = 0;
    scalarAttribute(object, name, H5T_STD_U32LE, H5T_NATIVE_UINT32, &v);
    return v;
}
std::int32_t H5Reader::i32(const char* object, const char* name) const {
    std::int32_t v = 0;
    scalarAttribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT32, &v);
    return v;
}
std::uint64_t H5Reader::u64(const char* object, const char* name) const {
    std::uint64_t v = 0;
    scalarAttribute(object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, &v);
    return v;
}
double H5Reader::f64(const char* object, const char* name) const {
    double v = 0;
    scalarAttribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &v);
    return v;
}

std::string H5Reader::string(const char* object, const char* name) const {
    const std::string where = attributeWhere(object, name);
    if (H5Aexists_by_name(file_.get(), object, name, H5P_DEFAULT) <= 0) fail(where, "missing attribute");
    Handle a = attributeHandle(H5Aopen_by_name(file_.get(), object, name, H5P_DEFAULT, H5P_DEFAULT));
    if (!a.valid()) fail(where, "cannot open attribute: " + takeErrorMessage());
    Handle ftype = typeHandle(H5Aget_type(a.get()));
    if (!ftype.valid() || H5Tget_class(ftype.get()) != H5T_STRING || H5Tis_variable_str(ftype.get()) != 0)
        fail(where, "is not a fixed-length string");
    Handle space = spaceHandle(H5Aget_space(a.get()));
    if (!space.valid() || H5Sget_simple_extent_type(space.get()) != H5S_SCALAR) fail(where, "is not a scalar");
    const std::uint64_t bytes = H5Tget_size(ftype.get());
    if (bytes > fileSize_) fail(where, "claims " + std::to_string(bytes) + " bytes, more than the file holds");
    std::string out(bytes, '\0');
    if (H5Aread(a.get(), ftype.get(), out.data()) < 0) fail(where, "cannot read: " + takeErrorMessage());
    return unpad(std::move(out));
}

}  // namespace shapevo::h5

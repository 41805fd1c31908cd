// H5Writer: creates checkpoint HDF5 files (see hdf5_file.hpp): checksummed datasets, scalar
// attributes, no timestamps. The file is built in memory (HDF5's core driver, no backing store)
// and written out by finish() through base/atomic_write.hpp: a full disk or a quota is then one
// clean error, and libhdf5 never holds a file it cannot flush (it would crash at exit).
#include <cstring>
#include <stdexcept>
#include <vector>

#include "checkpoint/hdf5_file.hpp"
#include "base/atomic_write.hpp"
#include "base/hash.hpp"
#include "base/little_endian.hpp"

namespace shapevo::h5 {

namespace {
constexpr hsize_t kCurveChunkRows = 64;

/// Object creation properties shared by groups and datasets: no access/modification times, so
/// writing the same state twice gives byte-identical files.
Handle untimed(hid_t cls) {
    Handle p = plistHandle(H5Pcreate(cls));
    if (p.valid()) H5Pset_obj_track_times(p.get(), false);
    return p;
}
}  // namespace

H5Writer::H5Writer(std::string path) : path_(std::move(path)) {
    silenceErrorPrinting();
    Handle fapl = plistHandle(H5Pcreate(H5P_FILE_ACCESS));
    if (!fapl.valid() || H5Pset_fapl_core(fapl.get(), 1 << 20, /*backing_store=*/false) < 0)
        fail("cannot set up an in-memory HDF5 file");
    file_ = fileHandle(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
    if (!file_.valid()) fail("cannot create HDF5 file");
}

void H5Writer::fail(const std::string& what) const {
    throw std::runtime_error(path_ + ": " + what + ": " + takeErrorMessage());
}

Handle H5Writer::group(hid_t parent, const char* name) {
    Handle gcpl = untimed(H5P_GROUP_CREATE);
    Handle g = groupHandle(H5Gcreate2(parent, name, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT));
    if (!g.valid()) fail(std::string("cannot create group ") + name);
    return g;
}

Handle H5Writer::dataset(hid_t parent, const char* name, hid_t type, std::span<const std::uint8_t> bytes,
                       std::span<const hsize_t> dims, bool extendible) {
    std::vector<hsize_t> max(dims.begin(), dims.end()), chunk(dims.begin(), dims.end());
    Handle dcpl = untimed(H5P_DATASET_CREATE);
    if (extendible) {
        max[0] = H5S_UNLIMITED;
        chunk[0] = kCurveChunkRows;
        if (H5Pset_chunk(dcpl.get(), int(chunk.size()), chunk.data()) < 0) fail(std::string("cannot chunk ") + name);
    }
    Handle space = spaceHandle(H5Screate_simple(int(dims.size()), dims.data(), max.data()));
    if (!space.valid()) fail(std::string("cannot make the dataspace of ") + name);
    Handle d = datasetHandle(H5Dcreate2(parent, name, type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT));
    if (!d.valid()) fail(std::string("cannot create dataset ") + name);
    // The memory type equals the (little-endian) file type: the bytes go to disk unconverted.
    if (!bytes.empty() && H5Dwrite(d.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) < 0)
        fail(std::string("cannot write dataset ") + name);
    attribute(d.get(), kChecksumAttribute, hash64(bytes.data(), bytes.size()));
    return d;
}

Handle H5Writer::text(hid_t parent, const char* name, const std::string& text) {
    Handle type = typeHandle(H5Tcopy(H5T_C_S1));
    // HDF5 has no zero-length fixed strings: an empty text is stored as one NUL.
    const std::string stored = text.empty() ? std::string(1, '\0') : text;
    if (!type.valid() || H5Tset_size(type.get(), stored.size()) < 0 || H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0 ||
        H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
        fail(std::string("cannot make the string type of ") + name);
    Handle space = spaceHandle(H5Screate(H5S_SCALAR));
    Handle dcpl = untimed(H5P_DATASET_CREATE);
    Handle d = datasetHandle(H5Dcreate2(parent, name, type.get(), space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT));
    if (!d.valid()) fail(std::string("cannot create dataset ") + name);
    if (H5Dwrite(d.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, stored.data()) < 0)
        fail(std::string("cannot write dataset ") + name);
    attribute(d.get(), kChecksumAttribute, hash64(stored.data(), stored.size()));
    return d;
}

void H5Writer::scalarAttribute(hid_t object, const char* name, hid_t fileType, hid_t memType, const void* v,
                               std::size_t bytes) {
    Handle space = spaceHandle(H5Screate(H5S_SCALAR));
    Handle a = attributeHandle(H5Acreate2(object, name, fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT));
    if (!a.valid() || H5Awrite(a.get(), memType, v) < 0) fail(std::string("cannot write attribute ") + name);
    if (std::strcmp(name, kChecksumAttribute) == 0) return;  // self-checking: covers its dataset
    char objectName[1024];
    const ssize_t n = H5Iget_name(object, objectName, sizeof objectName);
    if (n <= 0 || std::size_t(n) >= sizeof objectName) fail(std::string("cannot name the object of attribute ") + name);
    // The file types are little-endian: store the value's little-endian bytes, as H5Aread with
    // the file type gives them back.
    std::vector<std::uint8_t> raw(bytes);
    if (memType == fileType) std::memcpy(raw.data(), v, bytes);
    else if (bytes == 4) {
        std::uint32_t u;
        std::memcpy(&u, v, 4);
        le::store(raw.data(), u);
    } else {
        std::uint64_t u;
        std::memcpy(&u, v, 8);
        le::store(raw.data(), u);
    }
    attributes_.push_back({objectName, name, std::move(raw)});
}

void H5Writer::attribute(hid_t object, const char* name, std::uint32_t v) {
    scalarAttribute(object, name, H5T_STD_U32LE, H5T_NATIVE_UINT32, &v, 4);
}
void H5Writer::attribute(hid_t object, const char* name, std::int32_t v) {
    scalarAttribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT32, &v, 4);
}
void H5Writer::attribute(hid_t object, const char* name, std::uint64_t v) {
    scalarAttribute(object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, &v, 8);
}
void H5Writer::attribute(hid_t object, const char* name, double v) {
    scalarAttribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &v, 8);
}
void H5Writer::attribute(hid_t object, const char* name, const std::string& v) {
    Handle type = typeHandle(H5Tcopy(H5T_C_S1));
    const std::string stored = v.empty() ? std::string(1, '\0') : v;
    if (!type.valid() || H5Tset_size(type.get(), stored.size()) < 0 || H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0 ||
        H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
        fail(std::string("cannot make the string type of attribute ") + name);
    scalarAttribute(object, name, type.get(), type.get(), stored.data(), stored.size());
}

void H5Writer::finish() {
    const std::uint64_t ledger = attributeLedgerHash(attributes_);
    Handle space = spaceHandle(H5Screate(H5S_SCALAR));
    Handle a = attributeHandle(H5Acreate2(root(), kAttributesChecksum, H5T_STD_U64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
    if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_UINT64, &ledger) < 0)
        fail(std::string("cannot write attribute ") + kAttributesChecksum);
    a = Handle();
    if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) fail("cannot flush");
    const ssize_t size = H5Fget_file_image(file_.get(), nullptr, 0);
    if (size <= 0) fail("cannot take the file image");
    std::vector<char> image(static_cast<std::size_t>(size));
    if (H5Fget_file_image(file_.get(), image.data(), image.size()) != size) fail("cannot take the file image");
    if (!file_.close()) fail("cannot close");
    // The one atomic writer (temporary file, checked write, fsync, rename, fsync of the folder).
    writeStreamAtomically(path_, [&](std::ostream& out) { out.write(image.data(), std::streamsize(image.size())); });
}

}  // namespace shapevo::h5

// attributeLedgerHash: the one definition of what the attribute checksum of a checkpoint file
// covers, shared by H5Writer (which stores it) and H5Reader (which checks it on open).
#include <algorithm>

#include "base/hash.hpp"
#include "checkpoint/hdf5_file.hpp"

namespace shapevo::h5 {

std::uint64_t attributeLedgerHash(std::vector<AttributeRecord> records) {
    std::sort(records.begin(), records.end(), [](const AttributeRecord& a, const AttributeRecord& b) {
        return a.object != b.object ? a.object < b.object : a.name < b.name;
    });
    Hasher h;
    for (const AttributeRecord& r : records) {
        h.add(r.object.data(), r.object.size() + 1);  // with its NUL
        h.add(r.name.data(), r.name.size() + 1);
        h.addNumber(std::uint64_t(r.bytes.size()));
        h.add(r.bytes.data(), r.bytes.size());
    }
    return h.digest();
}

}  // namespace shapevo::h5

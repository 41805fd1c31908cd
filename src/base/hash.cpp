// XXH3-64 through libxxhash's one-shot and streaming calls.
#include "base/hash.hpp"

#include <cstdio>
#include <fstream>
#include <new>
#include <vector>

#include <xxhash.h>

namespace shapevo {

std::uint64_t hash64(const void* data, std::size_t bytes) { return XXH3_64bits(bytes ? data : "", bytes); }

Hasher::Hasher() : state_(XXH3_createState()) {
    if (!state_) throw std::bad_alloc();
    XXH3_64bits_reset(static_cast<XXH3_state_t*>(state_));
}

Hasher::~Hasher() { XXH3_freeState(static_cast<XXH3_state_t*>(state_)); }

void Hasher::add(const void* data, std::size_t bytes) {
    if (bytes) XXH3_64bits_update(static_cast<XXH3_state_t*>(state_), data, bytes);
}

std::string hashHex(std::uint64_t hash) {
    char b[17];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(hash));
    return b;
}

FileHash hashFile(const std::string& path) {
    FileHash f;
    std::ifstream in(path, std::ios::binary);
    if (!in) return f;
    Hasher hasher;
    std::vector<char> block(1 << 16);
    while (in) {
        in.read(block.data(), std::streamsize(block.size()));
        const auto n = std::size_t(in.gcount());
        hasher.add(block.data(), n);
        f.size += n;
    }
    f.ok = in.eof();
    f.hash = hasher.digest();
    return f;
}

std::uint64_t Hasher::digest() const { return XXH3_64bits_digest(static_cast<const XXH3_state_t*>(state_)); }

}  // namespace shapevo

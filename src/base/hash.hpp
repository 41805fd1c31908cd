// hash64: the one content hash of shapevo, XXH3-64 (seed 0) from Debian's libxxhash. It checks
// checkpoint datasets and MANIFEST lines, ties genome files to their grammar, and identifies
// targets. A file's hash is what `xxhsum -H3 FILE` prints, so users can check any MANIFEST line
// by hand. Numbers are hashed as their little-endian bytes, so a hash is the same on every CPU.
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include "base/little_endian.hpp"

#define XXH_INLINE_ALL
#include <xxhash.h>

namespace shapevo {

/// XXH3-64 of `bytes` bytes at `data` (data may be null when bytes == 0).
std::uint64_t hash64(const void* data, std::size_t bytes);
inline std::uint64_t hash64(std::string_view s) { return hash64(s.data(), s.size()); }

/// A hash as 16 lowercase hex digits, as MANIFEST lines and `xxhsum -H3` show it.
std::string hashHex(std::uint64_t hash);

/// A file's size and hash64 of its bytes, read in blocks; ok = false if it could not be read.
struct FileHash {
    std::uint64_t size = 0, hash = 0;
    bool ok = false;
};
FileHash hashFile(const std::string& path);

/// The same hash over a stream of pieces: Hasher h; h.add(p, n); ...; h.digest() equals
/// hash64 of the concatenated pieces.
class Hasher {
public:
    Hasher();
    ~Hasher();
    Hasher(const Hasher&) = delete;
    Hasher& operator=(const Hasher&) = delete;

    void add(const void* data, std::size_t bytes);
    /// A number as its little-endian bytes (doubles and floats by their IEEE-754 bits).
    template <class T>
    void addNumber(T value) {
        static_assert(std::is_arithmetic_v<T>);
        std::uint8_t b[sizeof(T)];
        le::store(b, value);
        add(b, sizeof b);
    }
    std::uint64_t digest() const;

private:
    void* state_;  ///< an XXH3_state_t, kept out of this header
};

/// A quick hash of `n` 32-bit words for in-memory tables (it picks a bucket; the table compares
/// the words): XXH3-64 of their bytes in memory, inlined (its lanes run side by side, so a
/// 72-byte key takes a few multiplies' latency, not one per word). Never stored or sent: it
/// may change between versions, and differs between byte orders, unlike hash64.
inline std::uint64_t quickHash(const std::uint32_t* words, std::size_t n) {
    return XXH_INLINE_XXH3_64bits(n ? static_cast<const void*>(words) : "", n * sizeof(std::uint32_t));
}

}  // namespace shapevo

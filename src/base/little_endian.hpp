// Endian helpers for every file format: load and store fixed-size numbers as little-endian bytes, the byte
// order of checkpoints, genome files and hashed numbers, whatever the CPU.
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace shapevo::le {

template <class T>
T load(const std::uint8_t* p) {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(&v, p, sizeof v);
    } else {
        std::uint8_t b[sizeof v];
        std::reverse_copy(p, p + sizeof v, b);
        std::memcpy(&v, b, sizeof v);
    }
    return v;
}

template <class T>
void store(std::uint8_t* p, T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::memcpy(p, &v, sizeof v);
    if constexpr (std::endian::native != std::endian::little) std::reverse(p, p + sizeof v);
}

/// Append `v` to `out` as little-endian bytes.
template <class T>
void append(std::vector<std::uint8_t>& out, T v) {
    const std::size_t at = out.size();
    out.resize(at + sizeof v);
    store(out.data() + at, v);
}

}  // namespace shapevo::le

// Test helper: the two chunks of a binary glTF file, with its header and chunk framing checked
// as it is taken apart (EXPECTs), and little-endian words of the BIN chunk.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace shapevo::test {

inline std::uint32_t u32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(std::uint8_t(bytes.at(at + std::size_t(i)))) << (8 * i);
    return v;
}

struct Glb {
    std::string json, bin;
    bool hasBin = false;
};

/// Parses the GLB container, checking header and chunk framing as it goes.
inline Glb parseGlb(const std::string& bytes) {
    Glb g;
    EXPECT_GE(bytes.size(), 20u);
    EXPECT_EQ(u32(bytes, 0), 0x46546C67u) << "magic 'glTF'";
    EXPECT_EQ(u32(bytes, 4), 2u) << "version";
    EXPECT_EQ(u32(bytes, 8), bytes.size()) << "total length";
    const std::uint32_t jsonLength = u32(bytes, 12);
    EXPECT_EQ(u32(bytes, 16), 0x4E4F534Au) << "first chunk is JSON";
    EXPECT_EQ(jsonLength % 4, 0u) << "JSON chunk aligned";
    g.json = bytes.substr(20, jsonLength);
    std::size_t at = 20 + std::size_t(jsonLength);
    if (at < bytes.size()) {
        const std::uint32_t binLength = u32(bytes, at);
        EXPECT_EQ(u32(bytes, at + 4), 0x004E4942u) << "second chunk is BIN";
        EXPECT_EQ(binLength % 4, 0u) << "BIN chunk aligned";
        g.bin = bytes.substr(at + 8, binLength);
        g.hasBin = true;
        at += 8 + std::size_t(binLength);
    }
    EXPECT_EQ(at, bytes.size()) << "nothing after the chunks";
    return g;
}

}  // namespace shapevo::test

// hash64 is XXH3-64 with seed 0: the value `xxhsum -H3` prints for a file, the streaming Hasher
// agrees with the one-shot call however the bytes are split, and numbers hash as little-endian.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "../test_support.hpp"
#include "base/hash.hpp"

namespace shapevo {
namespace {

TEST(Hash, IsXxh3With64BitsAndSeedZero) {
    // Published XXH3_64bits test values (xxHash's sanity check: empty input; and "abc").
    EXPECT_EQ(hash64(nullptr, 0), 0x2D06800538D394C2ull);
    EXPECT_EQ(hash64(std::string_view("abc")), 0x78AF5F94892F3950ull);
}

TEST(Hash, AFilesHashIsWhatXxhsumPrints) {
    const std::string path = test::sourcePath("grammars/spaceship.grammar");
    const std::string text = test::readFile(path);
    const test::CommandResult r = test::runCommand("xxhsum -H3 " + path);
    ASSERT_EQ(r.exitCode, 0) << "xxhsum (Debian package xxhash) is needed: " << r.output;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash64(text)));
    EXPECT_NE(r.output.find(hex), std::string::npos) << r.output << " does not show " << hex;
}

TEST(Hash, StreamingEqualsOneShotForEverySplit) {
    std::string bytes(300, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = char(i * 131 + 7);
    const std::uint64_t whole = hash64(bytes);
    for (std::size_t cut : {0u, 1u, 63u, 64u, 240u, 299u, 300u}) {
        Hasher h;
        h.add(bytes.data(), cut);
        h.add(bytes.data() + cut, bytes.size() - cut);
        EXPECT_EQ(h.digest(), whole) << "split at " << cut;
    }
}

TEST(Hash, NumbersHashAsTheirLittleEndianBytes) {
    Hasher h;
    h.addNumber(std::uint32_t(0x04030201));
    h.addNumber(1.0);  // IEEE-754: 00 00 00 00 00 00 f0 3f
    const unsigned char expected[] = {1, 2, 3, 4, 0, 0, 0, 0, 0, 0, 0xf0, 0x3f};
    EXPECT_EQ(h.digest(), hash64(expected, sizeof expected));
}

}  // namespace
}  // namespace shapevo

// libFuzzer target: arbitrary bytes -> readPng (image/png_image.hpp), through a temporary file
// since readPng takes a path. An InputError is the expected way to reject input; any other
// exception, a sanitizer report or a broken invariant of an accepted image is a crash. An
// accepted image has 1..kMaxPngSide pixels on each side and one luminance and one alpha byte
// per pixel.
//
// Two things keep the fuzzer in shapevo's code rather than at libpng's front door:
//  - every chunk's CRC is recomputed before the bytes are written (libpng would refuse almost
//    every mutation on its CRC check otherwise);
//  - images within kMaxPngSide but of more than kMaxFuzzPixels pixels are skipped: readPng
//    allocates the whole RGBA buffer (up to 16384^2 * 4 bytes = 1 GiB) before it reads a row,
//    so a 60-byte file announcing a large image would cost a second and a gigabyte per run
//    (even a 1 Mpixel cap, 4 MiB zeroed per run, made the fuzzer eight times slower).
//    Sides above kMaxPngSide still go through, to exercise the refusal.
// libpng itself is not instrumented (it is the system library), so only its use is fuzzed.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "base/input_error.hpp"
#include "image/png_image.hpp"
#include "scratch_folder.hpp"

namespace {

using namespace shapevo;

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz_png_reader: invariant broken: %s\n", what);
    std::abort();
}
#define CHECK(cond) \
    do {            \
        if (!(cond)) broken(#cond); \
    } while (0)

constexpr std::uint64_t kMaxFuzzPixels = 1u << 16;
std::string folder;  // this process's temporary folder
std::string file;    // folder + "/fuzz.png"

std::uint32_t loadBE32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}
void storeBE32(std::uint8_t* p, std::uint32_t v) {
    p[0] = std::uint8_t(v >> 24);
    p[1] = std::uint8_t(v >> 16);
    p[2] = std::uint8_t(v >> 8);
    p[3] = std::uint8_t(v);
}

std::uint32_t crc32(const std::uint8_t* p, std::size_t n) {
    static const auto table = [] {
        std::vector<std::uint32_t> t(256);
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < n; ++i) c = table[(c ^ p[i]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

/// Rewrites the CRC of every complete chunk after the 8-byte signature.
void fixCrcs(std::vector<std::uint8_t>& b) {
    std::size_t at = 8;
    while (at + 12 <= b.size()) {
        const std::uint64_t length = loadBE32(&b[at]);
        if (length > b.size() - at - 12) break;
        storeBE32(&b[at + 8 + length], crc32(&b[at + 4], 4 + length));
        at += 12 + length;
    }
}

/// True if the IHDR announces an image readPng would accept but that is too large to fuzz.
bool tooLarge(const std::vector<std::uint8_t>& b) {
    if (b.size() < 24 || std::memcmp(&b[12], "IHDR", 4) != 0) return false;
    const std::uint64_t w = loadBE32(&b[16]), h = loadBE32(&b[20]);
    return w <= std::uint64_t(kMaxPngSide) && h <= std::uint64_t(kMaxPngSide) && w * h > kMaxFuzzPixels;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    folder = shapevo::fuzz::scratchFolder("fuzz_png_reader");
    file = folder + "/fuzz.png";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::uint8_t> bytes(data, data + size);
    fixCrcs(bytes);
    if (tooLarge(bytes)) return 0;
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size() || std::fclose(f) != 0) {
        std::perror(file.c_str());
        std::abort();
    }
    try {
        const PngImage image = readPng(file);
        CHECK(image.width >= 1 && image.width <= kMaxPngSide && image.height >= 1 && image.height <= kMaxPngSide);
        const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
        CHECK(image.luminance.size() == n && image.alpha.size() == n);
    } catch (const InputError& e) {
        CHECK(std::strncmp(e.what(), file.c_str(), file.size()) == 0);
    }
    return 0;
}

// ImageTarget: a target picture baked into bit rows of "hit" and "avoid" pixels, ready for the
// image scorer. A PixelRule says which pixels are which: luminance in the hit range -> hit,
// luminance in the avoid range -> avoid, anything else (and every pixel whose alpha is below
// the threshold) -> don't care. Defaults: dark (0..127) = hit, light (128..255) = avoid,
// alpha < 128 = don't care; on the papers' black-on-white targets that is "black = target".
// Rows run along x: row y (0 = the top row of the picture) starts at word y * wordsPerRow(),
// bit i of the row is pixel x = i.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace shapevo {

struct PixelRule {
    int hitMin = 0, hitMax = 127;      ///< luminance range of hit pixels (min > max: none)
    int avoidMin = 128, avoidMax = 255; ///< luminance range of avoid pixels (min > max: none)
    int alphaThreshold = 128;           ///< pixels with alpha below this are don't care (0: alpha ignored)

    /// InputError(file, section + ".<key>", ...) if a bound is outside 0..255 (threshold 0..256)
    /// or the two ranges overlap. Keys: hit_min, hit_max, avoid_min, avoid_max, alpha_threshold.
    void check(const std::string& file, const std::string& section) const;
    bool hit(int luminance) const { return luminance >= hitMin && luminance <= hitMax; }
    bool avoid(int luminance) const { return luminance >= avoidMin && luminance <= avoidMax; }
};

struct ImageTarget {
    std::string path;
    int width = 0, height = 0;
    std::vector<std::uint64_t> hit;    ///< pixels the model should cover (bit rows)
    std::vector<std::uint64_t> avoid;  ///< pixels the model should leave empty (bit rows)
    std::uint64_t hitCount = 0;
    std::uint64_t avoidCount = 0;
    std::uint64_t hash = 0;            ///< XXH3-64 of size and bits; identifies the target in outputs

    int wordsPerRow() const { return (width + 63) / 64; }
    bool isHit(int x, int y) const { return (hit[std::size_t(y) * std::size_t(wordsPerRow()) + std::size_t(x >> 6)] >> (x & 63)) & 1; }
    bool isAvoid(int x, int y) const { return (avoid[std::size_t(y) * std::size_t(wordsPerRow()) + std::size_t(x >> 6)] >> (x & 63)) & 1; }
};

/// Classify luminance/alpha bytes (row 0 = top) with `rule` (no checks on the result).
ImageTarget makeImageTarget(int width, int height, const std::vector<std::uint8_t>& luminance,
                            const std::vector<std::uint8_t>& alpha, const PixelRule& rule);

/// Read the PNG at `path` and classify its pixels. Throws InputError naming the file if it cannot
/// be read (see readPng), if its size is not expectedWidth x expectedHeight (the camera's image:
/// an odd-sized target), or if no pixel is a hit pixel (nothing to match).
ImageTarget loadImageTarget(const std::string& path, const PixelRule& rule, int expectedWidth, int expectedHeight);

}  // namespace shapevo

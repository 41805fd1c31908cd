// Image targets: pixel classification into bit rows, and loading from PNG with size checks.
#include "score/image_target.hpp"

#include "base/hash.hpp"
#include "base/input_error.hpp"
#include "image/png_image.hpp"

namespace shapevo {

namespace {
std::string range(int lo, int hi) { return lo > hi ? "none" : std::to_string(lo) + ".." + std::to_string(hi); }
std::string size(int w, int h) { return std::to_string(w) + " x " + std::to_string(h); }
}  // namespace

void PixelRule::check(const std::string& file, const std::string& section) const {
    auto bound = [&](int v, const char* key, int hi) {
        if (v < 0 || v > hi)
            throw InputError(file, section + "." + key,
                             std::to_string(v) + " is out of range [0, " + std::to_string(hi) + "]");
    };
    bound(hitMin, "hit_min", 255);
    bound(hitMax, "hit_max", 255);
    bound(avoidMin, "avoid_min", 255);
    bound(avoidMax, "avoid_max", 255);
    bound(alphaThreshold, "alpha_threshold", 256);
    if (hitMin <= hitMax && avoidMin <= avoidMax && hitMin <= avoidMax && avoidMin <= hitMax)
        throw InputError(file, section + ".avoid_min",
                         "the avoid luminance range " + range(avoidMin, avoidMax) + " overlaps the hit range " +
                             range(hitMin, hitMax) + "; a pixel can only be one of them");
}

ImageTarget makeImageTarget(int width, int height, const std::vector<std::uint8_t>& luminance,
                            const std::vector<std::uint8_t>& alpha, const PixelRule& rule) {
    ImageTarget t;
    t.width = width;
    t.height = height;
    const std::size_t W = std::size_t(t.wordsPerRow());
    t.hit.assign(W * std::size_t(height), 0);
    t.avoid.assign(W * std::size_t(height), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            if (alpha[i] < rule.alphaThreshold) continue;
            const std::size_t w = std::size_t(y) * W + std::size_t(x >> 6);
            const std::uint64_t bit = 1ULL << (x & 63);
            if (rule.hit(luminance[i])) {
                t.hit[w] |= bit;
                ++t.hitCount;
            } else if (rule.avoid(luminance[i])) {
                t.avoid[w] |= bit;
                ++t.avoidCount;
            }
        }
    Hasher h;
    h.addNumber(std::uint64_t(width));
    h.addNumber(std::uint64_t(height));
    for (std::uint64_t v : t.hit) h.addNumber(v);
    for (std::uint64_t v : t.avoid) h.addNumber(v);
    t.hash = h.digest();
    return t;
}

ImageTarget loadImageTarget(const std::string& path, const PixelRule& rule, int expectedWidth, int expectedHeight) {
    const PngImage image = readPng(path);
    if (image.width != expectedWidth || image.height != expectedHeight)
        throw InputError(path, "",
                         "odd-sized target: the image is " + size(image.width, image.height) + " pixels but the camera renders " +
                             size(expectedWidth, expectedHeight) + "; resize the image or set the camera's width and height");
    ImageTarget t = makeImageTarget(image.width, image.height, image.luminance, image.alpha, rule);
    t.path = path;
    if (t.hitCount == 0)
        throw InputError(path, "",
                         "no hit pixel: no pixel has luminance in " + range(rule.hitMin, rule.hitMax) +
                             " with alpha >= " + std::to_string(rule.alphaThreshold) + ", so there is nothing to match");
    return t;
}

}  // namespace shapevo

// Image targets: pixel classification into bit rows, the exact area-vote resampling into the
// camera's frame, and loading from PNG with its size and content checks.
#include "score/image/image_target.hpp"

#include <algorithm>
#include <cmath>

#include "base/hash.hpp"
#include "base/input_error.hpp"
#include "image/png_image.hpp"

namespace shapevo {

namespace {
std::string range(int lo, int hi) { return lo > hi ? "none" : std::to_string(lo) + ".." + std::to_string(hi); }
std::string size(int w, int h) { return std::to_string(w) + " x " + std::to_string(h); }

enum : std::uint8_t { kDontCare = 0, kHit = 1, kAvoid = 2 };

/// Counts and hash of a target whose bit rows are set.
void finish(ImageTarget& t) {
    t.hitCount = t.avoidCount = 0;
    for (std::uint64_t v : t.hit) t.hitCount += std::uint64_t(__builtin_popcountll(v));
    for (std::uint64_t v : t.avoid) t.avoidCount += std::uint64_t(__builtin_popcountll(v));
    Hasher h;
    h.addNumber(std::uint64_t(t.width));
    h.addNumber(std::uint64_t(t.height));
    for (std::uint64_t v : t.hit) h.addNumber(v);
    for (std::uint64_t v : t.avoid) h.addNumber(v);
    t.hash = h.digest();
}

/// One frame coordinate's share of the picture along one axis. In units where picture pixel i
/// spans [i * placed, (i + 1) * placed), placed pixel v spans [v * picture, (v + 1) * picture):
/// both are whole numbers, so overlaps are exact.
struct Span {
    int first = -1, last = -1;  ///< picture pixels it overlaps (first < 0: outside the picture)
    std::int64_t begin = 0, end = 0;
};

std::vector<Span> spans(int picture, int placed, int offset, int frame) {
    std::vector<Span> out(static_cast<std::size_t>(frame));
    for (int c = 0; c < frame; ++c) {
        const std::int64_t v = std::int64_t(c) - offset;
        if (v < 0 || v >= placed) continue;
        Span& s = out[std::size_t(c)];
        s.begin = v * picture;
        s.end = (v + 1) * picture;
        s.first = int(s.begin / placed);
        s.last = int((s.end - 1) / placed);
    }
    return out;
}

std::int64_t overlap(const Span& s, int i, int placed) {
    return std::min(s.end, std::int64_t(i + 1) * placed) - std::max(s.begin, std::int64_t(i) * placed);
}

/// Round a * b / c to the nearest whole number (halves up), at least 1.
int scaled(int a, int b, int c) {
    const std::int64_t v = (2 * std::int64_t(a) * b + c) / (2 * std::int64_t(c));
    return int(std::max<std::int64_t>(1, v));
}
}  // namespace

PixelRule PixelRule::forCover(TargetCover cover, int alphaThreshold) {
    PixelRule r;
    r.alphaThreshold = alphaThreshold;
    switch (cover) {
        case TargetCover::Auto: r.autoCover = true; break;
        case TargetCover::Dark: break;
        case TargetCover::Light: r.hitMin = 128, r.hitMax = 255, r.avoidMin = 0, r.avoidMax = 127; break;
        case TargetCover::Opaque: r.hitMin = 0, r.hitMax = 255, r.avoidMin = 1, r.avoidMax = 0, r.transparentAvoid = true; break;
    }
    return r;
}

const char* targetFitName(TargetFit fit) {
    switch (fit) {
        case TargetFit::Contain: return "contain";
        case TargetFit::Cover: return "cover";
        case TargetFit::Stretch: return "stretch";
        case TargetFit::Exact: return "exact";
    }
    return "?";
}

const char* targetCoverName(TargetCover cover) {
    switch (cover) {
        case TargetCover::Auto: return "auto";
        case TargetCover::Dark: return "dark";
        case TargetCover::Light: return "light";
        case TargetCover::Opaque: return "opaque";
    }
    return "?";
}

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

TargetPlacement placeTarget(int pw, int ph, int fw, int fh, TargetFit fit) {
    TargetPlacement p{0, 0, fw, fh};
    if (fit == TargetFit::Stretch || fit == TargetFit::Exact) return p;
    // The frame is relatively wider than the picture iff fw / fh > pw / ph.
    const bool frameWider = std::int64_t(fw) * ph > std::int64_t(fh) * pw;
    const bool heightRules = fit == TargetFit::Contain ? frameWider : !frameWider;
    if (heightRules) p.width = scaled(pw, fh, ph);
    else p.height = scaled(ph, fw, pw);
    if (fit == TargetFit::Contain) {
        p.width = std::min(p.width, fw), p.height = std::min(p.height, fh);
        p.x = (fw - p.width) / 2, p.y = (fh - p.height) / 2;
    } else {
        p.width = std::max(p.width, fw), p.height = std::max(p.height, fh);
        p.x = -((p.width - fw) / 2), p.y = -((p.height - fh) / 2);
    }
    return p;
}

TargetPlacement placeTarget(int pw, int ph, int fw, int fh, TargetFit fit, double scale) {
    if (scale >= 1.0 || (fit != TargetFit::Contain && fit != TargetFit::Stretch) || (pw == fw && ph == fh))
        return placeTarget(pw, ph, fw, fh, fit);
    const int bw = std::max(1, int(std::lround(fw * scale))), bh = std::max(1, int(std::lround(fh * scale)));
    TargetPlacement p = placeTarget(pw, ph, bw, bh, fit);
    p.x += (fw - bw) / 2, p.y += (fh - bh) / 2;
    return p;
}

ImageTarget makeImageTarget(int width, int height, const std::vector<std::uint8_t>& luminance,
                            const std::vector<std::uint8_t>& alpha, const PixelRule& rule) {
    ImageTarget t;
    t.width = t.pictureWidth = width;
    t.height = t.pictureHeight = height;
    t.placement = {0, 0, width, height};
    const std::size_t W = std::size_t(t.wordsPerRow());
    t.hit.assign(W * std::size_t(height), 0);
    t.avoid.assign(W * std::size_t(height), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            const std::size_t w = std::size_t(y) * W + std::size_t(x >> 6);
            const std::uint64_t bit = 1ULL << (x & 63);
            if (alpha[i] < rule.alphaThreshold) {
                if (rule.transparentAvoid) t.avoid[w] |= bit;
            } else if (rule.hit(luminance[i])) {
                t.hit[w] |= bit;
            } else if (rule.avoid(luminance[i])) {
                t.avoid[w] |= bit;
            }
        }
    finish(t);
    return t;
}

ImageTarget fitImageTarget(const ImageTarget& picture, int frameWidth, int frameHeight, const TargetPlacement& p) {
    const int pw = picture.width, ph = picture.height;
    if (frameWidth == pw && frameHeight == ph && p == TargetPlacement{0, 0, pw, ph}) {
        ImageTarget same = picture;
        same.placement = p;
        return same;
    }
    ImageTarget t;
    t.path = picture.path;
    t.width = frameWidth;
    t.height = frameHeight;
    t.pictureWidth = picture.pictureWidth;
    t.pictureHeight = picture.pictureHeight;
    t.placement = p;
    const std::size_t W = std::size_t(t.wordsPerRow());
    t.hit.assign(W * std::size_t(frameHeight), 0);
    t.avoid.assign(W * std::size_t(frameHeight), 0);
    const std::vector<Span> columns = spans(pw, p.width, p.x, frameWidth), rows = spans(ph, p.height, p.y, frameHeight);
    std::vector<std::uint8_t> classes;  // the picture rows of one frame row
    for (int y = 0; y < frameHeight; ++y) {
        const Span& row = rows[std::size_t(y)];
        if (row.first < 0) continue;
        const int nRows = row.last - row.first + 1;
        classes.resize(std::size_t(nRows) * std::size_t(pw));
        for (int j = 0; j < nRows; ++j)
            for (int i = 0; i < pw; ++i)
                classes[std::size_t(j) * std::size_t(pw) + std::size_t(i)] =
                    picture.isHit(i, row.first + j) ? kHit : picture.isAvoid(i, row.first + j) ? kAvoid : kDontCare;
        for (int x = 0; x < frameWidth; ++x) {
            const Span& col = columns[std::size_t(x)];
            if (col.first < 0) continue;
            std::int64_t area[3] = {0, 0, 0};
            for (int j = 0; j < nRows; ++j) {
                const std::int64_t wy = overlap(row, row.first + j, p.height);
                const std::uint8_t* c = &classes[std::size_t(j) * std::size_t(pw)];
                for (int i = col.first; i <= col.last; ++i) area[c[i]] += wy * overlap(col, i, p.width);
            }
            const std::size_t w = std::size_t(y) * W + std::size_t(x >> 6);
            const std::uint64_t bit = 1ULL << (x & 63);
            if (area[kHit] > 0 && area[kHit] >= area[kAvoid] && area[kHit] >= area[kDontCare]) t.hit[w] |= bit;
            else if (area[kAvoid] > 0 && area[kAvoid] >= area[kDontCare]) t.avoid[w] |= bit;
        }
    }
    finish(t);
    return t;
}

ImageTarget loadImageTarget(const std::string& path, const PixelRule& given, int frameWidth, int frameHeight, TargetFit fit,
                            double scale) {
    const PngImage image = readPng(path);
    // target.cover = "auto": a picture with a transparent pixel is a logo on transparency
    TargetCover autoCover = TargetCover::Auto;
    if (given.autoCover)
        autoCover = std::any_of(image.alpha.begin(), image.alpha.end(), [&](std::uint8_t a) { return a < given.alphaThreshold; })
                        ? TargetCover::Opaque
                        : TargetCover::Dark;
    const PixelRule rule = autoCover == TargetCover::Opaque ? PixelRule::forCover(TargetCover::Opaque, given.alphaThreshold) : given;
    if (image.width < kMinTargetSide || image.height < kMinTargetSide)
        throw InputError(path, "",
                         "the image is " + size(image.width, image.height) + " pixels, too small for a target: it needs at least " +
                             std::to_string(kMinTargetSide) + " pixels on a side (any larger size is fitted into the camera's frame)");
    if (fit == TargetFit::Exact && (image.width != frameWidth || image.height != frameHeight))
        throw InputError(path, "",
                         "odd-sized target: the image is " + size(image.width, image.height) + " pixels but the camera renders " +
                             size(frameWidth, frameHeight) + " and target.fit = \"exact\"; resize the image, set the camera's width "
                             "and height, or let the picture be fitted (target.fit = \"contain\", the default)");
    ImageTarget picture = makeImageTarget(image.width, image.height, image.luminance, image.alpha, rule);
    picture.path = path;
    const bool opaqueRule = rule.transparentAvoid && rule.hitMin == 0 && rule.hitMax == 255;
    if (opaqueRule && picture.avoidCount == 0)
        throw InputError(path, "",
                         "no transparent pixel: target.cover = \"opaque\" covers the pixels with alpha >= " +
                             std::to_string(rule.alphaThreshold) + " and avoids the others, but every pixel is opaque; "
                             "use target.cover = \"dark\" or \"light\" for a picture without a transparent background");
    ImageTarget t = fitImageTarget(picture, frameWidth, frameHeight, placeTarget(image.width, image.height, frameWidth, frameHeight, fit, scale));
    if (t.hitCount == 0) {
        const std::string which = opaqueRule ? "no pixel has alpha >= " + std::to_string(rule.alphaThreshold)
                                             : "no pixel has luminance in " + range(rule.hitMin, rule.hitMax) +
                                                   " with alpha >= " + std::to_string(rule.alphaThreshold);
        throw InputError(path, "",
                         "no hit pixel: " + which + (picture.hitCount > 0 ? " once fitted into the camera's frame" : "") +
                             (autoCover != TargetCover::Auto ? " (target.cover = \"auto\" chose \"" + std::string(targetCoverName(autoCover)) + "\")" : "") +
                             ", so there is nothing to match (target.cover = \"dark\" covers dark pixels, \"light\" light "
                             "ones, \"opaque\" the opaque ones of a picture on a transparent background)");
    }
    t.autoCover = autoCover;
    return t;
}

}  // namespace shapevo

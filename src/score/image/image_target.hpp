// ImageTarget: a target picture baked into bit rows of "hit" and "avoid" pixels of the camera's
// frame, ready for the image scorer.
//
// Which pixels are which (PixelRule): luminance in the hit range -> hit, luminance in the avoid
// range -> avoid, anything else -> don't care; a pixel whose alpha is below the threshold is don't
// care, or avoid when `transparentAvoid` is set. The presets (TargetCover, config key
// target.cover): "auto" (the default: "opaque" for a picture with transparency, i.e. at least one
// pixel whose alpha is below the threshold, "dark" for one without; loadImageTarget decides and
// says which in ImageTarget::autoCover), "dark" (0..127 hit, 128..255 avoid, transparent don't
// care; on the papers' black-on-white targets that is "black = target"), "light" (the ranges
// swapped) and "opaque" (alpha >= threshold hit whatever its colour, transparent avoid: white or
// coloured logos on a transparent background).
//
// How the picture meets the frame (TargetFit, config key target.fit): the picture is classified
// at its own size, then resampled into a rectangle of the frame (TargetPlacement):
//   contain (default)  aspect kept, as large as fits, centred; the margins are don't care;
//   cover              aspect kept, as small as fills the frame, centred; the overflow is cut off;
//   stretch            the whole frame, aspect not kept;
//   exact              the picture must be the frame's size (an error otherwise).
// contain and stretch may use a centred part of the frame only (target.scale, e.g. 0.6: the
// picture takes at most 60% of the frame's width and height; the rest is don't care), so that a
// logo is drawn at the size the scene's grammar can reach.
// Resampling is an exact, deterministic area vote: a frame pixel takes the class (hit, avoid,
// don't care) that covers most of its area in the picture, computed in integers; ties go to hit,
// then avoid. A picture of the frame's size comes through unchanged whatever the fit.
//
// Rows run along x: row y (0 = the top row of the frame) starts at word y * wordsPerRow(), bit i
// of the row is pixel x = i.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace shapevo {

enum class TargetCover { Auto, Dark, Light, Opaque };
enum class TargetFit { Contain, Cover, Stretch, Exact };

/// A picture smaller than this on a side is refused as a target: there is no shape in it.
inline constexpr int kMinTargetSide = 8;

struct PixelRule {
    int hitMin = 0, hitMax = 127;      ///< luminance range of hit pixels (min > max: none)
    int avoidMin = 128, avoidMax = 255; ///< luminance range of avoid pixels (min > max: none)
    int alphaThreshold = 128;           ///< pixels with alpha below this are transparent (0: none is)
    bool transparentAvoid = false;      ///< transparent pixels are avoid (else don't care)
    /// target.cover = "auto": loadImageTarget uses the opaque preset (same threshold) for a
    /// picture with a transparent pixel, and this rule (the dark ranges) for one without.
    /// makeImageTarget ignores it.
    bool autoCover = false;

    /// The rule of a preset (Auto: the dark ranges with autoCover set); `alphaThreshold` is kept
    /// as given.
    static PixelRule forCover(TargetCover cover, int alphaThreshold = 128);

    /// InputError(file, section + ".<key>", ...) if a bound is outside 0..255 (threshold 0..256)
    /// or the two ranges overlap. Keys: hit_min, hit_max, avoid_min, avoid_max, alpha_threshold.
    void check(const std::string& file, const std::string& section) const;
    bool hit(int luminance) const { return luminance >= hitMin && luminance <= hitMax; }
    bool avoid(int luminance) const { return luminance >= avoidMin && luminance <= avoidMax; }
};

/// Where the resampled picture lies in the frame: its top-left pixel (negative when `cover`
/// cuts it) and its size in frame pixels.
struct TargetPlacement {
    int x = 0, y = 0;
    int width = 0, height = 0;
    bool operator==(const TargetPlacement&) const = default;
};

/// The placement of a pictureWidth x pictureHeight picture in a frameWidth x frameHeight frame
/// (all sizes >= 1). Scaled sizes are rounded to the nearest pixel (at least 1); centring puts
/// the odd pixel of a margin (or of a cut) on the right / bottom. `exact` gives the whole frame
/// (loadImageTarget checks the sizes).
TargetPlacement placeTarget(int pictureWidth, int pictureHeight, int frameWidth, int frameHeight, TargetFit fit);

/// The same within a box of `scale` (in (0, 1]) times the frame's width and height, rounded (at
/// least 1 pixel), centred in the frame (config key target.scale: how much of the frame a picture
/// may take). Only for contain and stretch (cover and exact take the whole frame); a picture of
/// the frame's own size is placed on the whole frame whatever the scale: it was drawn for it.
TargetPlacement placeTarget(int pictureWidth, int pictureHeight, int frameWidth, int frameHeight, TargetFit fit,
                            double scale);

const char* targetFitName(TargetFit fit);      ///< "contain", "cover", "stretch", "exact"
const char* targetCoverName(TargetCover cover);  ///< "auto", "dark", "light", "opaque"

struct ImageTarget {
    std::string path;
    int width = 0, height = 0;         ///< the frame's size (the camera's picture)
    int pictureWidth = 0, pictureHeight = 0;  ///< the PNG's size (= width, height for makeImageTarget)
    TargetPlacement placement;         ///< where the picture lies in the frame
    std::vector<std::uint64_t> hit;    ///< pixels the model should cover (bit rows)
    std::vector<std::uint64_t> avoid;  ///< pixels the model should leave empty (bit rows)
    std::uint64_t hitCount = 0;
    std::uint64_t avoidCount = 0;
    std::uint64_t hash = 0;            ///< XXH3-64 of the frame's size and bits; identifies the target in outputs
    /// Under target.cover = "auto" (PixelRule::autoCover), the preset loadImageTarget chose: Opaque
    /// (the picture has a pixel with alpha below the threshold) or Dark; Auto otherwise.
    TargetCover autoCover = TargetCover::Auto;

    int wordsPerRow() const { return (width + 63) / 64; }
    bool isHit(int x, int y) const { return (hit[std::size_t(y) * std::size_t(wordsPerRow()) + std::size_t(x >> 6)] >> (x & 63)) & 1; }
    bool isAvoid(int x, int y) const { return (avoid[std::size_t(y) * std::size_t(wordsPerRow()) + std::size_t(x >> 6)] >> (x & 63)) & 1; }
};

/// Classify luminance/alpha bytes (row 0 = top) with `rule` at their own size (no checks on the
/// result).
ImageTarget makeImageTarget(int width, int height, const std::vector<std::uint8_t>& luminance,
                            const std::vector<std::uint8_t>& alpha, const PixelRule& rule);

/// Resample a classified picture into a frameWidth x frameHeight frame at `placement` (area vote,
/// above); frame pixels outside the placement are don't care. Keeps `path`; the hash is the
/// frame's.
ImageTarget fitImageTarget(const ImageTarget& picture, int frameWidth, int frameHeight, const TargetPlacement& placement);

/// Read the PNG at `path`, classify its pixels and fit them into the frameWidth x frameHeight
/// frame; under rule.autoCover the picture's transparency chooses the rule first (see PixelRule).
/// Throws InputError naming the file if it cannot be read (see readPng), if it is smaller
/// than kMinTargetSide on a side, if `fit` is exact and its size is not the frame's (an odd-sized
/// target), if no pixel of the fitted target is a hit pixel (nothing to match), or, for the
/// opaque preset (transparentAvoid with the full hit range), if no pixel is transparent.
ImageTarget loadImageTarget(const std::string& path, const PixelRule& rule, int frameWidth, int frameHeight,
                            TargetFit fit = TargetFit::Contain, double scale = 1.0);

}  // namespace shapevo

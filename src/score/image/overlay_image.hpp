// Overlay image: a model's silhouette against an image target, one colour per outcome, so a user
// sees at a glance where the model matches, falls short and overshoots:
//   hit      model and target both cover the pixel           bluish green
//   missed   the target wants the pixel, the model is absent  orange
//   extra    the model covers a pixel the target does not want (don't care or avoid)   blue
//   avoid    an avoid pixel the model leaves alone            light grey
//   otherwise (don't care, empty)                             white
// The colours are the Okabe-Ito palette, distinguishable with the common colour blindnesses.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/rgba.hpp"

namespace shapevo {

/// Target pixel values (one byte per pixel).
inline constexpr std::uint8_t kTargetDontCare = 0, kTargetHit = 1, kTargetAvoid = 2;

inline constexpr Rgba kOverlayHit{0, 158, 115, 255};
inline constexpr Rgba kOverlayMissed{230, 159, 0, 255};
inline constexpr Rgba kOverlayExtra{0, 114, 178, 255};
inline constexpr Rgba kOverlayAvoid{220, 220, 220, 255};
inline constexpr Rgba kOverlayBackground{255, 255, 255, 255};

/// The overlay colour of one pixel; target values other than hit and avoid count as don't care.
Rgba overlayColour(std::uint8_t target, bool model);

/// Writes the overlay of `model` (per pixel 0 or non-zero) on `target` (per pixel kTargetDontCare,
/// kTargetHit or kTargetAvoid) as an RGBA PNG. Both are `width` x `height`, row-major, row 0 at
/// the top of the image. The file appears atomically.
/// @throw InputError naming `path` if the size is not positive or the file cannot be written.
void writeOverlayPng(const std::string& path, int width, int height, const std::uint8_t* target,
                     const std::uint8_t* model);

/// Writes `mask` (per pixel 0 or non-zero, row-major, row 0 at the top) as an opaque PNG, black
/// where non-zero and white elsewhere: a target picture that cover "dark" reads as the mask. The
/// file appears atomically and never replaces one. @throw InputError naming `path`.
void writeMaskPng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& mask);

}  // namespace shapevo

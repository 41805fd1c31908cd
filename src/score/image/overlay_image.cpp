// Overlay image: classify each pixel (hit / missed / extra / avoid / background) and write a PNG.
#include "score/image/overlay_image.hpp"

#include <filesystem>

#include <vector>

#include "base/input_error.hpp"
#include "image/png_writer.hpp"

namespace shapevo {

Rgba overlayColour(std::uint8_t target, bool model) {
    if (target == kTargetHit) return model ? kOverlayHit : kOverlayMissed;
    if (model) return kOverlayExtra;
    return target == kTargetAvoid ? kOverlayAvoid : kOverlayBackground;
}

void writeOverlayPng(const std::string& path, int width, int height, const std::uint8_t* target,
                     const std::uint8_t* model) {
    if (width <= 0 || height <= 0)
        throw InputError(path, "", "cannot write a " + std::to_string(width) + " x " + std::to_string(height) + " image");
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<std::uint8_t> rgba(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        const Rgba c = overlayColour(target[i], model[i] != 0);
        for (int k = 0; k < 4; ++k) rgba[i * 4 + std::size_t(k)] = c[std::size_t(k)];
    }
    writePngRgba(path, width, height, rgba);
}

void writeMaskPng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& mask) {
    if (std::filesystem::exists(path)) throw InputError(path, "", "already exists; refusing to overwrite it");
    std::vector<std::uint8_t> rgba(mask.size() * 4, 255);
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) rgba[i * 4] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = 0;
    writePngRgba(path, width, height, rgba);
}

}  // namespace shapevo

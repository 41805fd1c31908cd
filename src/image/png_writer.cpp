// PNG writer: libpng's simplified write API onto the temporary file of writeAtomically.
#include "image/png_writer.hpp"

#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <png.h>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"

namespace shapevo {

void writePngRgba(const std::string& path, int width, int height, std::span<const std::uint8_t> rgba) {
    if (width <= 0 || height <= 0)
        throw InputError(path, "", "cannot write a " + std::to_string(width) + " x " + std::to_string(height) + " image");
    if (rgba.size() != std::size_t(width) * std::size_t(height) * 4)
        throw std::invalid_argument("writePngRgba: " + std::to_string(rgba.size()) + " bytes for " + std::to_string(width) +
                                    " x " + std::to_string(height) + " RGBA pixels");
    writeAtomically(path, [&](const std::string& temp) {
        png_image image;
        std::memset(&image, 0, sizeof image);
        image.version = PNG_IMAGE_VERSION;
        image.width = png_uint_32(width);
        image.height = png_uint_32(height);
        image.format = PNG_FORMAT_RGBA;
        const int ok = png_image_write_to_file(&image, temp.c_str(), 0, rgba.data(), 0, nullptr);
        const std::string message = image.message;
        png_image_free(&image);
        if (!ok) throw InputError(path, "", "cannot write PNG: " + message);
    });
}

}  // namespace shapevo

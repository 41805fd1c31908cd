// Model pictures: views side by side, written as PNG (model_picture.hpp).
#include "report/render/model_picture.hpp"

#include <charconv>

#include "base/input_error.hpp"
#include "image/png_writer.hpp"

namespace shapevo {

PictureSize parsePictureSize(const std::string& text, const std::string& option) {
    const auto bad = [&](const std::string& why) {
        return InputError(option, "", why + ", got \"" + shortened(text) + "\" (expected WIDTHxHEIGHT in pixels, e.g. 800x600)");
    };
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos) throw bad("no 'x' between width and height");
    int v[2] = {0, 0};
    const std::string parts[2] = {text.substr(0, x), text.substr(x + 1)};
    for (int i = 0; i < 2; ++i) {
        const char* end = parts[i].data() + parts[i].size();
        const auto [ptr, ec] = std::from_chars(parts[i].data(), end, v[i]);
        if (parts[i].empty() || ptr != end || ec != std::errc())
            throw bad(std::string(i == 0 ? "the width" : "the height") + " is not a whole number");
        if (v[i] < 16 || v[i] > kMaxPictureSide)
            throw bad(std::string(i == 0 ? "the width" : "the height") + " is outside 16 to " + std::to_string(kMaxPictureSide));
    }
    if ((long long)v[0] * v[1] > kMaxPicturePixels)
        throw bad("more than " + std::to_string(kMaxPicturePixels) + " pixels (4096x4096)");
    return {v[0], v[1]};
}

std::vector<std::uint8_t> renderViews(const Mesh& mesh, std::span<const View> views, PictureSize size,
                                      MeshRenderer& renderer) {
    const long long width = (long long)size.width * (long long)views.size();
    if (width * size.height > kMaxPicturePixels)
        throw InputError("--size", "", std::to_string(views.size()) + " views of " + std::to_string(size.width) + "x" +
                                           std::to_string(size.height) + " make more than " +
                                           std::to_string(kMaxPicturePixels) + " pixels: choose a smaller size");
    std::vector<std::uint8_t> rgba(std::size_t(width) * std::size_t(size.height) * 4);
    const BoundingSphere bounds = boundingSphere(mesh);
    for (std::size_t i = 0; i < views.size(); ++i)
        renderer.render(mesh, frameView(views[i], bounds, size.width, size.height), rgba, int(width),
                        int(i) * size.width, 0);
    return rgba;
}

void writeModelPicture(const Mesh& mesh, std::span<const View> views, PictureSize size, const std::string& path) {
    MeshRenderer renderer;
    const auto rgba = renderViews(mesh, views, size, renderer);
    writePngRgba(path, size.width * int(views.size()), size.height, rgba);
}

}  // namespace shapevo

// PNG reading with libpng (writing: image/png_writer.cpp). libpng reports errors by calling our
// handler, which longjmps back to the setjmp in decode(); that function holds no object with a
// destructor, so the jump skips nothing (every buffer lives in the caller).
#include "image/png_image.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "base/input_error.hpp"

namespace shapevo {

namespace {

struct LibpngContext {
    std::FILE* file = nullptr;
    bool endOfFile = false;
    char message[256] = "";
    char warning[256] = "";  ///< the last warning: libpng often explains an error in one first
    std::jmp_buf jump;
};

[[noreturn]] void onError(png_structp png, png_const_charp message) {
    auto* ctx = static_cast<LibpngContext*>(png_get_error_ptr(png));
    std::snprintf(ctx->message, sizeof ctx->message, "%s", message);
    std::longjmp(ctx->jump, 1);
}
void onWarning(png_structp png, png_const_charp message) {  // kept for the error that may follow
    auto* ctx = static_cast<LibpngContext*>(png_get_error_ptr(png));
    std::snprintf(ctx->warning, sizeof ctx->warning, "%s", message);
}

void readBytes(png_structp png, png_bytep data, std::size_t n) {
    auto* ctx = static_cast<LibpngContext*>(png_get_io_ptr(png));
    if (std::fread(data, 1, n, ctx->file) != n) {
        ctx->endOfFile = true;
        png_error(png, "the file ends too early");
    }
}

void toLuminanceAndAlpha(const std::uint8_t* rgba, std::size_t n, std::uint8_t* luminance, std::uint8_t* alpha) {
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* p = rgba + 4 * i;
        luminance[i] = std::uint8_t((299u * p[0] + 587u * p[1] + 114u * p[2] + 500u) / 1000u);
        alpha[i] = p[3];
    }
}

/// Decode into luminance and alpha bytes. Returns false on a libpng error (message in ctx).
/// Holds nothing with a destructor: every buffer belongs to the caller. Non-interlaced images
/// go through one RGBA row (`rgba`); interlaced ones through a full RGBA image and `rows`.
bool decode(LibpngContext& ctx, png_structp png, png_infop info, PngImage& image, std::vector<std::uint8_t>& rgba,
            std::vector<png_bytep>& rows) {
    if (setjmp(ctx.jump)) return false;
    png_set_read_fn(png, &ctx, readBytes);
    png_set_sig_bytes(png, 8);
    png_set_user_limits(png, kMaxPngSide, kMaxPngSide);  // readPng checked the IHDR already; a second guard
    // Read past the ancillary chunks we do not use (all but tRNS) without storing them: libpng
    // would allocate and zero the length a text or colour chunk announces (2 GB for a 45-byte
    // file) before it finds that the file is too short.
    static constexpr png_byte kUnused[] =
        "bKGD\0cHRM\0eXIf\0gAMA\0hIST\0iCCP\0iTXt\0oFFs\0pCAL\0pHYs\0sBIT\0sCAL\0sPLT\0sRGB\0sTER\0tEXt\0tIME\0zTXt";
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, kUnused, int(sizeof kUnused / 5));
    png_read_info(png, info);
    png_uint_32 w = 0, h = 0;
    int depth = 0, colour = 0, interlace = 0;
    png_get_IHDR(png, info, &w, &h, &depth, &colour, &interlace, nullptr, nullptr);
    png_set_expand(png);  // palette -> RGB, grey < 8 bits -> 8 bits, tRNS -> alpha
    png_set_scale_16(png);
    png_set_gray_to_rgb(png);
    if (!(colour & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS))
        png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_channels(png, info) != 4 || png_get_bit_depth(png, info) != 8 || png_get_rowbytes(png, info) != 4 * w)
        png_error(png, "unsupported pixel layout");
    image.width = int(w);
    image.height = int(h);
    const std::size_t n = std::size_t(w) * h;
    image.luminance.resize(n);
    image.alpha.resize(n);
    if (interlace == PNG_INTERLACE_NONE) {
        rgba.resize(std::size_t(w) * 4);
        for (png_uint_32 y = 0; y < h; ++y) {
            png_read_row(png, rgba.data(), nullptr);
            const std::size_t at = std::size_t(y) * w;
            toLuminanceAndAlpha(rgba.data(), w, image.luminance.data() + at, image.alpha.data() + at);
        }
    } else {
        rgba.resize(n * 4);
        rows.resize(h);
        for (png_uint_32 y = 0; y < h; ++y) rows[y] = rgba.data() + std::size_t(y) * w * 4;
        png_read_image(png, rows.data());
        toLuminanceAndAlpha(rgba.data(), n, image.luminance.data(), image.alpha.data());
    }
    png_read_end(png, nullptr);
    return true;
}

/// The size an IHDR chunk right after the signature announces (the PNG standard puts it first),
/// or false if the next chunk is not a well-formed IHDR (libpng then says what is wrong).
bool peekSize(std::FILE* f, std::uint64_t& width, std::uint64_t& height) {
    unsigned char b[16];
    const bool ok = std::fread(b, 1, 16, f) == 16 && std::memcmp(b, "\0\0\0\x0dIHDR", 8) == 0;
    std::fseek(f, 8, SEEK_SET);
    if (!ok) return false;
    auto big = [](const unsigned char* p) { return std::uint64_t(p[0]) << 24 | std::uint64_t(p[1]) << 16 | std::uint64_t(p[2]) << 8 | p[3]; };
    width = big(b + 8);
    height = big(b + 12);
    return true;
}

struct FileCloser {
    std::FILE* f;
    ~FileCloser() {
        if (f) std::fclose(f);
    }
};

}  // namespace

PngImage readPng(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path, "", "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, "", "not a regular file (expected a PNG image)");
    if (std::filesystem::file_size(path, ec) == 0) throw InputError(path, "", "the file is empty (expected a PNG image)");
    LibpngContext ctx;
    ctx.file = std::fopen(path.c_str(), "rb");
    if (!ctx.file) throw InputError(path, "", std::string("cannot open: ") + std::strerror(errno));
    FileCloser closer{ctx.file};
    png_byte signature[8] = {};
    const std::size_t got = std::fread(signature, 1, 8, ctx.file);
    if (got < 8 || png_sig_cmp(signature, 0, 8) != 0) throw InputError(path, "", "not a PNG file (bad signature)");

    std::uint64_t announcedWidth = 0, announcedHeight = 0;
    if (peekSize(ctx.file, announcedWidth, announcedHeight) &&
        (announcedWidth > std::uint64_t(kMaxPngSide) || announcedHeight > std::uint64_t(kMaxPngSide) ||
         announcedWidth * announcedHeight > std::uint64_t(kMaxPngPixels)))
        throw InputError(path, "",
                         "the image is " + std::to_string(announcedWidth) + " x " + std::to_string(announcedHeight) +
                             " pixels, over the size limit of " + std::to_string(kMaxPngSide) + " pixels on a side and " +
                             std::to_string(kMaxPngPixels) + " (64 Mpixel) in all; scale it down");
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, onError, onWarning);
    if (!png) throw std::bad_alloc();
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        throw std::bad_alloc();
    }
    PngImage image;
    std::vector<std::uint8_t> rgba;
    std::vector<png_bytep> rows;
    bool ok = false;
    try {
        ok = decode(ctx, png, info, image, rgba, rows);
    } catch (...) {  // std::bad_alloc from the buffers
        png_destroy_read_struct(&png, &info, nullptr);
        throw;
    }
    png_destroy_read_struct(&png, &info, nullptr);
    if (!ok) {
        if (ctx.endOfFile) throw InputError(path, "", "truncated PNG: the file ends before the image does");
        throw InputError(path, "", std::string("unreadable PNG: ") + ctx.message +
                                       (ctx.warning[0] ? std::string(" (") + ctx.warning + ")" : std::string()));
    }
    if (image.width <= 0 || image.height <= 0) throw InputError(path, "", "the image has no pixels");
    return image;
}

}  // namespace shapevo

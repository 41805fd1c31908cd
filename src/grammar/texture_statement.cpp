// The `texture NAME "FILE.png" (SX, SY)` statement (grammars/README.md, "Colours and
// materials"): NAME names the material (a word or a "string", as for `material`), FILE is read
// relative to the grammar file's folder when the grammar is loaded and must be a PNG that
// image/png_image.hpp reads, SX and SY are scalar expressions evaluated where the statement runs.
// Promises: every file is read once per grammar (a second statement naming the same file shares
// its bytes); a missing, unreadable or non-PNG file is one InputError at the file name's token
// that names the file as written and says why.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "base/input_error.hpp"
#include "grammar/parser_state.hpp"
#include "image/png_image.hpp"

namespace shapevo::grammar_detail {

namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

/// The bytes of texture `written` (as the grammar names it) at `file`, checked to be a readable
/// PNG; otherwise the reason, without location, in `why` (and an empty result).
std::vector<std::uint8_t> readTexture(const std::string& written, const std::filesystem::path& file, std::string& why) {
    std::string quoted(1, '\'');  // built step by step: GCC 12 warns (-Wrestrict) on literal + string
    quoted += shortened(written);
    quoted += '\'';
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        why = "cannot open texture " + quoted + ": no such file (" + shortened(file.string(), 200) + ")";
        return {};
    }
    if (!std::filesystem::is_regular_file(file, ec)) {
        why = "cannot open texture " + quoted + ": not a regular file";
        return {};
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        why = "cannot open texture " + quoted + ": " + std::strerror(errno);
        return {};
    }
    // the signature first: a file that is no PNG is never read whole (it may be huge)
    unsigned char head[sizeof kPngSignature] = {};
    in.read(reinterpret_cast<char*>(head), sizeof head);
    if (in.gcount() != std::streamsize(sizeof head) || std::memcmp(head, kPngSignature, sizeof head) != 0) {
        why = "texture " + quoted + " is not a PNG (" +
              (in.gcount() == 0 ? std::string("the file is empty") : std::string("it does not start with the PNG signature")) + ")";
        return {};
    }
    try {
        readPng(file.string());  // decodes every pixel: a damaged image fails here, not when a model is written
    } catch (const InputError& e) {
        why = "texture " + quoted + " is not a readable PNG: " + e.message();
        return {};
    }
    in.seekg(0);
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad() || bytes.size() < sizeof kPngSignature) {
        why = "cannot read texture " + quoted;
        return {};
    }
    return bytes;
}

}  // namespace

void Parser::parseTexture(const BodyScope& scope, Statement& s) {
    const Token name = tokens_.take();
    if (name.kind != TokenKind::String && name.kind != TokenKind::Identifier)
        tokens_.fail(name.where, "expected a material name after 'texture' (a word or \"text\"), found " + name.describe());
    const Token file = tokens_.take();
    if (file.kind != TokenKind::String)
        tokens_.fail(file.where, "expected the texture's file name in quotes after 'texture " + shortened(name.text) +
                                     "' (a PNG image, relative to the grammar's folder), found " + file.describe());
    std::size_t index = 0;
    while (index < g_.textures.size() && !(g_.textures[index].name == name.text && g_.textures[index].path == file.text))
        ++index;
    if (index == g_.textures.size()) {
        if (index >= 65535) tokens_.fail(file.where, "too many different textures (at most 65535)");
        Texture t;
        t.name = name.text;
        t.path = file.text;
        // An empty name would make an empty path, which std::filesystem::absolute throws on.
        if (file.text.empty()) tokens_.fail(file.where, "the texture's file name is empty (expected a PNG image, relative to the grammar's folder)");
        std::error_code ec;
        const std::filesystem::path relative = std::filesystem::path(g_.path).parent_path() / file.text;
        const std::filesystem::path absolute = std::filesystem::absolute(relative, ec);
        t.file = (ec ? relative : absolute).lexically_normal().string();
        for (const Texture& other : g_.textures)  // the same image under another name: read once
            if (other.file == t.file) t.png = other.png;
        if (t.png.empty()) {
            std::string why;
            t.png = readTexture(file.text, t.file, why);
            if (!why.empty()) tokens_.fail(file.where, why);
        }
        std::size_t material = 0;
        while (material < g_.materialNames.size() && g_.materialNames[material] != name.text) ++material;
        if (material == g_.materialNames.size()) {
            if (material >= 65535) tokens_.fail(name.where, "too many materials (at most 65534)");
            g_.materialNames.push_back(name.text);
        }
        t.material = std::uint16_t(material);
        g_.textures.push_back(std::move(t));
    }
    tokens_.expect('(', "after the texture's file name (its stretch factors (SX, SY) follow)");
    compileScalar(scope, s.expr[0]);
    tokens_.expect(',', "between the texture's stretch factors (SX, SY)");
    compileScalar(scope, s.expr[1]);
    tokens_.expect(')', "to close the texture's stretch factors (SX, SY)");
    s.kind = StatementKind::Texture;
    s.slot = std::uint16_t(index);
    g_.hasAppearance = true;
}

}  // namespace shapevo::grammar_detail

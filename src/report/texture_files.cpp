// Texture files beside an exported model: reuse an identical file, never replace another one.
#include "report/texture_files.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"

namespace shapevo {

namespace fs = std::filesystem;

namespace {

/// True if `path` is a regular file holding exactly `bytes`.
bool holds(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) != bytes.size()) return false;
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> there((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return !in.bad() && there == bytes;
}

/// "STEM_n.png" for n >= 2 ("bricks.png" -> "bricks_2.png").
std::string numbered(const std::string& name, int n) {
    if (n < 2) return name;
    const fs::path p(name);
    return p.stem().string() + "_" + std::to_string(n) + p.extension().string();
}

}  // namespace

PlacedTextures placeTextures(const Mesh& mesh, const std::string& folder) {
    PlacedTextures placed;
    try {
        for (const MeshTexture& t : mesh.textures) {
            for (int n = 1;; ++n) {
                const std::string name = numbered(t.name, n);
                const fs::path path = fs::path(folder) / name;
                std::error_code ec;
                if (fs::exists(path, ec) || fs::is_symlink(path, ec)) {
                    if (holds(path, t.png)) {
                        placed.names.push_back(name);
                        break;
                    }
                    continue;  // someone else's file: keep it, take the next name
                }
                try {
                    writeStreamAtomically(
                        path.string(),
                        [&](std::ostream& out) { out.write(reinterpret_cast<const char*>(t.png.data()), std::streamsize(t.png.size())); },
                        Replace::Never);
                } catch (const InputError&) {
                    if (!fs::exists(path, ec)) throw;
                    --n;  // it appeared meanwhile: look at what it holds
                    continue;
                }
                placed.created.push_back(path.string());
                placed.names.push_back(name);
                break;
            }
        }
    } catch (...) {
        removeCreated(placed);
        throw;
    }
    return placed;
}

void removeCreated(const PlacedTextures& placed) {
    std::error_code ec;
    for (const std::string& f : placed.created) fs::remove(f, ec);
}

}  // namespace shapevo

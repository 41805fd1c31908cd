// GLB writer: glTF JSON chunk (space-padded) and BIN chunk (zero-padded), both 4-byte aligned.
// Without materials the index accessor covers all triangles and no primitive names a material,
// so a plain mesh is the minimal file (positions and indices only); what materials add, and then
// what textures add, comes after everything a plain mesh writes, so neither changes its bytes.
#include "mesh/glb_writer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"
#include "mesh/mesh_material.hpp"

namespace shapevo {

namespace {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kLinear = 9729, kLinearMipmapLinear = 9987, kRepeat = 10497;

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
}
void appendF32(std::vector<std::uint8_t>& out, float v) { appendU32(out, std::bit_cast<std::uint32_t>(v)); }

/// %.9g round-trips every float.
void appendNumber(std::string& out, float v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.9g", double(v));
    out += s;
}
void appendVec3(std::string& out, const float v[3]) {
    out += '[';
    for (int a = 0; a < 3; ++a) {
        if (a > 0) out += ',';
        appendNumber(out, v[a]);
    }
    out += ']';
}

using Groups = std::vector<std::vector<std::uint32_t>>;  ///< trianglesByMaterial()

/// Bytes of image `k` in the binary buffer, padded to a multiple of 4.
std::size_t paddedImageBytes(const Mesh& mesh, std::size_t k) { return (mesh.textures[k].png.size() + 3) / 4 * 4; }

/// The binary buffer: positions, then the indices of each material's triangles, material after
/// material, then (with textures) the UVs (glTF's v = 1 - v) and each texture's PNG bytes, each
/// padded with zeros to a multiple of 4 bytes.
std::vector<std::uint8_t> binaryBuffer(const Mesh& mesh, const Groups& groups) {
    std::vector<std::uint8_t> bin;
    bin.reserve(mesh.vertices.size() * 12 + mesh.triangles.size() * 12 + mesh.uvs.size() * 8);
    for (const auto& v : mesh.vertices)
        for (int a = 0; a < 3; ++a) appendF32(bin, v[a]);
    for (const auto& group : groups)
        for (const std::uint32_t t : group)
            for (std::uint32_t i : mesh.triangles[t]) appendU32(bin, i);
    for (const auto& uv : mesh.uvs) {
        appendF32(bin, uv.x);
        appendF32(bin, 1.0f - uv.y);
    }
    for (std::size_t k = 0; k < mesh.textures.size(); ++k) {
        const auto& png = mesh.textures[k].png;
        bin.insert(bin.end(), png.begin(), png.end());
        bin.resize(bin.size() + paddedImageBytes(mesh, k) - png.size(), 0);
    }
    return bin;
}

std::string gltfJson(const Mesh& mesh, const Groups& groups, std::size_t binBytes) {
    std::string json = R"({"asset":{"version":"2.0","generator":"shapevo"},"scene":0,"scenes":[{"nodes":[0]}],)";
    if (mesh.triangles.empty()) {
        json += R"("nodes":[{"name":"shapevo model"}]})";
        return json;
    }
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) lo[a] = std::numeric_limits<float>::max(), hi[a] = -std::numeric_limits<float>::max();
    for (const auto& v : mesh.vertices)
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a]);
    const std::size_t positionBytes = mesh.vertices.size() * 12, indexBytes = mesh.triangles.size() * 12;
    // appended piece by piece: literal + std::string trips GCC 12's -Wrestrict false positive
    const auto add = [&json](auto... parts) {
        for (const std::string& p : {std::string(parts)...}) json += p;
    };
    const auto n = [](std::size_t v) { return std::to_string(v); };
    const bool materials = !mesh.materials.empty();
    const bool uvs = !mesh.uvs.empty();
    std::size_t primitives = 0;
    for (const auto& group : groups) primitives += group.empty() ? 0 : 1;
    const std::size_t uvAccessor = 1 + primitives;  // after the index accessors
    // one primitive per material that has triangles; its index accessor is 1 + its rank here
    add(R"("nodes":[{"mesh":0,"name":"shapevo model"}],)", R"("meshes":[{"name":"shapevo model","primitives":[)");
    std::size_t accessor = 1;
    for (std::size_t m = 0; m < groups.size(); ++m) {
        if (groups[m].empty()) continue;
        if (accessor > 1) json += ',';
        add(R"({"attributes":{"POSITION":0)", uvs ? R"(,"TEXCOORD_0":)" + n(uvAccessor) : std::string(), R"(},"indices":)",
            n(accessor));
        ++accessor;
        if (materials) add(R"(,"material":)", n(m));
        add(R"(,"mode":4})");
    }
    add("]}],");
    if (materials) {  // metallicFactor 0: a plain coloured surface (glTF's default would be metal)
        add(R"("materials":[)");
        for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
            const glm::vec3& c = mesh.materials[m].color;
            add(m ? "," : "", R"({"name":")", mesh.materials[m].name, R"(","pbrMetallicRoughness":{"baseColorFactor":[)");
            for (int a = 0; a < 3; ++a) {
                appendNumber(json, c[a]);
                json += ',';
            }
            add("1]");
            if (mesh.materials[m].texture >= 0)
                add(R"(,"baseColorTexture":{"index":)", n(std::size_t(mesh.materials[m].texture)), "}");
            add(R"(,"metallicFactor":0}})");
        }
        add("],");
    }
    const std::size_t firstImageView = uvs ? 3 : 2;  // after positions, indices and UVs
    if (!mesh.textures.empty()) {  // one sampler: linear, repeating
        add(R"("images":[)");
        for (std::size_t k = 0; k < mesh.textures.size(); ++k)
            add(k ? "," : "", R"({"bufferView":)", n(firstImageView + k), R"(,"mimeType":"image/png","name":")", mesh.textures[k].name, R"("})");
        add(R"(],"samplers":[{"magFilter":)", n(kLinear), R"(,"minFilter":)", n(kLinearMipmapLinear), R"(,"wrapS":)",
            n(kRepeat), R"(,"wrapT":)", n(kRepeat), R"(}],"textures":[)");
        for (std::size_t k = 0; k < mesh.textures.size(); ++k) add(k ? "," : "", R"({"sampler":0,"source":)", n(k), "}");
        add("],");
    }
    add(R"("accessors":[{"bufferView":0,"componentType":)", n(kFloat), R"(,"count":)", n(mesh.vertices.size()),
        R"(,"type":"VEC3","min":)");
    appendVec3(json, lo);
    add(R"(,"max":)");
    appendVec3(json, hi);
    add("}");
    std::size_t offset = 0;  // bytes into the index buffer view
    for (const auto& group : groups) {
        if (group.empty()) continue;
        add(R"(,{"bufferView":1,)");
        if (offset > 0) add(R"("byteOffset":)", n(offset), ",");
        add(R"("componentType":)", n(kUnsignedInt), R"(,"count":)", n(group.size() * 3), R"(,"type":"SCALAR"})");
        offset += group.size() * 12;
    }
    if (uvs) add(R"(,{"bufferView":2,"componentType":)", n(kFloat), R"(,"count":)", n(mesh.uvs.size()), R"(,"type":"VEC2"})");
    add("],");
    add(R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)", n(positionBytes), R"(,"target":)",
        n(kArrayBuffer), "},");
    add(R"({"buffer":0,"byteOffset":)", n(positionBytes), R"(,"byteLength":)", n(indexBytes), R"(,"target":)",
        n(kElementArrayBuffer), "}");
    std::size_t at = positionBytes + indexBytes;
    if (uvs) {
        add(R"(,{"buffer":0,"byteOffset":)", n(at), R"(,"byteLength":)", n(mesh.uvs.size() * 8), R"(,"target":)",
            n(kArrayBuffer), "}");
        at += mesh.uvs.size() * 8;
    }
    for (std::size_t k = 0; k < mesh.textures.size(); ++k) {
        add(R"(,{"buffer":0,"byteOffset":)", n(at), R"(,"byteLength":)", n(mesh.textures[k].png.size()), "}");
        at += paddedImageBytes(mesh, k);
    }
    add("],");
    add(R"("buffers":[{"byteLength":)", n(binBytes), "}]}");
    return json;
}

void check(const Mesh& mesh, const std::string& path) {
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(mesh.vertices[i][a]))
                throw InputError(path, "vertex " + std::to_string(i), "coordinate is not a finite number");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t i : mesh.triangles[t])
            if (i >= mesh.vertices.size())
                throw InputError(path, "triangle " + std::to_string(t), "vertex index " + std::to_string(i) + " out of range");
    checkMaterials(mesh, path);
}

}  // namespace

void writeGlb(const Mesh& mesh, const std::string& path, Replace replace) {
    check(mesh, path);
    const Groups groups = trianglesByMaterial(mesh);
    const std::vector<std::uint8_t> bin = mesh.triangles.empty() ? std::vector<std::uint8_t>{} : binaryBuffer(mesh, groups);
    std::string json = gltfJson(mesh, groups, bin.size());
    json.append((4 - json.size() % 4) % 4, ' ');  // chunks are 4-byte aligned; JSON pads with spaces

    std::vector<std::uint8_t> file;
    const std::size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
    if (total > std::numeric_limits<std::uint32_t>::max()) throw InputError(path, "", "model too large for a GLB file");
    file.reserve(total);
    appendU32(file, kMagic);
    appendU32(file, 2);
    appendU32(file, std::uint32_t(total));
    appendU32(file, std::uint32_t(json.size()));
    appendU32(file, kJsonChunk);
    file.insert(file.end(), json.begin(), json.end());
    if (!bin.empty()) {
        appendU32(file, std::uint32_t(bin.size()));
        appendU32(file, kBinChunk);
        file.insert(file.end(), bin.begin(), bin.end());
    }
    writeStreamAtomically(
        path, [&](std::ostream& out) { out.write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size())); },
        replace);
}

}  // namespace shapevo

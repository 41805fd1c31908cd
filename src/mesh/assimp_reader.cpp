// Assimp mesh import (every format but OBJ/PLY/STL): Assimp runs in a sandboxed child process
// (mesh/sandboxed_call.hpp), which flattens the scene (node transforms applied, triangulated,
// points and lines dropped) and sends the meshes back as a small binary message; the parent
// decodes that message defensively (every count checked against the bytes present before
// anything is reserved), checks each vertex and index, and merges the meshes into one Mesh.
// Assimp reads on past some broken faces, logging an error and guessing (its OFF reader clamps
// an index that is out of range to the last vertex): the child sends Assimp's error messages
// along, and the parent refuses the file for one about a vertex or face index and turns the
// others into warnings.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "base/input_error.hpp"
#include "mesh/mesh_formats.hpp"
#include "mesh/sandboxed_call.hpp"

namespace shapevo::meshio {

namespace {

// The child's message: 'M', then Assimp's logged errors (each the tag 'l', a uint32 length and
// the text), then per mesh (until the end marker 'E' 'N' 'D'): the mesh tag 'm', uint32 vertex
// count, that many float triples, uint32 face count, per face a uint32 corner count and that many
// uint32 indices. Or: 'X' and Assimp's error message.
constexpr char kMeshes = 'M', kError = 'X', kMeshTag = 'm', kLogTag = 'l';
constexpr char kEnd[] = "END";
/// At most this many of Assimp's logged errors are sent, each cut to kMaxLoggedChars.
constexpr std::size_t kMaxLoggedErrors = 20, kMaxLoggedChars = 300;

void putU32(std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }

/// Collects what Assimp logs as an error, without DefaultLogger's "Error, T0: " prefix, as one
/// line of printable characters.
class ErrorCollector : public Assimp::LogStream {
public:
    explicit ErrorCollector(std::vector<std::string>& lines) : lines_(lines) {}
    void write(const char* message) override {
        if (lines_.size() >= kMaxLoggedErrors) return;
        std::string text(message);
        if (text.rfind("Error, T", 0) == 0 && text.find(": ") != std::string::npos) text.erase(0, text.find(": ") + 2);
        for (char& c : text)  // one line of printable text (Assimp may quote the file's bytes)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
        while (!text.empty() && text.back() == ' ') text.pop_back();
        if (!text.empty()) lines_.push_back(text.substr(0, kMaxLoggedChars));
    }

private:
    std::vector<std::string>& lines_;
};

/// True for Assimp 5's messages about a face's vertex index it could not use ("OFF: Vertex index
/// is out of range", "OBJ: Invalid face index.", "LWOB: face index is out of range", "Face has an
/// invalid index. It will be ignored", "IRRMESH: Index out of range", ...): Assimp read on with
/// the index clamped or the face dropped, so the mesh is not the file's.
bool isFaceIndexError(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (const char* s : {"vertex index", "face index", "polygon index", "face has an invalid index", "irrmesh: index out of range"})
        if (text.find(s) != std::string::npos) return true;
    return false;
}

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

/// Runs in the child: import and flatten.
std::string importScene(const std::string& path) {
    // The child's own logger (the parent never creates one): errors only, no file, no console.
    std::vector<std::string> logged;
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(new ErrorCollector(logged), Assimp::Logger::Err);
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                           aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, flags);
    Assimp::DefaultLogger::kill();  // deletes the collector; `logged` keeps what it collected
    std::string out;
    if (!scene) {
        out += kError;
        out += importer.GetErrorString();
        return out;
    }
    out += kMeshes;
    for (const std::string& line : logged) {
        out += kLogTag;
        putU32(out, std::uint32_t(line.size()));
        out += line;
    }
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        if (!mesh) continue;
        out += kMeshTag;
        const std::uint32_t nv = mesh->mVertices ? mesh->mNumVertices : 0;
        putU32(out, nv);
        for (std::uint32_t v = 0; v < nv; ++v) {
            const aiVector3D& p = mesh->mVertices[v];
            const float xyz[3] = {p.x, p.y, p.z};
            out.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
        }
        const std::uint32_t nf = mesh->mFaces ? mesh->mNumFaces : 0;
        putU32(out, nf);
        for (std::uint32_t f = 0; f < nf; ++f) {
            const aiFace& face = mesh->mFaces[f];
            const std::uint32_t n = face.mIndices ? face.mNumIndices : 0;
            putU32(out, n);
            out.append(reinterpret_cast<const char*>(face.mIndices), std::size_t(n) * 4);
        }
    }
    out += kEnd;
    return out;
}

/// Reads the child's message (in the parent).
class Message {
public:
    Message(const std::string& bytes, const std::string& path) : data_(bytes), path_(path) {}
    std::size_t left() const { return data_.size() - pos_; }
    bool startsWith(std::string_view s) const { return data_.substr(pos_, s.size()) == s; }
    void skip(std::size_t n) { pos_ += n; }
    std::uint32_t u32() {
        need(4);
        std::uint32_t v;
        std::memcpy(&v, data_.data() + pos_, 4);
        pos_ += 4;
        return v;
    }
    float f32() {
        need(4);
        float v;
        std::memcpy(&v, data_.data() + pos_, 4);
        pos_ += 4;
        return v;
    }
    std::string text(std::size_t n) {
        need(n);
        std::string s(data_.substr(pos_, n));
        pos_ += n;
        return s;
    }
    /// Throws unless `count` items of `bytes` bytes each are still there.
    void needItems(std::uint64_t count, std::uint64_t bytes) const {
        if (count > left() / bytes) broken();
    }
    [[noreturn]] void broken() const {
        throw InputError(path_, "", "cannot read the mesh: the Assimp import process sent an incomplete result");
    }

private:
    void need(std::size_t n) const {
        if (left() < n) broken();
    }
    std::string_view data_;
    std::size_t pos_ = 0;
    const std::string& path_;
};

Mesh decode(const std::string& bytes, const std::string& path, const std::string& format) {
    Message in(bytes, path);
    if (in.left() == 0) throw InputError(path, "", "cannot read " + format + " mesh: the Assimp import sent nothing");
    if (bytes[0] == kError) {
        std::string text = bytes.substr(1, 4000);
        for (char& c : text)
            if (c == '\n' || c == '\r' || c == '\t') c = ' ';
        while (!text.empty() && text.back() == ' ') text.pop_back();
        text = shortened(text, 300);
        if (text.find("bad_alloc") != std::string::npos)
            text = "Assimp ran out of the memory shapevo allows an import of this file (" + text +
                   "); the file announces more data than it can hold, or is very large";
        if (text.empty()) text = "Assimp gave no reason";
        throw InputError(path, "", "cannot read " + format + " mesh: " + text);
    }
    if (bytes[0] != kMeshes) in.broken();
    in.skip(1);
    Mesh mesh;
    while (in.startsWith(std::string_view(&kLogTag, 1))) {
        in.skip(1);
        const std::uint32_t n = in.u32();
        in.needItems(n, 1);
        const std::string line = in.text(n);
        if (isFaceIndexError(line))
            throw InputError(path, "", "cannot read " + format + " mesh: a face has a vertex index Assimp could not use (Assimp: \"" +
                                           line + "\"); the file is malformed");
        mesh.warnings.push_back(path + ": Assimp: " + line);
    }
    std::uint64_t dropped = 0;
    for (std::uint32_t m = 0; !in.startsWith(kEnd); ++m) {
        if (!in.startsWith(std::string_view(&kMeshTag, 1))) in.broken();
        in.skip(1);
        const std::uint32_t nv = in.u32();
        in.needItems(nv, 12);
        const std::uint64_t base = mesh.vertices.size();
        if (base + nv > 0xffffffffull)
            throw InputError(path, "mesh " + std::to_string(m), "too many vertices (over 4294967295 in all)");
        for (std::uint32_t v = 0; v < nv; ++v) {
            const float x = in.f32(), y = in.f32(), z = in.f32();
            if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))  // finitePoint throws, naming the place
                finitePoint(x, y, z, path, "mesh " + std::to_string(m) + " vertex " + std::to_string(v));
            mesh.vertices.push_back({x, y, z});
        }
        const std::uint32_t nf = in.u32();
        in.needItems(nf, 4);
        for (std::uint32_t f = 0; f < nf; ++f) {
            const std::uint32_t n = in.u32();
            in.needItems(n, 4);
            std::uint32_t first = 0, previous = 0;
            for (std::uint32_t k = 0; k < n; ++k) {
                const std::uint32_t index = in.u32();
                if (index >= nv)
                    throw InputError(path, "mesh " + std::to_string(m) + " face " + std::to_string(f),
                                     "vertex index " + std::to_string(index) + " out of range (" +
                                         std::to_string(nv) + " vertices)");
                const std::uint32_t global = std::uint32_t(base + index);
                if (k == 0) first = global;
                else if (k >= 2) mesh.triangles.push_back({first, previous, global});
                previous = global;
            }
            if (n < 3) ++dropped;
        }
    }
    in.skip(std::strlen(kEnd));
    if (in.left() != 0) in.broken();
    if (dropped > 0)
        mesh.warnings.push_back(path + ": dropped " + std::to_string(dropped) +
                                " face(s) with fewer than 3 vertices (points or lines)");
    return mesh;
}

}  // namespace

bool assimpReads(const std::string& extension) {
    if (extension.size() < 2 || extension[0] != '.') return false;
    Assimp::Importer importer;
    return importer.IsExtensionSupported(extension);
}

std::vector<std::string> assimpExtensionList() {
    Assimp::Importer importer;
    std::string list;  // "*.3d;*.3ds;..."
    importer.GetExtensionList(list);
    std::vector<std::string> out;
    for (std::size_t start = 0; start < list.size();) {
        std::size_t end = list.find(';', start);
        if (end == std::string::npos) end = list.size();
        std::string ext = list.substr(start, end - start);
        if (ext.rfind("*", 0) == 0) ext.erase(0, 1);
        for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext.size() > 1) out.push_back(ext);
        start = end + 1;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Mesh importWithAssimp(const std::string& path, std::uint64_t fileBytes, const MeshReadLimits& limits) {
    std::string format = std::filesystem::path(path).extension().string();
    if (!format.empty()) format.erase(0, 1);
    format = upper(format);
    SandboxLimits box;
    box.memoryBytes = limits.memoryBytes + std::min<std::uint64_t>(fileBytes, 1ull << 40) * limits.memoryPerFileByte;
    box.maxOutputBytes = box.memoryBytes;
    box.seconds = limits.seconds + limits.secondsPerMiB * double(fileBytes) / double(1 << 20);
    SandboxResult r;
    try {
        r = sandboxedCall([&path] { return importScene(path); }, box);
    } catch (const std::runtime_error& e) {
        throw InputError(path, "", "cannot read " + format + " mesh: cannot start the import process (" + e.what() + ")");
    }
    if (r.outcome != SandboxResult::Outcome::Finished)
        throw InputError(path, "", "cannot read " + format + " mesh: Assimp could not import it: " +
                                       describeFailure(r, box) + "; the file is malformed, hostile or too large");
    return decode(r.output, path, format);
}

}  // namespace shapevo::meshio

// Mesh file input: refuses missing, non-regular, empty and oversized files, picks the reader by
// extension (ours for OBJ/PLY/STL, Assimp for the rest), runs the same checks on every result
// (finite coordinates, indices in range, at least one triangle with an area), and checks closedness (every
// edge shared by exactly two triangles) for volume targets.
#include "mesh/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "base/input_error.hpp"
#include "mesh/mesh_formats.hpp"

namespace shapevo {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string sizeText(std::uint64_t bytes) {
    std::ostringstream s;
    s.precision(3);
    if (bytes >= (1ull << 30)) s << double(bytes) / double(1ull << 30) << " GiB";
    else if (bytes >= (1ull << 20)) s << double(bytes) / double(1ull << 20) << " MiB";
    else s << bytes << " bytes";
    return s.str();
}

/// Refuses what is no regular file, is empty or is too large; returns the size.
std::uint64_t checkedFileSize(const std::string& path, const MeshReadLimits& limits) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw InputError(path, "", "cannot open mesh file: no such file");
    if (std::filesystem::is_directory(status)) throw InputError(path, "", "cannot open mesh: is a directory");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(path, "", "cannot open mesh: not a regular file (a device, pipe or socket)");
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(path, "", "cannot open mesh file: " + ec.message());
    if (size == 0) throw InputError(path, "", "mesh file is empty");
    if (size > limits.maxFileBytes)
        throw InputError(path, "", "mesh file is " + sizeText(size) + ", over shapevo's limit of " +
                                       sizeText(limits.maxFileBytes) + " for mesh files");
    return size;
}

std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot open mesh file");
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path, "", "error while reading mesh file");
    return data;
}

std::string unknownExtensionMessage(const std::string& ext) {
    const std::vector<std::string> more = assimpMeshExtensions();
    std::string examples;
    for (const char* e : {".off", ".gltf", ".glb", ".fbx", ".3mf", ".dae", ".3ds"})
        if (std::find(more.begin(), more.end(), e) != more.end()) examples += std::string(examples.empty() ? "" : ", ") + e;
    std::string all;
    for (const std::string& e : more) all += " " + e;
    return "unknown mesh extension '" + ext + "': shapevo reads .obj, .ply and .stl itself and " +
           std::to_string(more.size()) + " more extensions through Assimp (" + examples + ", ...; all:" + all + ")";
}

/// True when triangle `t`'s corners span a positive area (computed in double, so that tiny
/// triangles of float coordinates do not underflow).
bool hasArea(const Mesh& mesh, const std::array<std::uint32_t, 3>& t) {
    const glm::dvec3 a(mesh.vertices[t[0]]), b(mesh.vertices[t[1]]), c(mesh.vertices[t[2]]);
    return glm::length(glm::cross(b - a, c - a)) > 0.0;
}

/// The checks every reader's result gets, whatever the format.
void checkMesh(const Mesh& mesh, const std::string& path) {
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const glm::vec3& p = mesh.vertices[v];
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))  // it throws, naming the vertex
            meshio::finitePoint(p.x, p.y, p.z, path, "vertex " + std::to_string(v));
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t i : mesh.triangles[t])
            if (i >= mesh.vertices.size())
                throw InputError(path, "triangle " + std::to_string(t),
                                 "vertex index " + std::to_string(i) + " out of range (" +
                                     std::to_string(mesh.vertices.size()) + " vertices)");
    if (mesh.triangles.empty()) throw InputError(path, "", "mesh has no triangles");
    if (std::none_of(mesh.triangles.begin(), mesh.triangles.end(), [&](const auto& t) { return hasArea(mesh, t); }))
        throw InputError(path, "", "mesh has no valid face: " +
                                       (mesh.triangles.size() == 1 ? std::string("its only triangle is")
                                                                   : "all " + std::to_string(mesh.triangles.size()) + " triangles are") +
                                       " degenerate (two corners at one position, or all three on a line)");
}

std::string formatPoint(const glm::vec3& p) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

}  // namespace

Mesh readMesh(const std::string& path, const MeshReadLimits& limits) {
    const std::string ext = lowerExtension(path);
    const bool own = ext == ".obj" || ext == ".ply" || ext == ".stl";
    if (!own && !meshio::assimpReads(ext)) throw InputError(path, "", unknownExtensionMessage(ext));
    const std::uint64_t size = checkedFileSize(path, limits);
    Mesh mesh;
    if (own) {
        const std::string data = readWholeFile(path);
        mesh = ext == ".obj"   ? meshio::parseObj(data, path)
               : ext == ".ply" ? meshio::parsePly(data, path)
                               : meshio::parseStl(data, path);
    } else {
        mesh = meshio::importWithAssimp(path, size, limits);
    }
    checkMesh(mesh, path);
    return mesh;
}

std::vector<std::string> assimpMeshExtensions() { return meshio::assimpExtensionList(); }

void requireClosed(const Mesh& mesh, const std::string& path) {
    // Canonical id per distinct position, so seams with duplicated vertices still count as shared.
    Mesh welded;
    meshio::VertexWelder welder(welded);
    std::vector<std::uint32_t> canon(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) canon[i] = welder.add(mesh.vertices[i]);

    std::unordered_map<std::uint64_t, std::uint32_t> uses;  // key: (low id << 32) | high id
    uses.reserve(mesh.triangles.size() * 2);
    for (const auto& t : mesh.triangles) {
        for (int e = 0; e < 3; ++e) {
            std::uint32_t a = canon.at(t[e]), b = canon.at(t[(e + 1) % 3]);
            if (a == b) continue;  // a collapsed edge of a degenerate triangle bounds nothing
            if (a > b) std::swap(a, b);
            ++uses[std::uint64_t(a) << 32 | b];
        }
    }
    std::size_t open = 0;
    std::uint64_t exampleKey = 0;
    std::uint32_t exampleUses = 0;
    for (const auto& [key, count] : uses) {
        if (count == 2) continue;
        // Report the smallest key so the example is the same on every run.
        if (open == 0 || key < exampleKey) exampleKey = key, exampleUses = count;
        ++open;
    }
    if (open == 0) return;
    const glm::vec3& a = welded.vertices[exampleKey >> 32];
    const glm::vec3& b = welded.vertices[exampleKey & 0xffffffffu];
    throw InputError(path, "",
                     "mesh is not closed: " + std::to_string(open) +
                         (open == 1 ? " edge is" : " edges are") +
                         " not shared by exactly two triangles, e.g. the edge " + formatPoint(a) + " - " +
                         formatPoint(b) + " used by " + std::to_string(exampleUses) + " triangle(s)");
}

}  // namespace shapevo

// Mesh file input: picks the parser by extension, enforces "at least one triangle", and
// checks closedness (every edge shared by exactly two triangles) for volume targets.
#include "mesh/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>

#include "base/input_error.hpp"
#include "mesh/mesh_formats.hpp"

namespace shapevo {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string readWholeFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "cannot open mesh: is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot open mesh file");
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path, "", "error while reading mesh file");
    return data;
}

std::string formatPoint(const glm::vec3& p) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

}  // namespace

Mesh readMesh(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".obj" && ext != ".ply" && ext != ".stl")
        throw InputError(path, "",
                         "unknown mesh extension '" + ext + "' (expected .obj, .ply or .stl)");
    const std::string data = readWholeFile(path);
    Mesh mesh = ext == ".obj"   ? meshio::parseObj(data, path)
                : ext == ".ply" ? meshio::parsePly(data, path)
                                : meshio::parseStl(data, path);
    if (mesh.triangles.empty()) throw InputError(path, "", "mesh has no triangles");
    return mesh;
}

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

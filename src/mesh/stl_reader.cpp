// STL parser (ascii and binary). STL stores a triangle soup, so vertices with exactly equal
// positions are welded into shared indices. Binary is recognised by its exact size; a file that
// starts with "solid" and does not match that size is read as ascii.
#include <string>
#include <vector>

#include "base/little_endian.hpp"
#include "mesh/mesh_formats.hpp"

namespace shapevo::meshio {

namespace {

constexpr std::size_t kHeaderBytes = 84;    // 80-byte header + uint32 triangle count
constexpr std::size_t kTriangleBytes = 50;  // normal, 3 vertices (12 floats), uint16 attribute

bool startsWithSolid(std::string_view data) {
    Tokens tokens(data.substr(0, 256));
    return tokens.next() == "solid";
}

Mesh parseBinary(std::string_view data, const std::string& path) {
    if (data.size() < kHeaderBytes)
        throw InputError(path, "", "too short for a binary STL (" + std::to_string(data.size()) + " bytes)");
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    const std::uint64_t count = le::load<std::uint32_t>(bytes + 80);
    const std::uint64_t room = (data.size() - kHeaderBytes) / kTriangleBytes;
    if (count > room)
        throw InputError(path, "", "truncated binary STL: header announces " + std::to_string(count) +
                                       " triangles, the file holds " + std::to_string(room));
    Mesh mesh;
    VertexWelder welder(mesh);
    mesh.triangles.reserve(count);
    for (std::uint64_t t = 0; t < count; ++t) {
        const unsigned char* p = bytes + kHeaderBytes + t * kTriangleBytes + 12;  // skip the normal
        std::array<std::uint32_t, 3> tri{};
        for (int v = 0; v < 3; ++v, p += 12) {
            const glm::vec3 q = finitePoint(le::load<float>(p), le::load<float>(p + 4), le::load<float>(p + 8), path,
                                            "triangle " + std::to_string(t));
            tri[v] = welder.add(q);
        }
        mesh.triangles.push_back(tri);
    }
    return mesh;
}

Mesh parseAscii(std::string_view data, const std::string& path) {
    Mesh mesh;
    VertexWelder welder(mesh);
    std::vector<std::uint32_t> polygon;
    bool open = false;  // inside a facet whose vertices are not yet turned into triangles
    std::size_t lineNo = 0, facetLine = 0;
    auto flush = [&](std::size_t line) {
        if (polygon.size() < 3)
            throw InputError(path, std::to_string(line),
                             "facet has " + std::to_string(polygon.size()) + " vertices, needs at least 3");
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
            mesh.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
        polygon.clear();
        open = false;
    };
    while (!data.empty()) {
        const std::size_t eol = data.find('\n');
        const std::string_view line = data.substr(0, eol);
        data.remove_prefix(eol == std::string_view::npos ? data.size() : eol + 1);
        ++lineNo;
        Tokens tokens(line);
        const std::string_view keyword = tokens.next();
        if (keyword == "facet") {
            if (open) flush(lineNo);
            polygon.clear();
            open = true;
            facetLine = lineNo;
        } else if (keyword == "vertex") {
            const std::string where = std::to_string(lineNo);
            if (!open) throw InputError(path, where, "vertex outside a facet");
            double c[3];
            for (double& v : c) {
                const std::string_view t = tokens.next();
                if (t.empty()) throw InputError(path, where, "vertex needs 3 coordinates");
                v = parseDouble(t, path, where);
            }
            polygon.push_back(welder.add(finitePoint(c[0], c[1], c[2], path, where)));
        } else if (keyword == "endloop" || keyword == "endfacet") {
            if (open) flush(lineNo);
        }
        // solid, outer loop, endsolid and facet normals carry nothing we need.
    }
    if (open) throw InputError(path, std::to_string(facetLine), "facet is not terminated");
    return mesh;
}

}  // namespace

Mesh parseStl(std::string_view data, const std::string& path) {
    if (data.size() >= kHeaderBytes) {
        const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
        const std::uint64_t count = le::load<std::uint32_t>(bytes + 80);
        if (data.size() == kHeaderBytes + count * kTriangleBytes) return parseBinary(data, path);
    }
    return startsWithSolid(data) ? parseAscii(data, path) : parseBinary(data, path);
}

}  // namespace shapevo::meshio

// Wavefront OBJ parser: `v` positions and `f` faces (v, v/vt, v/vt/vn, v//vn; negative indices
// count back from the last vertex read). Polygons are fan-triangulated; other records are ignored.
#include <string>

#include "mesh/mesh_formats.hpp"

namespace shapevo::meshio {

namespace {

/// Resolves one face corner ("7", "-1", "7/2/3", "7//3") to a 0-based vertex index.
std::uint32_t faceCorner(std::string_view corner, std::size_t vertexCount, const std::string& path,
                         const std::string& where) {
    const std::string_view position = corner.substr(0, corner.find('/'));
    const long long raw = parseInteger(position, path, where);
    const long long n = static_cast<long long>(vertexCount);
    const long long index = raw < 0 ? n + raw : raw - 1;  // OBJ counts from 1; -1 is the last vertex
    if (raw == 0 || index < 0 || index >= n)
        throw InputError(path, where,
                         "face index " + std::to_string(raw) + " out of range (" + std::to_string(n) +
                             " vertices defined so far)");
    return static_cast<std::uint32_t>(index);
}

}  // namespace

Mesh parseObj(std::string_view data, const std::string& path) {
    Mesh mesh;
    std::vector<std::uint32_t> polygon;
    std::size_t lineNo = 0;
    while (!data.empty()) {
        const std::size_t eol = data.find('\n');
        std::string_view line = data.substr(0, eol);
        data.remove_prefix(eol == std::string_view::npos ? data.size() : eol + 1);
        ++lineNo;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);

        Tokens tokens(line);
        const std::string_view keyword = tokens.next();
        if (keyword == "v") {
            const std::string where = std::to_string(lineNo);
            double c[3];
            for (double& v : c) {
                const std::string_view t = tokens.next();
                if (t.empty()) throw InputError(path, where, "vertex needs 3 coordinates");
                v = parseDouble(t, path, where);
            }
            // A 4th value (w) or vertex colours may follow; they do not affect the shape.
            mesh.vertices.push_back(finitePoint(c[0], c[1], c[2], path, where));
        } else if (keyword == "f") {
            const std::string where = std::to_string(lineNo);
            polygon.clear();
            for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next())
                polygon.push_back(faceCorner(t, mesh.vertices.size(), path, where));
            if (polygon.size() < 3)
                throw InputError(path, where,
                                 "face has " + std::to_string(polygon.size()) + " vertices, needs at least 3");
            for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
                mesh.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
        }
        // vt, vn, g, o, s, usemtl, mtllib, l, p, ...: not part of the solid's shape.
    }
    return mesh;
}

}  // namespace shapevo::meshio

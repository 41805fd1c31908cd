// Model writers: a model's surface (geometry/tessellation.hpp) as OBJ / PLY, written atomically.
#include "report/model_writer.hpp"

#include <cstdio>

#include "geometry/tessellation.hpp"
#include "base/atomic_write.hpp"

namespace shapevo {

Mesh meshOf(const Geometry& geometry) { return tessellate(geometry); }

void writeObj(const Mesh& mesh, const std::string& path) {
    writeStreamAtomically(path, [&](std::ostream& out) {
        out << "# written by shapevo: " << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
        char line[128];
        for (const auto& v : mesh.vertices) {
            std::snprintf(line, sizeof line, "v %.6g %.6g %.6g\n", double(v.x), double(v.y), double(v.z));
            out << line;
        }
        for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    });
}

void writePly(const Mesh& mesh, const std::string& path) {
    writeStreamAtomically(path, [&](std::ostream& out) {
        out << "ply\nformat binary_little_endian 1.0\ncomment written by shapevo\nelement vertex " << mesh.vertices.size()
            << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.triangles.size()
            << "\nproperty list uchar uint vertex_indices\nend_header\n";
        for (const auto& v : mesh.vertices) out.write(reinterpret_cast<const char*>(&v.x), 3 * sizeof(float));
        for (const auto& t : mesh.triangles) {
            const unsigned char n = 3;
            out.write(reinterpret_cast<const char*>(&n), 1);
            out.write(reinterpret_cast<const char*>(t.data()), 3 * sizeof(std::uint32_t));
        }
    });
}

}  // namespace shapevo

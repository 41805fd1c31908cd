// Model writers: box triangulation and OBJ / PLY output (written to a temporary file, then renamed).
#include "io/model_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <glm/glm.hpp>

namespace shapevo {

namespace {
// Corners indexed by bits (x, y, z) = (i & 1, i >> 1 & 1, i >> 2 & 1); outward CCW quads.
constexpr int kQuads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

std::ofstream openTemp(const std::string& path, std::string& temp) {
    temp = path + ".tmp";
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + path);
    return out;
}
void publish(std::ofstream& out, const std::string& temp, const std::string& path) {
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path);
    std::filesystem::rename(temp, path);
}
}  // namespace

Mesh meshOf(const Geometry& geometry) {
    Mesh m;
    m.vertices.reserve(geometry.primitives.size() * 8);
    m.triangles.reserve(geometry.primitives.size() * 12);
    for (const Primitive& p : geometry.primitives) {
        const auto base = std::uint32_t(m.vertices.size());
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 s((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
            m.vertices.push_back(p.centre + p.axes * (s * p.half));
        }
        const bool flipped = glm::determinant(p.axes) < 0;
        for (const auto& q : kQuads) {
            std::uint32_t a = base + q[0], b = base + q[1], c = base + q[2], d = base + q[3];
            if (flipped) std::swap(b, d);
            m.triangles.push_back({a, b, c});
            m.triangles.push_back({a, c, d});
        }
    }
    return m;
}

void writeObj(const Mesh& mesh, const std::string& path) {
    std::string temp;
    std::ofstream out = openTemp(path, temp);
    out << "# written by shapevo: " << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
    char line[128];
    for (const auto& v : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.6g %.6g %.6g\n", double(v.x), double(v.y), double(v.z));
        out << line;
    }
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    publish(out, temp, path);
}

void writePly(const Mesh& mesh, const std::string& path) {
    std::string temp;
    std::ofstream out = openTemp(path, temp);
    out << "ply\nformat binary_little_endian 1.0\ncomment written by shapevo\nelement vertex " << mesh.vertices.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.triangles.size()
        << "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (const auto& v : mesh.vertices) out.write(reinterpret_cast<const char*>(&v.x), 3 * sizeof(float));
    for (const auto& t : mesh.triangles) {
        const unsigned char n = 3;
        out.write(reinterpret_cast<const char*>(&n), 1);
        out.write(reinterpret_cast<const char*>(t.data()), 3 * sizeof(std::uint32_t));
    }
    publish(out, temp, path);
}

}  // namespace shapevo

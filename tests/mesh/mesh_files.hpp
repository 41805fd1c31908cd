// Test helpers: a Mesh written as the text (or bytes) of mesh formats that shapevo reads through
// Assimp (OFF, glTF with an embedded or an external buffer, COLLADA, 3MF), and measures to compare
// what was read with what was written (signed volume, bounds).
#pragma once
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"

namespace shapevo::test {

/// OFF: a header line, the counts, the vertices, one "3 a b c" line per triangle.
inline std::string toOff(const Mesh& m) {
    std::ostringstream s;
    s << "OFF\n# a test mesh\n" << m.vertices.size() << ' ' << m.triangles.size() << " 0\n";
    for (const auto& v : m.vertices) s << v.x << ' ' << v.y << ' ' << v.z << '\n';
    for (const auto& t : m.triangles) s << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return s.str();
}

/// The glTF buffer: positions (float VEC3) then indices (uint32).
inline std::string gltfBuffer(const Mesh& m) {
    std::string b;
    for (const auto& v : m.vertices) b.append(reinterpret_cast<const char*>(&v.x), 12);
    for (const auto& t : m.triangles) b.append(reinterpret_cast<const char*>(t.data()), 12);
    return b;
}

inline std::string base64(const std::string& bytes) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = std::uint32_t(std::uint8_t(bytes[i])) << 16 |
                                (i + 1 < bytes.size() ? std::uint32_t(std::uint8_t(bytes[i + 1])) << 8 : 0) |
                                (i + 2 < bytes.size() ? std::uint32_t(std::uint8_t(bytes[i + 2])) : 0);
        out += abc[n >> 18 & 63];
        out += abc[n >> 12 & 63];
        out += i + 1 < bytes.size() ? abc[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? abc[n & 63] : '=';
    }
    return out;
}

/// A glTF 2.0 JSON file: one mesh under one node translated by `move`; the buffer is `uri`
/// (a file name beside it, or empty for a base64 data URI).
inline std::string toGltf(const Mesh& m, const glm::vec3& move, const std::string& uri = "") {
    const std::string buffer = gltfBuffer(m);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const auto& v : m.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const std::size_t vertexBytes = m.vertices.size() * 12;
    std::ostringstream s;
    s << "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
      << "\"nodes\":[{\"mesh\":0,\"translation\":[" << move.x << ',' << move.y << ',' << move.z << "]}],"
      << "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
      << "\"buffers\":[{\"byteLength\":" << buffer.size() << ",\"uri\":\""
      << (uri.empty() ? "data:application/octet-stream;base64," + base64(buffer) : uri) << "\"}],"
      << "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" << vertexBytes << ",\"target\":34962},"
      << "{\"buffer\":0,\"byteOffset\":" << vertexBytes << ",\"byteLength\":" << buffer.size() - vertexBytes
      << ",\"target\":34963}],"
      << "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":" << m.vertices.size()
      << ",\"type\":\"VEC3\",\"min\":[" << lo.x << ',' << lo.y << ',' << lo.z << "],\"max\":[" << hi.x << ',' << hi.y
      << ',' << hi.z << "]},{\"bufferView\":1,\"componentType\":5125,\"count\":" << m.triangles.size() * 3
      << ",\"type\":\"SCALAR\"}]}";
    return s.str();
}

/// COLLADA 1.4.1 (Y up, metres): one geometry instanced by one node translated by `move`.
inline std::string toDae(const Mesh& m, const glm::vec3& move) {
    std::ostringstream s;
    s << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
         "<asset><unit name=\"meter\" meter=\"1\"/><up_axis>Y_UP</up_axis></asset>\n"
         "<library_geometries><geometry id=\"g\" name=\"g\"><mesh>\n<source id=\"p\"><float_array id=\"pa\" count=\""
      << m.vertices.size() * 3 << "\">";
    for (const auto& v : m.vertices) s << v.x << ' ' << v.y << ' ' << v.z << ' ';
    s << "</float_array>\n<technique_common><accessor source=\"#pa\" count=\"" << m.vertices.size()
      << "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
         "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>\n"
         "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>\n<triangles count=\""
      << m.triangles.size() << "\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><p>";
    for (const auto& t : m.triangles) s << t[0] << ' ' << t[1] << ' ' << t[2] << ' ';
    s << "</p></triangles>\n</mesh></geometry></library_geometries>\n"
         "<library_visual_scenes><visual_scene id=\"s\"><node id=\"n\" name=\"n\"><translate>"
      << move.x << ' ' << move.y << ' ' << move.z
      << "</translate><instance_geometry url=\"#g\"/></node></visual_scene></library_visual_scenes>\n"
         "<scene><instance_visual_scene url=\"#s\"/></scene>\n</COLLADA>\n";
    return s.str();
}

// ---- 3MF: a ZIP archive (stored, no compression) of the 3D model XML and its relationships ----

inline std::uint32_t zipCrc32(const std::string& bytes) {  // not crc32: png_test_util.hpp has one (unity build)
    std::uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

inline std::string storedZip(const std::vector<std::pair<std::string, std::string>>& files) {
    auto u16 = [](std::string& o, std::uint16_t v) { o += char(v & 255), o += char(v >> 8); };
    auto u32 = [&](std::string& o, std::uint32_t v) { u16(o, std::uint16_t(v & 0xffff)), u16(o, std::uint16_t(v >> 16)); };
    std::string out, central;
    for (const auto& [name, data] : files) {
        const std::uint32_t offset = std::uint32_t(out.size()), crc = zipCrc32(data), size = std::uint32_t(data.size());
        u32(out, 0x04034b50), u16(out, 20), u16(out, 0), u16(out, 0), u16(out, 0), u16(out, 0x21);
        u32(out, crc), u32(out, size), u32(out, size), u16(out, std::uint16_t(name.size())), u16(out, 0);
        out += name + data;
        u32(central, 0x02014b50), u16(central, 20), u16(central, 20), u16(central, 0), u16(central, 0);
        u16(central, 0), u16(central, 0x21), u32(central, crc), u32(central, size), u32(central, size);
        u16(central, std::uint16_t(name.size())), u16(central, 0), u16(central, 0), u16(central, 0), u16(central, 0);
        u32(central, 0), u32(central, offset);
        central += name;
    }
    const std::uint32_t at = std::uint32_t(out.size());
    out += central;
    u32(out, 0x06054b50), u16(out, 0), u16(out, 0), u16(out, std::uint16_t(files.size()));
    u16(out, std::uint16_t(files.size())), u32(out, std::uint32_t(central.size())), u32(out, at), u16(out, 0);
    return out;
}

inline std::string to3mf(const Mesh& m) {
    std::ostringstream model;
    model << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"millimeter\" xml:lang=\"en-US\" "
             "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n<resources><object id=\"1\" "
             "type=\"model\"><mesh><vertices>";
    for (const auto& v : m.vertices) model << "<vertex x=\"" << v.x << "\" y=\"" << v.y << "\" z=\"" << v.z << "\"/>";
    model << "</vertices><triangles>";
    for (const auto& t : m.triangles) model << "<triangle v1=\"" << t[0] << "\" v2=\"" << t[1] << "\" v3=\"" << t[2] << "\"/>";
    model << "</triangles></mesh></object></resources>\n<build><item objectid=\"1\"/></build>\n</model>\n";
    const std::string types =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/"
        "content-types\"><Default Extension=\"rels\" ContentType=\"application/"
        "vnd.openxmlformats-package.relationships+xml\"/><Default Extension=\"model\" "
        "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>\n";
    const std::string rels =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships xmlns=\"http://schemas.openxmlformats.org/"
        "package/2006/relationships\"><Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
        "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>\n";
    return storedZip({{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model.str()}});
}

// ---- measures ----

/// Signed volume by the divergence theorem: positive for a closed, outward-wound mesh.
inline double signedVolume(const Mesh& m) {
    double v = 0;
    for (const auto& t : m.triangles) {
        const glm::dvec3 a(m.vertices[t[0]]), b(m.vertices[t[1]]), c(m.vertices[t[2]]);
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

struct Bounds {
    glm::vec3 lo{1e30f}, hi{-1e30f};
};

inline Bounds bounds(const Mesh& m) {
    Bounds b;
    for (const auto& v : m.vertices) b.lo = glm::min(b.lo, v), b.hi = glm::max(b.hi, v);
    return b;
}

}  // namespace shapevo::test

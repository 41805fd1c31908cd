// Model writers: a model's surface (geometry/tessellation.hpp) as OBJ (+ MTL) / PLY, written
// atomically; a mesh without materials is written as plain geometry (no MTL, no colour columns).
#include "report/model_writer.hpp"

#include <cstdio>
#include <filesystem>

#include "base/input_error.hpp"
#include "geometry/tessellation.hpp"
#include "mesh/mesh_material.hpp"
#include "report/texture_files.hpp"

namespace shapevo {

namespace fs = std::filesystem;

namespace {

/// `images`: the file name of each of the mesh's textures beside the MTL.
void writeMtl(const Mesh& mesh, const std::string& path, const std::vector<std::string>& images, Replace replace) {
    writeStreamAtomically(
        path,
        [&](std::ostream& out) {
            out << "# written by shapevo: " << mesh.materials.size() << " materials; Kd is the linear RGB colour\n";
            char kd[96];
            for (const MeshMaterial& m : mesh.materials) {
                std::snprintf(kd, sizeof kd, "Kd %.6g %.6g %.6g\n", double(m.color.x), double(m.color.y), double(m.color.z));
                out << "\nnewmtl " << m.name << '\n' << kd;
                if (m.texture >= 0) out << "map_Kd " << images.at(std::size_t(m.texture)) << '\n';
            }
        },
        replace);
}

void writeObjFile(const Mesh& mesh, const std::string& path, const std::string& mtlPath, Replace replace) {
    writeStreamAtomically(
        path,
        [&](std::ostream& out) {
            out << "# written by shapevo: " << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles";
            if (!mesh.materials.empty())
                out << ", " << mesh.materials.size() << " materials\nmtllib " << fs::path(mtlPath).filename().string();
            out << '\n';
            char line[128];
            for (const auto& v : mesh.vertices) {
                std::snprintf(line, sizeof line, "v %.6g %.6g %.6g\n", double(v.x), double(v.y), double(v.z));
                out << line;
            }
            for (const auto& uv : mesh.uvs) {  // one per vertex: face corners use the vertex's index for both
                std::snprintf(line, sizeof line, "vt %.7g %.7g\n", double(uv.x), double(uv.y));
                out << line;
            }
            const bool uvs = !mesh.uvs.empty();
            const auto groups = trianglesByMaterial(mesh);
            for (std::size_t m = 0; m < groups.size(); ++m) {
                if (!mesh.materials.empty() && !groups[m].empty()) out << "usemtl " << mesh.materials[m].name << '\n';
                for (const std::uint32_t i : groups[m]) {
                    const auto& t = mesh.triangles[i];
                    if (uvs) {
                        out << "f " << t[0] + 1 << '/' << t[0] + 1 << ' ' << t[1] + 1 << '/' << t[1] + 1 << ' ' << t[2] + 1
                            << '/' << t[2] + 1 << '\n';
                    } else {
                        out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
                    }
                }
            }
        },
        replace);
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return ext;
}

}  // namespace

Mesh meshOf(const Geometry& geometry) { return tessellate(geometry); }

std::string mtlPathFor(const std::string& objPath) { return fs::path(objPath).replace_extension(".mtl").string(); }

void writeObj(const Mesh& mesh, const std::string& path, Replace replace) {
    checkMaterials(mesh, path);
    if (mesh.materials.empty()) return writeObjFile(mesh, path, "", replace);
    const std::string mtlPath = mtlPathFor(path);
    if (lowerExtension(path) == ".mtl")
        throw InputError(path, "", "an OBJ file with materials cannot have the extension .mtl (its material file)");
    std::error_code ec;
    if (replace == Replace::Never)  // refuse before writing either file; the writes refuse again, atomically
        for (const std::string& p : {path, mtlPath})
            if (fs::exists(p, ec)) {
                std::string why = "already exists; refusing to overwrite it";
                if (p == mtlPath) why += " with the materials of " + fs::path(path).filename().string();
                throw InputError(p, "", why);
            }
    const PlacedTextures images = placeTextures(mesh, fs::path(path).parent_path().string());
    try {
        writeMtl(mesh, mtlPath, images.names, replace);
    } catch (...) {
        removeCreated(images);
        throw;
    }
    try {
        writeObjFile(mesh, path, mtlPath, replace);
    } catch (...) {
        if (replace == Replace::Never) fs::remove(mtlPath, ec);  // ours: it did not exist before
        removeCreated(images);
        throw;
    }
}

void writePly(const Mesh& mesh, const std::string& path, Replace replace) {
    checkMaterials(mesh, path);
    const bool colours = !mesh.materials.empty();
    std::vector<std::array<std::uint8_t, 3>> vertexColours;
    if (colours) {
        std::vector<bool> coloured(mesh.vertices.size(), false);
        vertexColours.assign(mesh.vertices.size(), {0, 0, 0});
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            for (const std::uint32_t v : mesh.triangles[t])
                if (v < coloured.size() && !coloured[v]) {
                    coloured[v] = true;
                    vertexColours[v] = srgbBytes(mesh.materials[mesh.triangleMaterials[t]].color);
                }
    }
    writeStreamAtomically(
        path,
        [&](std::ostream& out) {
            out << "ply\nformat binary_little_endian 1.0\ncomment written by shapevo\n";
            if (colours) out << "comment vertex colours: 8-bit sRGB encoding of the linear RGB colour\n";
            out << "element vertex " << mesh.vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\n";
            if (colours) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
            out << "element face " << mesh.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
            for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
                out.write(reinterpret_cast<const char*>(&mesh.vertices[i].x), 3 * sizeof(float));
                if (colours) out.write(reinterpret_cast<const char*>(vertexColours[i].data()), 3);
            }
            for (const auto& t : mesh.triangles) {
                const unsigned char n = 3;
                out.write(reinterpret_cast<const char*>(&n), 1);
                out.write(reinterpret_cast<const char*>(t.data()), 3 * sizeof(std::uint32_t));
            }
        },
        replace);
}

}  // namespace shapevo

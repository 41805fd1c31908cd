// Mesh: an indexed triangle mesh as read from a mesh file (mesh/mesh_reader.hpp; input to target making) and as the
// writers (report/model_writer.hpp, mesh/glb_writer.hpp) export it. An exported model may also
// carry how its triangles look: a list of materials (a name and a colour) and one material per
// triangle. Both lists are empty for meshes read from files and for models whose grammar sets no
// colour; the writers then write plain geometry, exactly as before colours existed. A material
// may have a texture image (MeshTexture); a mesh with one has one UV coordinate per vertex
// (OBJ's convention: v = 0 at the bottom row of the image, one unit = the whole image, which
// repeats), and a mesh without one has none.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shapevo {

/// One look of an exported mesh. mesh/mesh_material.hpp checks what it promises.
struct MeshMaterial {
    std::string name;             ///< non-empty, unique within its mesh; only A-Z a-z 0-9 _ - .
    glm::vec3 color{0.8f};        ///< linear RGB, each channel in [0, 1]
    int texture = -1;             ///< index into Mesh::textures, or -1: untextured
    bool operator==(const MeshMaterial&) const = default;
};

/// A texture image of an exported mesh.
struct MeshTexture {
    std::string name;               ///< the file name it gets beside a model: only A-Z a-z 0-9 _ - ., ends in .png, unique in its mesh
    std::vector<std::uint8_t> png;  ///< the PNG file's bytes
    bool operator==(const MeshTexture&) const = default;
};

struct Mesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< faces are triangulated on read
    /// Empty (no colours), or the mesh's distinct looks, each used by at least one triangle
    /// when made by tessellate() (geometry/tessellation.hpp).
    std::vector<MeshMaterial> materials;
    /// Empty when `materials` is; otherwise one index into `materials` per triangle.
    std::vector<std::uint32_t> triangleMaterials;
    /// The images of textured materials (each used by at least one material when made by tessellate()).
    std::vector<MeshTexture> textures;
    /// Empty when no material has a texture; otherwise one UV coordinate per vertex (those of
    /// untextured triangles are 0).
    std::vector<glm::vec2> uvs;
    /// What the reader read past (e.g. a stray PLY header line), one message each, starting
    /// with the file's path and the place ("cube.ply: line 3: skipped ..."). Empty for meshes
    /// that were not read from a file; the writers ignore it.
    std::vector<std::string> warnings;
};

}  // namespace shapevo

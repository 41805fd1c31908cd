// Model writers: a model's primitives as a triangle mesh in OBJ or PLY (binary little endian).
// Every primitive kind is tessellated as in geometry/tessellation.hpp (outward-facing, mirrored
// frames too); the files appear atomically (temporary file, then rename). A mesh without
// materials (a grammar without colours) is written as plain geometry: no material library, no
// colour columns. With materials (mesh/mesh.hpp):
//   OBJ  a material library next to the OBJ (mtlPathFor: same folder and stem, extension .mtl)
//        with one `newmtl NAME` and `Kd R G B` per material, the linear colour as it is (the
//        way Blender reads and writes Kd); the OBJ names it (`mtllib m.mtl`) and lists the faces
//        of each material after one `usemtl NAME`, materials in order, faces in mesh order.
//        A textured material adds `map_Kd FILE.png`, its image copied into the OBJ's folder
//        (report/texture_files.hpp: an existing file is never replaced; an identical one is
//        used, another one keeps its name and the image takes the next free one); the OBJ then
//        has one `vt U V` per vertex after the `v` lines and faces `f a/a b/b c/c`.
//   PLY  vertex colours, `property uchar red / green / blue` after x y z: the 8-bit sRGB
//        encoding of the linear colour (mesh/mesh_material.hpp). A vertex takes the colour of
//        the first triangle that uses it (tessellate() never shares a vertex between
//        primitives); a vertex no triangle uses is black. Textured materials are white; no UVs.
#pragma once
#include <string>

#include "base/atomic_write.hpp"
#include "mesh/mesh.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// Triangulate every primitive into one mesh, with its materials (tessellate()).
Mesh meshOf(const Geometry& geometry);

/// The material library of OBJ file `objPath`: its extension replaced by .mtl ("out/m.obj" ->
/// "out/m.mtl"; "m" -> "m.mtl").
std::string mtlPathFor(const std::string& objPath);

/// Writes `mesh` as OBJ to `path`; with materials the MTL first, then the OBJ. With
/// Replace::Never an existing OBJ or MTL is not replaced: InputError, and neither file is
/// written (an MTL this call wrote is removed again if the OBJ then cannot be written).
/// @throw InputError naming the file that cannot be written, or the mesh's materials as
///        checkMaterials() does, or an OBJ path whose extension is .mtl when there are materials.
void writeObj(const Mesh& mesh, const std::string& path, Replace replace = Replace::Always);

/// Writes `mesh` as binary little-endian PLY to `path` (Replace as for writeAtomically).
/// @throw InputError naming `path` if it cannot be written or the materials are inconsistent.
void writePly(const Mesh& mesh, const std::string& path, Replace replace = Replace::Always);

}  // namespace shapevo

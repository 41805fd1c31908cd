// Mesh file input: reads any common mesh format into a triangle Mesh (OBJ, PLY and STL with
// shapevo's own readers, every other format Assimp knows through Assimp, in a sandboxed child
// process), and checks that a mesh is closed before it is turned into a volume target.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace shapevo {

/// Guards against hostile or absurd mesh files. The defaults are what every caller gets.
struct MeshReadLimits {
    /// Larger files are refused before anything is read (2 GiB).
    std::uint64_t maxFileBytes = 2ull << 30;
    /// An Assimp import runs in a child process that may use this much memory, plus
    /// `memoryPerFileByte` bytes per byte of the file, beyond what it inherits (1 GiB + 16 x size).
    std::uint64_t memoryBytes = 1ull << 30;
    std::uint64_t memoryPerFileByte = 16;
    /// ... and this much wall-clock time, plus `secondsPerMiB` per MiB of the file, before it is
    /// stopped (20 s + 1 s per MiB).
    double seconds = 20.0;
    double secondsPerMiB = 1.0;
};

/// Reads a mesh, choosing the format by the file extension (any case):
///   .obj, .ply (ascii, binary little-endian), .stl (ascii, binary): shapevo's own readers;
///   any other extension Assimp 5 imports (assimpMeshExtensions(): .off, .gltf, .glb, .fbx, .3mf,
///   .dae, .3ds, .x, .blend, ...): Assimp, from the path (so a .gltf finds its .bin buffers), with
///   the scene's node transforms applied (world space), every mesh of the scene merged into one,
///   polygons triangulated, points and lines dropped. Assimp runs in a child process under the
///   time and memory limits above, so a file that crashes it, hangs it or makes it allocate
///   without bound gives an InputError like any other bad file.
/// Polygons are fan-triangulated. STL vertices are welded where positions are exactly equal.
/// Harmless oddities are read past and listed in `Mesh::warnings`, each naming the file and place
/// (a PLY header line that is no PLY keyword, e.g. Blender 2.4x's "Created by ..." line).
/// Assimp's logged errors become warnings, but one about a face's vertex index (Assimp reads on
/// past it, clamping the index or dropping the face) refuses the file.
/// After any reader the same checks run on the result: finite coordinates, indices in range, at
/// least one triangle, and at least one valid face (a triangle whose corners span a positive area).
/// @throw InputError naming the file (and line, element or mesh/face index) when the path is
///        missing, a directory or not a regular file, the file is empty or over maxFileBytes, the
///        extension is unknown (the message lists the known ones), a number is malformed, a face
///        index is out of range (also one Assimp reports and reads past), a face has fewer than 3
///        vertices (OBJ/PLY/STL), a coordinate is not finite, there are no triangles, every
///        triangle is degenerate ("no valid face"), or Assimp cannot read the file (its own
///        message, or that it crashed, ran out of time or memory).
Mesh readMesh(const std::string& path, const MeshReadLimits& limits = {});

/// The extensions readMesh reads through Assimp (lower case, with the dot, sorted; without
/// .obj, .ply and .stl, which shapevo reads itself).
std::vector<std::string> assimpMeshExtensions();

/// Throws InputError (naming `path`) unless every undirected edge is shared by exactly two
/// triangles, after merging vertices whose positions are exactly equal. The message says how
/// many edges are open and gives one of them by its end-point coordinates.
void requireClosed(const Mesh& mesh, const std::string& path);

}  // namespace shapevo

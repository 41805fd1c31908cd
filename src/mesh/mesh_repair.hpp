// Mesh repair for volume targets: a mesh with holes becomes closed enough for OpenVDB's
// level-set conversion (which needs a closed surface, not a manifold one: seams, doubled faces
// and non-manifold edges do it no harm). Holes are filled with CGAL's hole triangulation after
// its soup orientation and border stitching; a mesh that is mostly holes is refused, as its
// inside cannot be determined. All CGAL code is in mesh_repair.cpp.
#pragma once
#include <cstddef>
#include <string>

#include "mesh/mesh.hpp"
#include "mesh/mesh_defects.hpp"

namespace shapevo {

struct MeshRepair {
    /// What to convert: the input itself (unchanged) when it has no open edge; otherwise the
    /// welded mesh without degenerate and doubled triangles, plus the triangles that fill holes.
    Mesh mesh;
    MeshDefects found;               ///< analyseMesh of the input
    std::size_t filledHoles = 0;     ///< CGAL's border cycles filled (holes touching at a vertex may be one)
    std::size_t unfilledHoles = 0;   ///< border cycles CGAL could not triangulate (left open)
    std::size_t addedTriangles = 0;
    double fillArea = 0.0;           ///< area of the added triangles
};

/// Holes larger in total than this fraction of the mesh's own surface mean the mesh is mostly
/// holes (an open sheet, a bowl): which side is inside is then a guess, and it is refused.
constexpr double kMaxFillAreaFraction = 0.5;

/// Analyses `mesh` and fills its holes when it has open edges (see MeshRepair::mesh).
/// @throw InputError naming `path` when the holes' area exceeds kMaxFillAreaFraction of the
///        surface ("mostly holes": the inside cannot be determined).
MeshRepair repairForVolume(const Mesh& mesh, const std::string& path);

/// One line for the user, e.g. "12,345 triangles, 412 open edges in 52 holes: filled (610
/// triangles added); 3 non-manifold edges" or "12 triangles, closed".
std::string describeRepair(const MeshRepair& repair);

/// `n` with thousands separators: 12345 -> "12,345".
std::string groupedNumber(std::size_t n);

}  // namespace shapevo

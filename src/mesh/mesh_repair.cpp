// repairForVolume: analyseMesh, then (only for a mesh with open edges) CGAL: orient the welded
// triangle soup (which also splits non-manifold edges so the soup becomes a polygon mesh), build
// a Surface_mesh, stitch coincident borders, and triangulate every remaining border cycle as
// polylines (CGAL's hole triangulation), a cycle through a vertex twice split into simple loops.
#include "mesh/mesh_repair.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <unordered_map>
#include <sstream>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include "base/input_error.hpp"

namespace shapevo {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

std::string number(double v) {
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
}

/// A border cycle that passes a vertex twice (holes touching at a vertex: a figure 8) as simple
/// loops, each vertex once; loops of fewer than 3 vertices bound nothing and are dropped.
std::vector<std::vector<std::uint32_t>> simpleLoops(const std::vector<std::uint32_t>& cycle) {
    std::vector<std::vector<std::uint32_t>> loops;
    std::vector<std::uint32_t> stack;
    std::unordered_map<std::uint32_t, std::size_t> onStack;  // vertex -> its place in `stack`
    for (const std::uint32_t v : cycle) {
        const auto seen = onStack.find(v);
        if (seen == onStack.end()) {
            onStack.emplace(v, stack.size());
            stack.push_back(v);
            continue;
        }
        const auto from = stack.begin() + std::ptrdiff_t(seen->second);
        loops.emplace_back(from, stack.end());  // v ... back to v
        for (auto it = from + 1; it != stack.end(); ++it) onStack.erase(*it);
        stack.erase(from + 1, stack.end());
    }
    loops.push_back(stack);
    std::erase_if(loops, [](const std::vector<std::uint32_t>& l) { return l.size() < 3; });
    return loops;
}

/// Fills the holes of `welded` into `out` (mesh, counts). Leaves out.mesh empty if CGAL cannot
/// make a polygon mesh of the soup at all.
void fillHoles(const WeldedMesh& welded, MeshRepair& out) {
    std::vector<Point> points;
    points.reserve(welded.vertices.size());
    for (const glm::vec3& v : welded.vertices) points.emplace_back(v.x, v.y, v.z);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(welded.triangles.size());
    for (const auto& t : welded.triangles) polygons.push_back({t[0], t[1], t[2]});
    PMP::orient_polygon_soup(points, polygons);  // false only means points were duplicated
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return;

    SurfaceMesh sm;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    PMP::stitch_borders(sm);
    sm.collect_garbage();  // stitching removes vertices: make the indices below contiguous again
    std::vector<SurfaceMesh::Halfedge_index> cycles;
    PMP::extract_boundary_cycles(sm, std::back_inserter(cycles));

    // Orienting the soup gives a vertex where holes touch one copy per fan, so a figure-8 cycle
    // passes two copies: name each border vertex by the first one at its position.
    std::map<Point, std::uint32_t> firstAt;
    std::vector<std::array<std::uint32_t, 3>> patches;
    for (const SurfaceMesh::Halfedge_index start : cycles) {
        std::vector<std::uint32_t> cycle;
        SurfaceMesh::Halfedge_index h = start;
        do {
            const SurfaceMesh::Vertex_index v = sm.target(h);
            cycle.push_back(firstAt.emplace(sm.point(v), std::uint32_t(v.idx())).first->second);
            h = sm.next(h);
        } while (h != start && cycle.size() <= sm.number_of_halfedges());
        for (const std::vector<std::uint32_t>& loop : simpleLoops(cycle)) {
            std::vector<Point> polyline;
            for (std::uint32_t v : loop) polyline.push_back(sm.point(SurfaceMesh::Vertex_index(v)));
            std::vector<CGAL::Triple<int, int, int>> patch;
            try {
                PMP::triangulate_hole_polyline(polyline, std::back_inserter(patch));
            } catch (const std::exception&) {
                patch.clear();  // a CGAL precondition on a pathological loop: leave the hole
            }
            if (patch.empty()) {
                ++out.unfilledHoles;
                continue;
            }
            ++out.filledHoles;
            for (const auto& t : patch) {
                const std::array<std::uint32_t, 3> tri{loop[std::size_t(t.first)], loop[std::size_t(t.second)],
                                                       loop[std::size_t(t.third)]};
                patches.push_back(tri);
                out.fillArea += std::sqrt(CGAL::squared_area(polyline[std::size_t(t.first)], polyline[std::size_t(t.second)],
                                                             polyline[std::size_t(t.third)]));
            }
        }
    }
    out.addedTriangles = patches.size();

    Mesh& m = out.mesh;
    m.vertices.reserve(sm.number_of_vertices());
    for (const SurfaceMesh::Vertex_index v : sm.vertices()) {
        const Point& p = sm.point(v);
        m.vertices.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    }
    for (const SurfaceMesh::Face_index f : sm.faces()) {
        std::array<std::uint32_t, 3> tri{};
        int k = 0;
        for (const SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm))
            if (k < 3) tri[k++] = std::uint32_t(v.idx());
        if (k == 3) m.triangles.push_back(tri);
    }
    m.triangles.insert(m.triangles.end(), patches.begin(), patches.end());
}

}  // namespace

MeshRepair repairForVolume(const Mesh& mesh, const std::string& path) {
    MeshRepair r;
    WeldedMesh welded;
    r.found = analyseMesh(mesh, &welded);
    if (r.found.closed()) {
        r.mesh = mesh;
        return r;
    }
    fillHoles(welded, r);
    if (r.mesh.triangles.empty()) {  // CGAL could not take it: let OpenVDB try the soup as it is
        r.mesh.vertices = welded.vertices;
        r.mesh.triangles = welded.triangles;
        r.unfilledHoles = r.found.holes;
    }
    if (r.fillArea > kMaxFillAreaFraction * r.found.surfaceArea)
        throw InputError(path, "",
                         "the inside of the mesh cannot be determined: it is mostly holes (" +
                             groupedNumber(r.found.openEdges) + " open edges in " + groupedNumber(r.found.holes) +
                             (r.found.holes == 1 ? " hole" : " holes") + " whose filling would have " + number(r.fillArea) +
                             " units^2, against " + number(r.found.surfaceArea) +
                             " units^2 of surface); a volume target needs a mesh that encloses its inside");
    return r;
}

std::string groupedNumber(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string describeRepair(const MeshRepair& r) {
    const MeshDefects& d = r.found;
    auto count = [](std::size_t n, const char* one, const char* many) {
        return groupedNumber(n) + " " + (n == 1 ? one : many);
    };
    std::string s = count(d.triangles, "triangle", "triangles");
    if (d.closed()) {
        s += ", closed";
    } else {
        s += ", " + count(d.openEdges, "open edge", "open edges") + " in " + count(d.holes, "hole", "holes") + ": ";
        if (r.unfilledHoles == 0)
            s += "filled (";
        else if (r.filledHoles == 0)
            s += "not filled (";
        else
            s += "partly filled (" + count(r.unfilledHoles, "border cycle", "border cycles") + " left open, ";
        s += count(r.addedTriangles, "triangle", "triangles") + " added)";
    }
    if (d.seamVertices) s += "; " + count(d.seamVertices, "duplicated vertex", "duplicated vertices") + " (seams)";
    if (d.nonManifoldEdges) s += "; " + count(d.nonManifoldEdges, "non-manifold edge", "non-manifold edges");
    if (d.duplicateTriangles) s += "; " + count(d.duplicateTriangles, "duplicated triangle", "duplicated triangles");
    if (d.degenerateTriangles) s += "; " + count(d.degenerateTriangles, "degenerate triangle", "degenerate triangles");
    if (d.components > 1) s += "; " + count(d.components, "piece", "pieces");
    return s;
}

}  // namespace shapevo

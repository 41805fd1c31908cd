// autoPosition: the placement frame of one application (auto_position.hpp).
#include "graph/auto_position.hpp"

#include <algorithm>
#include <cmath>

namespace shapevo::graph {

namespace {

Vec2 mean(const std::vector<Vec2>& points) {
    Vec2 m;
    for (const Vec2& p : points) m.x += p.x, m.y += p.y;
    if (!points.empty()) m.x /= double(points.size()), m.y /= double(points.size());
    return m;
}

Vec2 rotated(Vec2 v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

Vec2 extent(const std::vector<Vec2>& points) {
    if (points.empty()) return {};
    double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
    for (const Vec2& p : points) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    return {x1 - x0, y1 - y0};
}

}  // namespace

double regressionAngle(const std::vector<Vec2>& points) {
    if (points.size() < 2) return 0;
    const Vec2 m = mean(points);
    double sxx = 0, syy = 0, sxy = 0;
    for (const Vec2& p : points) {
        sxx += (p.x - m.x) * (p.x - m.x);
        syy += (p.y - m.y) * (p.y - m.y);
        sxy += (p.x - m.x) * (p.y - m.y);
    }
    if (sxx == 0 && syy == 0) return 0;
    if (sxx == 0 || std::sqrt(syy / sxx) > 2) {  // x on y: x = a + b y, direction (b, 1)
        const double angle = std::atan2(1.0, sxy / syy);
        return angle > M_PI / 2 ? angle - M_PI : angle;
    }
    return std::atan(sxy / sxx);  // y on x
}

Vec2 PlacementFrame::place(Vec2 d) const {
    const Vec2 r = rotated({d.x - daughterCentre.x, d.y - daughterCentre.y}, angle);
    return {hostCentre.x + scale.x * r.x, hostCentre.y + scale.y * r.y};
}

PlacementFrame placementFrame(const Production& production, const ProductionOption& option, const HostGraph& graph,
                              const ElementId* vertexImages, const ElementId* edgeImages, const std::uint8_t* swapped,
                              PlacementScratch& scratch) {
    PlacementFrame f;
    std::vector<Vec2>& daughter = scratch.daughter;
    std::vector<Vec2>& host = scratch.host;
    daughter.clear();
    host.clear();
    for (const DaughterVertex& d : option.vertices)
        if (d.mother >= 0) {
            daughter.push_back(d.position);
            host.push_back(graph.vertex(vertexImages[d.mother]).position);
        }
    for (const DaughterEdge& d : option.edges) {
        if (d.mother < 0) continue;
        const HostEdge& h = graph.edge(edgeImages[d.mother]);
        const ElementId ends[2] = {swapped[d.mother] ? h.vertex2 : h.vertex1, swapped[d.mother] ? h.vertex1 : h.vertex2};
        const int dEnds[2] = {d.vertex1, d.vertex2};
        for (int k = 0; k < 2; ++k) {
            if (dEnds[k] >= 0) daughter.push_back(option.vertices[std::size_t(dEnds[k])].position);
            if (ends[k] != kNoVertex) host.push_back(graph.vertex(ends[k]).position);
        }
    }
    if (daughter.empty())
        for (const DaughterVertex& d : option.vertices) daughter.push_back(d.position);
    if (host.empty())
        for (std::size_t i = 0; i < production.motherVertices.size(); ++i) host.push_back(graph.vertex(vertexImages[i]).position);
    f.daughterCentre = mean(daughter);
    f.hostCentre = host.empty() ? f.daughterCentre : mean(host);

    std::vector<Vec2>& mother = scratch.mother;
    std::vector<Vec2>& images = scratch.images;
    mother.clear();
    images.clear();
    for (std::size_t i = 0; i < production.motherVertices.size(); ++i) {
        mother.push_back(production.motherVertices[i].position);
        images.push_back(graph.vertex(vertexImages[i]).position);
    }
    bool directed = false;
    for (const MotherEdge& m : production.motherEdges) {
        if (!m.directed || m.vertex1 < 0 || m.vertex2 < 0) continue;
        const Vec2 a = production.motherVertices[std::size_t(m.vertex1)].position, b = production.motherVertices[std::size_t(m.vertex2)].position;
        const Vec2 ha = graph.vertex(vertexImages[m.vertex1]).position, hb = graph.vertex(vertexImages[m.vertex2]).position;
        f.angle = std::atan2(hb.y - ha.y, hb.x - ha.x) - std::atan2(b.y - a.y, b.x - a.x);
        directed = true;
        break;
    }
    if (!directed) f.angle = regressionAngle(images) - regressionAngle(mother);
    for (Vec2& m : mother) m = rotated(m, f.angle);
    const Vec2 me = extent(mother), he = extent(images);
    // An extent is 0 up to rounding (a vertical segment turned by π/2 keeps ~1e-16 of width).
    const double mTiny = 1e-9 * (me.x + me.y), hTiny = 1e-9 * (he.x + he.y);
    f.scale.x = me.x <= mTiny || he.x <= hTiny ? 1 : he.x / me.x;
    f.scale.y = me.y <= mTiny || he.y <= hTiny ? 1 : he.y / me.y;
    return f;
}

}  // namespace shapevo::graph

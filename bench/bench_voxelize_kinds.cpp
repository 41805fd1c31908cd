// bench_voxelize_kinds: Voxelizer::score on 20 random primitives of one kind in a 100^3 grid
// (voxel 0.1, random fill target), to compare the kinds' row costs.
//  - BM_VoxelizeKind/kind:<k>/mesh:<m>/rotated:<r>: kind 0 box, 1 cylinder, 2 cone (tapers
//    uniform in [0, 1]), 3 sphere, 4 mesh (m: 0 octahedron, 8 triangles; 1 L-shaped prism,
//    20 triangles; 2 geodesic sphere, 2048 triangles), 5 roof (both top fractions uniform in
//    [0, 1]), 6 paraboloid. Rotated: random unit quaternion (Shoemake), else axis-aligned (the
//    box fast path; round kinds, roofs and paraboloids have none). Half extents
//    0.2 .. 1.0 (2 .. 10 voxels), centres inside the grid, fixed seed.
// Counters: voxel_rows/s = rows a primitive was rasterized into (VoxelCounts::rows) per second;
// primitives/s; rows/eval. The grid is counted against the target in every iteration, as in a
// real evaluation.
//
//   cd build && ninja bench_voxelize_kinds && taskset -c 1 ./bench/bench_voxelize_kinds --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "genome/random.hpp"
#include "score/volume/voxelizer.hpp"
#include "shape/kinds.hpp"

namespace {

using namespace shapevo;

MeshShape octahedron() {
    MeshShape m;
    m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (std::uint32_t sx = 0; sx < 2; ++sx)
        for (std::uint32_t sy = 0; sy < 2; ++sy)
            for (std::uint32_t sz = 0; sz < 2; ++sz) {
                std::array<std::uint32_t, 3> t{sx, 2 + sy, 4 + sz};
                if ((sx + sy + sz) % 2 == 1) std::swap(t[1], t[2]);
                m.triangles.push_back(t);
            }
    return m;
}

/// The L {[-1,1]x[-1,0]} u {[-1,0]x[-1,1]} extruded over z in [-1, 1].
MeshShape lPrism() {
    MeshShape m;
    const float l[6][2] = {{-1, -1}, {1, -1}, {1, 0}, {0, 0}, {0, 1}, {-1, 1}};
    for (int z = 0; z < 2; ++z)
        for (const auto& v : l) m.vertices.push_back({v[0], v[1], z ? 1.0f : -1.0f});
    const std::uint32_t fan[4][2] = {{4, 5}, {5, 0}, {0, 1}, {1, 2}};
    for (const auto& f : fan) {
        m.triangles.push_back({9, 6 + f[0], 6 + f[1]});
        m.triangles.push_back({3, f[1], f[0]});
    }
    for (std::uint32_t i = 0; i < 6; ++i) {
        const std::uint32_t j = (i + 1) % 6;
        m.triangles.push_back({i, j, 6 + j});
        m.triangles.push_back({i, 6 + j, 6 + i});
    }
    return m;
}

/// The octahedron subdivided `levels` times (each triangle into four), vertices pushed onto the
/// unit sphere: 8 * 4^levels triangles.
MeshShape geodesicSphere(int levels) {
    MeshShape m = octahedron();
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            m.vertices.push_back(glm::normalize(m.vertices[a] + m.vertices[b]));
            return midpoints[key] = std::uint32_t(m.vertices.size() - 1);
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        for (const auto& t : m.triangles) {
            const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
            next.push_back({t[0], ab, ca});
            next.push_back({ab, t[1], bc});
            next.push_back({ca, bc, t[2]});
            next.push_back({ab, bc, ca});
        }
        m.triangles = std::move(next);
    }
    return m;
}

const std::vector<MeshShape>& meshes() {
    static const std::vector<MeshShape> m = {octahedron(), lPrism(), geodesicSphere(4)};
    return m;
}

const VolumeTarget& target() {
    static const VolumeTarget t = [] {
        VolumeTarget v;
        v.grid.origin = glm::dvec3(-5.0);
        v.grid.voxelSize = 0.1;
        v.grid.nx = v.grid.ny = v.grid.nz = 100;
        v.fill.assign(v.grid.words(), 0);
        v.avoid.assign(v.grid.words(), 0);
        Rng rng(7);
        for (auto& w : v.fill) w = rng.next() & rng.next();  // about a quarter of the voxels
        for (auto w : v.fill) v.fillCount += std::uint64_t(std::popcount(w));
        return v;
    }();
    return t;
}

/// Uniform random rotation (Shoemake's method: a uniform unit quaternion).
glm::mat3 randomRotation(Rng& rng) {
    const double u1 = rng.uniform(), u2 = rng.uniform() * 2 * M_PI, u3 = rng.uniform() * 2 * M_PI;
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const glm::quat q(float(b * std::cos(u3)), float(a * std::sin(u2)), float(a * std::cos(u2)), float(b * std::sin(u3)));
    return glm::mat3_cast(glm::normalize(q));
}

const char* kindName(PrimitiveKind k) {
    switch (k) {
    case PrimitiveKind::Box: return "box";
    case PrimitiveKind::Cylinder: return "cylinder";
    case PrimitiveKind::Cone: return "cone";
    case PrimitiveKind::Sphere: return "sphere";
    case PrimitiveKind::Mesh: return "mesh";
    case PrimitiveKind::Roof: return "roof";
    case PrimitiveKind::Paraboloid: return "paraboloid";
    }
    return "?";
}

void BM_VoxelizeKind(benchmark::State& state) {
    const auto kind = PrimitiveKind(state.range(0));
    const auto mesh = std::uint16_t(state.range(1));
    const bool rotated = state.range(2) != 0;
    const GridSpec& grid = target().grid;
    Rng rng(2024);
    Geometry geometry;
    geometry.meshes = &meshes();
    for (int i = 0; i < 20; ++i) {
        Primitive p;
        p.kind = kind;
        const float taper = float(rng.uniform());
        p.axes = rotated ? randomRotation(rng) : glm::mat3(1.0f);
        for (int k = 0; k < 3; ++k) {
            p.half[k] = float(0.2 + 0.8 * rng.uniform());
            p.centre[k] = float(grid.origin[k] + rng.uniform() * grid.nx * grid.voxelSize);
        }
        if (kind == PrimitiveKind::Cone) setParams<ConeKind>(p, {taper});
        if (kind == PrimitiveKind::Mesh) setParams<MeshKind>(p, {mesh});
        if (kind == PrimitiveKind::Roof) setParams<RoofKind>(p, {taper, float(rng.uniform())});  // drawn last: the other kinds keep their primitives
        geometry.primitives.push_back(p);
    }
    Voxelizer voxelizer(grid);
    voxelizer.score(geometry, target());  // warm
    std::uint64_t rows = 0;
    for (auto _ : state) {
        const VoxelCounts counts = voxelizer.score(geometry, target());
        benchmark::DoNotOptimize(counts);
        rows += counts.rows;
    }
    state.SetItemsProcessed(state.iterations() * 20);
    state.counters["voxel_rows/s"] = benchmark::Counter(double(rows), benchmark::Counter::kIsRate);
    state.counters["primitives/s"] = benchmark::Counter(double(state.iterations()) * 20, benchmark::Counter::kIsRate);
    state.counters["rows/eval"] = benchmark::Counter(double(rows), benchmark::Counter::kAvgIterations);
    std::string label = std::string("20 ") + (rotated ? "rotated " : "axis-aligned ") + kindName(kind);
    if (kind == PrimitiveKind::Mesh)
        label += " (" + std::to_string(meshes()[mesh].triangles.size()) + " triangles)";
    state.SetLabel(label + ", 100^3 grid");
}

BENCHMARK(BM_VoxelizeKind)
    ->ArgNames({"kind", "mesh", "rotated"})
    ->Args({0, 0, 1})
    ->Args({0, 0, 0})
    ->Args({1, 0, 1})
    ->Args({2, 0, 1})
    ->Args({3, 0, 1})
    ->Args({3, 0, 0})
    ->Args({4, 0, 1})
    ->Args({4, 1, 1})
    ->Args({4, 2, 1})
    ->Args({5, 0, 1})
    ->Args({5, 0, 0})
    ->Args({6, 0, 1})
    ->Args({6, 0, 0});

}  // namespace

BENCHMARK_MAIN();

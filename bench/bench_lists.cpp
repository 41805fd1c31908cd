// bench_lists: the PCGR list operations of geometry/lists on lists of about 1,000 entities: order
// by (2 keys), shuffle, aggregate, group by, k-means (K = 6), merge, unify (facade tiles), ray cast
// 1,000 x 1,000 (the box tree against testing every box), facing (with and without occlusion);
// and PCGR's Fig. 7 zoned city derived whole (grammars/city-zones.grammar: 1,024 blocks, two
// gathers with aggregates, a shuffle, k-means and orders by distance).
// Every benchmark reports min and max over repetitions beside the mean and median. The command and
// today's figures: docs/list-operations.md (experiments/list_operations_bench.py runs it).
//
//   cd build && ninja bench_lists && ./bench/bench_lists --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "base/random.hpp"
#include "geometry/lists/adjacency.hpp"
#include "geometry/lists/aggregate.hpp"
#include "geometry/lists/facing.hpp"
#include "geometry/lists/grouping.hpp"
#include "geometry/lists/kmeans.hpp"
#include "geometry/lists/merge.hpp"
#include "geometry/lists/ordering.hpp"
#include "geometry/lists/ray_cast.hpp"

#include "bench_main.hpp"
#include "genome/sample.hpp"
#include "grammar/front_ends.hpp"
#include "run_derive.hpp"

namespace {

using namespace shapevo;
using namespace shapevo::lists;

constexpr std::uint32_t kEntities = 1000;

std::vector<Scope> randomBoxes(std::uint64_t seed, std::uint32_t n) {
    Rng rng(seed);
    std::vector<Scope> boxes(n);
    for (Scope& s : boxes) {
        s.origin = glm::vec3(float(rng.normal() * 40), float(rng.normal() * 40), float(rng.normal() * 40));
        s.axes = glm::mat3(glm::mat3_cast(glm::normalize(glm::dquat(rng.normal(), rng.normal(), rng.normal(), rng.normal()))));
        s.size = glm::vec3(float(0.5 + rng.uniform() * 4), float(0.5 + rng.uniform() * 4), float(0.5 + rng.uniform() * 4));
    }
    return boxes;
}

std::vector<double> randomValues(std::uint64_t seed, std::size_t n) {
    Rng rng(seed);
    std::vector<double> v(n);
    for (double& x : v) x = double(rng.below(50)) + rng.uniform();
    return v;
}

void BM_OrderBy2Keys(benchmark::State& state) {
    std::vector<double> keys = randomValues(1, 2 * kEntities);
    for (std::size_t i = 0; i < keys.size(); i += 2) keys[i] = std::floor(keys[i] / 10);  // ties on the first key
    const std::vector<SortDirection> dirs{SortDirection::Ascending, SortDirection::Descending};
    std::vector<std::uint32_t> order;
    for (auto _ : state) {
        orderBy(keys, dirs, order);
        benchmark::DoNotOptimize(order.data());
    }
}

void BM_Shuffle(benchmark::State& state) {
    std::vector<std::uint32_t> order;
    double u = 0.125;
    for (auto _ : state) {
        shuffleOrder(kEntities, u, 42, order);
        benchmark::DoNotOptimize(order.data());
    }
}

void BM_AggregateAvgVector(benchmark::State& state) {
    const std::vector<double> v = randomValues(2, 3 * kEntities);
    std::vector<glm::dvec3> points(kEntities);
    for (std::uint32_t i = 0; i < kEntities; ++i) points[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    for (auto _ : state) benchmark::DoNotOptimize(aggregate(Aggregate::Avg, std::span<const glm::dvec3>(points)));
}

void BM_GroupBy(benchmark::State& state) {
    std::vector<double> keys = randomValues(3, kEntities);
    for (double& k : keys) k = std::floor(k / 5);  // 10 groups
    Grouping g;
    ListWorkspace ws;
    for (auto _ : state) {
        groupBy(keys, 1, g, ws);
        benchmark::DoNotOptimize(g.members.data());
    }
}

void BM_KMeans6(benchmark::State& state) {
    const std::vector<Scope> boxes = randomBoxes(4, kEntities);
    std::vector<glm::dvec3> points;
    scopeOrigins(boxes, points);
    std::vector<std::uint32_t> clusterOf;
    std::vector<glm::dvec3> centroids;
    ListWorkspace ws;
    std::uint32_t rounds = 0;
    for (auto _ : state) rounds = clusterKMeans(points, 6, 100, clusterOf, centroids, ws).rounds;
    state.counters["rounds"] = rounds;
}

void BM_Merge(benchmark::State& state) {
    const std::vector<Scope> boxes = randomBoxes(5, kEntities);
    for (auto _ : state) benchmark::DoNotOptimize(mergeScopes(boxes));
}

/// 1,008 facade tiles: 7 boxes, 4 faces each, 6 x 6 tiles per face.
std::vector<Scope> facadeTiles() {
    std::vector<Scope> tiles;
    for (int b = 0; b < 7; ++b) {
        const glm::vec3 centre(float(b * 30), 10.0f, 0.0f), size(12.0f, 20.0f, 8.0f);
        const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
        const struct {
            glm::vec3 origin, x, z;
            float width;
        } faces[4] = {{centre + Z * 4.0f, X, Z, 12.0f}, {centre - Z * 4.0f, -X, -Z, 12.0f}, {centre + X * 6.0f, -Z, X, 8.0f}, {centre - X * 6.0f, Z, -X, 8.0f}};
        for (const auto& f : faces)
            for (int c = 0; c < 6; ++c)
                for (int r = 0; r < 6; ++r) {
                    Scope t;
                    t.axes = glm::mat3(f.x, Y, f.z);
                    t.size = glm::vec3(f.width / 6, size.y / 6, 0.0f);
                    t.origin = f.origin + f.x * (-0.5f * f.width + (c + 0.5f) * t.size.x) + Y * (-0.5f * size.y + (r + 0.5f) * t.size.y);
                    tiles.push_back(t);
                }
    }
    return tiles;
}

void BM_Unify(benchmark::State& state) {
    const std::vector<Scope> tiles = facadeTiles();
    Grouping g;
    ListWorkspace ws;
    for (auto _ : state) {
        unifyAdjacent(tiles, 1e-4, g, ws);
        benchmark::DoNotOptimize(g.members.data());
    }
    state.counters["entities"] = double(tiles.size());
    state.counters["components"] = g.count();
}

void BM_RayCastTree(benchmark::State& state) {
    const std::vector<Scope> casters = randomBoxes(6, kEntities), targets = randomBoxes(7, kEntities);
    BoxTree tree;
    std::vector<RayHit> out(kEntities);
    for (auto _ : state) {
        rayCast(casters, RayAxis{2, false}, targets, tree, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["hits"] = double(std::count_if(out.begin(), out.end(), [](const RayHit& h) { return h.hit; }));
}

void BM_RayCastEveryBox(benchmark::State& state) {
    const std::vector<Scope> casters = randomBoxes(6, kEntities), targets = randomBoxes(7, kEntities);
    std::vector<RayHit> out(kEntities);
    for (auto _ : state) {
        for (std::uint32_t i = 0; i < kEntities; ++i) {
            glm::dvec3 origin, direction;
            casterRay(casters[i], RayAxis{2, false}, origin, direction);
            RayHit best;
            for (std::uint32_t j = 0; j < kEntities; ++j) {
                const double t = rayBoxDistance(origin, direction, targets[j]);
                if (t < best.distance) best.distance = t, best.target = j, best.hit = true;
            }
            out[i] = best;
        }
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["hits"] = double(std::count_if(out.begin(), out.end(), [](const RayHit& h) { return h.hit; }));
}

void BM_Facing(benchmark::State& state) {
    const std::vector<Scope> tiles = facadeTiles();
    std::vector<StreetSegment> streets;
    for (int s = 0; s < 10; ++s) streets.push_back({{-20.0 + s * 20, 0.5, 25}, {s * 20.0, 0.5, 25}});
    FacingOptions options;
    options.toleranceDegrees = 45;
    options.unoccluded = state.range(0) != 0;
    BoxTree tree;
    std::vector<std::uint8_t> out(tiles.size());
    for (auto _ : state) {
        facing(tiles, streets, options, tree, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["facing"] = double(std::count(out.begin(), out.end(), std::uint8_t(1)));
}

double minimum(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
double maximum(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

/// Fig. 7's city, one genome (growUncontrolled from seed 3).
void BM_DeriveZonedCity(benchmark::State& state) {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/city-zones.grammar");
    Chromosome c;
    Rng rng(3);
    growUncontrolled(g, c, rng, 10);
    bench::runDerive(state, g, c);
}

#define LIST_BENCHMARK(fn) BENCHMARK(fn)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", minimum)->ComputeStatistics("max", maximum)

LIST_BENCHMARK(BM_OrderBy2Keys);
LIST_BENCHMARK(BM_Shuffle);
LIST_BENCHMARK(BM_AggregateAvgVector);
LIST_BENCHMARK(BM_GroupBy);
LIST_BENCHMARK(BM_KMeans6);
LIST_BENCHMARK(BM_Merge);
LIST_BENCHMARK(BM_Unify);
LIST_BENCHMARK(BM_RayCastTree);
LIST_BENCHMARK(BM_RayCastEveryBox);
LIST_BENCHMARK(BM_Facing)->Arg(0)->Arg(1);
LIST_BENCHMARK(BM_DeriveZonedCity);

}  // namespace

SHAPEVO_BENCHMARK_MAIN()

// bench_render: model pictures on the CPU (report/render/), a 100k-triangle model at 800 x 600.
//  - BM_RenderSphere/<views>: MeshRenderer drawing a UV sphere of 100,352 triangles (224 stacks
//    x 224 slices, two colours in bands), framed to fill the picture; 1 = the three-quarter view
//    (what best.png is), 3 = front, side and top side by side (2400 x 600). The renderer is
//    reused, as writeModelPicture's callers may.
//  - BM_WriteModelPicture: the whole best.png path: a fresh renderer, the picture, PNG encoding
//    and the atomic write (to a file in the temp folder).
// Counters: triangles per second.
//
//   cd build && ninja bench_render && taskset -c 1 ./bench/bench_render --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "report/render/model_picture.hpp"

namespace {

using namespace shapevo;

Mesh sphere(int stacks, int slices) {
    Mesh m;
    for (int i = 0; i <= stacks; ++i) {
        const float theta = std::numbers::pi_v<float> * float(i) / float(stacks);
        for (int j = 0; j < slices; ++j) {
            const float phi = 2.0f * std::numbers::pi_v<float> * float(j) / float(slices);
            m.vertices.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
        }
    }
    m.materials = {{"red", {0.7f, 0.1f, 0.1f}}, {"sand", {0.8f, 0.7f, 0.5f}}};
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const auto a = std::uint32_t(i * slices + j), b = std::uint32_t(i * slices + (j + 1) % slices);
            const auto c = a + std::uint32_t(slices), d = b + std::uint32_t(slices);
            m.triangles.push_back({a, c, b});
            m.triangles.push_back({b, c, d});
            m.triangleMaterials.insert(m.triangleMaterials.end(), 2, std::uint32_t(i / 16 % 2));
        }
    return m;
}

const Mesh& bigSphere() {
    static const Mesh m = sphere(224, 224);
    return m;
}

void BM_RenderSphere(benchmark::State& state) {
    const Mesh& m = bigSphere();
    const std::vector<View> views =
        state.range(0) == 1 ? std::vector<View>{View::ThreeQuarter} : std::vector<View>{View::Front, View::Side, View::Top};
    MeshRenderer renderer;
    for (auto _ : state) benchmark::DoNotOptimize(renderViews(m, views, {800, 600}, renderer));
    state.counters["triangles/s"] =
        benchmark::Counter(double(m.triangles.size() * views.size()), benchmark::Counter::kIsIterationInvariantRate);
    state.SetLabel(std::to_string(m.triangles.size()) + " triangles");
}
BENCHMARK(BM_RenderSphere)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_WriteModelPicture(benchmark::State& state) {
    const Mesh& m = bigSphere();
    const std::string path = (std::filesystem::temp_directory_path() / "shapevo-bench-render.png").string();
    for (auto _ : state) writeModelPicture(m, std::array{View::ThreeQuarter}, {800, 600}, path);
    std::filesystem::remove(path);
}
BENCHMARK(BM_WriteModelPicture)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

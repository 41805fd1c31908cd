// bench_graph_genome: the graph-derivation genome (genome/families/graph_family.hpp) on each
// shipped graph grammar. (1) BM_Locality_<grammar>: how much of a drawing one mutation changes —
// over 200 random genomes, the median share of elements that differ after one mutation (an
// element is its vertex position, or its edge's two end positions, to 1e-6; share = 1 - common /
// larger count), for the keyed design (the family's grow: an override of one decision the
// derivation made) and for a plain sequence of draws (the derivation's n-th draw changed, n uniform
// among the draws it made). Counters per design: the median and mean share, the share of mutations
// that change anything (_changing) and the median share among those (_median_if_changed).
// (2) BM_Derive{Keyed,Seeded}_<grammar>: a keyed derivation against the seeded one.
//
//   cd build && ninja bench_graph_genome && ./bench/bench_graph_genome
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "genome/families/graph_family.hpp"
#include "graph/lineage_key.hpp"
#include "graph/read_graph_grammar.hpp"

#include "bench_main.hpp"

namespace {

using namespace shapevo;

const graph::GraphGrammar& load(const std::string& name) {
    static std::map<std::string, graph::GraphGrammar> cache;
    auto it = cache.find(name);
    if (it == cache.end()) it = cache.emplace(name, graph::readGraphGrammar(std::string(SHAPEVO_SOURCE_DIR "/grammars/graph/") + name)).first;
    return it->second;
}

graph::DeriveLimits limitsFor(const graph::GraphGrammar& g) {
    graph::DeriveLimits l;
    if (g.globalLimit == 0) l.maxSteps = 1000;
    return l;
}

/// The plain design: the n-th draw of a derivation is words[n] (or a hash of seed and n past them).
class SequenceDraws final : public graph::DrawSource {
public:
    SequenceDraws(std::uint64_t seed, const std::vector<std::uint64_t>& words) : seed_(seed), words_(words) {}
    double uniform(graph::DrawPurpose) override { return graph::wordUniform(next()); }
    std::uint64_t below(std::uint64_t n, graph::DrawPurpose) override { return graph::wordBelow(next(), n); }
    std::uint64_t used() const { return n_; }

private:
    std::uint64_t next() {
        const std::uint64_t i = n_++;
        return i < words_.size() ? words_[i] : graph::defaultWord(seed_, i);
    }
    std::uint64_t seed_;
    const std::vector<std::uint64_t>& words_;
    std::uint64_t n_ = 0;
};

using Signature = std::vector<long long>;
std::vector<Signature> signatures(const graph::HostGraph& g) {
    std::vector<Signature> out;
    auto q = [](double x) { return (long long)std::llround(x * 1e6); };
    for (const graph::HostVertex& v : g.vertices())
        if (v.alive) out.push_back({0, q(v.position.x), q(v.position.y)});
    for (const graph::HostEdge& e : g.edges()) {
        if (!e.alive) continue;
        Signature s{1};
        for (graph::ElementId v : {e.vertex1, e.vertex2})
            if (v != graph::kNoVertex) s.insert(s.end(), {q(g.vertex(v).position.x), q(g.vertex(v).position.y)});
        if (s.size() == 5 && std::make_pair(s[1], s[2]) > std::make_pair(s[3], s[4])) std::swap(s[1], s[3]), std::swap(s[2], s[4]);
        out.push_back(s);
    }
    std::sort(out.begin(), out.end());
    return out;
}

double changedShare(const graph::HostGraph& a, const graph::HostGraph& b) {
    const std::vector<Signature> x = signatures(a), y = signatures(b);
    std::vector<Signature> common;
    std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(common));
    const std::size_t larger = std::max(x.size(), y.size());
    return larger == 0 ? 0.0 : 1.0 - double(common.size()) / double(larger);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}
double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0 : s / double(v.size());
}

void locality(benchmark::State& state, const char* name) {
    const graph::GraphGrammar& g = load(name);
    const GraphFamily family(g, limitsFor(g));
    std::vector<double> keyed, sequence;
    GenomeLimits limits;
    const auto ops = family.makeOperators(limits);
    for (auto _ : state) {
        keyed.clear();
        sequence.clear();
        Rng rng(2026);
        for (int i = 0; i < 200; ++i) {
            const std::uint64_t seed = rng.next();
            // keyed: one decision of the derivation overridden
            Chromosome c;
            makeGraphGenome(c, seed);
            graph::DecisionRecord record;
            const graph::DeriveResult base = family.derive(c, &record);
            Chromosome m = c;
            if (ops->grow(m, rng)) keyed.push_back(changedShare(base.graph, family.derive(m).graph));
            // plain sequence: one draw of the derivation changed
            std::vector<std::uint64_t> words;
            SequenceDraws first(seed, words);
            const graph::DeriveResult sbase = graph::deriveGraph(g, 0, first, family.limits());
            if (first.used() == 0) continue;
            words.resize(first.used());
            for (std::size_t k = 0; k < words.size(); ++k) words[k] = graph::defaultWord(seed, k);
            words[rng.below(std::uint32_t(words.size()))] = rng.next();
            SequenceDraws second(seed, words);
            sequence.push_back(changedShare(sbase.graph, graph::deriveGraph(g, 0, second, family.limits()).graph));
        }
    }
    auto report = [&](const char* design, const std::vector<double>& v) {
        std::vector<double> changed;
        for (double x : v)
            if (x > 0) changed.push_back(x);
        state.counters[std::string(design) + "_median"] = median(v);
        state.counters[std::string(design) + "_mean"] = mean(v);
        state.counters[std::string(design) + "_changing"] = v.empty() ? 0 : double(changed.size()) / double(v.size());
        state.counters[std::string(design) + "_median_if_changed"] = median(changed);
    };
    report("keyed", keyed);
    report("sequence", sequence);
}

void derive(benchmark::State& state, const char* name, bool keyed) {
    const graph::GraphGrammar& g = load(name);
    const GraphFamily family(g, limitsFor(g));
    std::uint64_t seed = 1;
    for (auto _ : state) {
        if (keyed) {
            Chromosome c;
            makeGraphGenome(c, seed++);
            benchmark::DoNotOptimize(family.derive(c).steps);
        } else {
            graph::SeededDraws draws(seed++);
            benchmark::DoNotOptimize(graph::deriveGraph(g, 0, draws, family.limits()).steps);
        }
    }
}

#define GRAPH_GENOME_BENCHES(id, file)                                                                      \
    void BM_Locality_##id(benchmark::State& s) { locality(s, file); }                                        \
    BENCHMARK(BM_Locality_##id)->Unit(benchmark::kMillisecond)->Iterations(1);                               \
    void BM_DeriveKeyed_##id(benchmark::State& s) { derive(s, file, true); }                                 \
    BENCHMARK(BM_DeriveKeyed_##id)->Unit(benchmark::kMillisecond);                                            \
    void BM_DeriveSeeded_##id(benchmark::State& s) { derive(s, file, false); }                               \
    BENCHMARK(BM_DeriveSeeded_##id)->Unit(benchmark::kMillisecond);

GRAPH_GENOME_BENCHES(koch, "koch.yml")
GRAPH_GENOME_BENCHES(tree, "tree.yml")
GRAPH_GENOME_BENCHES(radial, "radial.yml")
GRAPH_GENOME_BENCHES(tiled, "tiled.yml")
GRAPH_GENOME_BENCHES(facade, "facade.yml")
GRAPH_GENOME_BENCHES(mosaic, "mosaic.yml")

}  // namespace

SHAPEVO_BENCHMARK_MAIN();

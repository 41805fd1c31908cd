// `.pcg` graph files derive what they say: PCGR's Fig. 2 window written as a graph derives the
// very primitives (bit for bit) of the same window written by hand in the shapevo language, for
// the same genomes; a cyclic graph (Fig. 3's kind of tree) translates its cyclic edge into a
// child slot and its chance nodes into slots with their probability, and derives a tree that
// recurses until thin pieces carry oranges; an included graph is bound by its node's
// arguments and listed in Grammar::includes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "base/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "grammar/pcg/pcg_front_end.hpp"

namespace shapevo {
namespace pcg_derive_test_helpers {

using test::sourcePath;

using test::deriveComplete;

std::size_t countKind(const Geometry& geo, PrimitiveKind kind) {
    std::size_t n = 0;
    for (const Primitive& p : geo.primitives) n += p.kind == kind;
    return n;
}

}  // namespace pcg_derive_test_helpers

using namespace pcg_derive_test_helpers;

TEST(PcgDerive, TheWindowGraphDerivesBitIdenticallyToTheHandWrittenWindow) {
    const Grammar graph = loadGrammar(sourcePath("grammars/pcg/window.pcg"));
    const Grammar hand = loadGrammar(sourcePath("grammars/pcg/window.grammar"));
    ASSERT_EQ(graph.rules[graph.start].geneWords(), hand.rules[hand.start].geneWords());
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(graph, c, rng, 100));
        const Geometry a = deriveComplete(graph, c), b = deriveComplete(hand, c);
        EXPECT_EQ(a.primitives.size(), 6u);  // four frame bars, the pane, the sill
        EXPECT_TRUE(test::identical(a, b)) << "seed " << seed;
    }
}

TEST(PcgDerive, TheCyclicTreeGraphTurnsItsCyclicEdgeIntoAChildSlotAndRecurses) {
    const std::string path = sourcePath("grammars/pcg/tree.pcg");
    const std::string text = test::readFile(path);
    const Translation t = pcg::translatePcg(text, path);
    EXPECT_NE(t.text.find("child pcg_c_wood optional"), std::string::npos) << t.text;
    for (const char* slot : {"child pcg_y_first prob 0.35", "child pcg_y_second prob 0.35", "child pcg_y_third prob 0.35"})
        EXPECT_NE(t.text.find(slot), std::string::npos) << slot << "\n" << t.text;
    const Grammar g = loadGrammar(path);
    ASSERT_GE(g.findRule("pcg_c_wood"), 0);
    std::size_t deepest = 0, oranges = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng(seed);
        const SampleOutcome o = sampleDerivation(g, c, rng, 1, 2000, 50);
        ASSERT_TRUE(o.found) << "seed " << seed;
        const Geometry geo = deriveComplete(g, c);
        deepest = std::max(deepest, countKind(geo, PrimitiveKind::Cone));
        for (const Primitive& prim : geo.primitives)  // an orange: a sphere of 0.25 (leaves are spheres too)
            oranges += prim.kind == PrimitiveKind::Sphere && std::abs(prim.half.x - 0.125f) < 1e-6f;
    }
    EXPECT_GE(deepest, 3u) << "some tree has branches (trunk, two branches at least)";
    EXPECT_GT(oranges, 0u);
}

TEST(PcgDerive, AnIncludedGraphIsBoundByItsNodeArgumentsAndListedAsAnInclude) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.file("parts"));
    test::writeFile(dir.file("parts/pillar.pcg"),
                    "graph Pillar\nparam h = uniform(1, 2)\nin base : volume\nout top : volume\n"
                    "node shape = size(0.5, h, 0.5)\nnode draw = box()\nbase -> shape\nshape -> draw\ndraw -> top\n");
    test::writeFile(dir.file("main.pcg"),
                    "graph Main\nin start : volume\nnode p = include \"parts/pillar.pcg\"(h: 3)\n"
                    "node q = include \"parts/pillar.pcg\"\nnode cap = sphere()\nstart -> p, q\np.top -> cap\n");
    const Grammar g = loadGrammar(dir.file("main.pcg"));
    ASSERT_EQ(g.includes.size(), 1u);
    EXPECT_EQ(g.includes[0], "parts/pillar.pcg");
    Chromosome c;
    Rng rng(7);
    ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
    const Geometry geo = deriveComplete(g, c);
    ASSERT_EQ(countKind(geo, PrimitiveKind::Box), 2u);
    EXPECT_EQ(countKind(geo, PrimitiveKind::Sphere), 1u);  // only p's top gate is connected
    std::size_t bound = 0, drawn = 0;
    for (const Primitive& prim : geo.primitives) {
        if (prim.kind != PrimitiveKind::Box) continue;
        bound += std::abs(prim.half.y - 1.5f) < 1e-6f;                       // h: 3 given
        drawn += prim.half.y >= 0.5f - 1e-6f && prim.half.y <= 1.0f + 1e-6f;  // h from its prior [1, 2]
    }
    EXPECT_EQ(bound, 1u);
    EXPECT_EQ(drawn, 1u);
}

}  // namespace shapevo

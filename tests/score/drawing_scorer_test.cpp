// DrawingScorer (score/image/drawing_scorer.hpp): its counts are the raster's pixels against the
// target's, its tolerance is what its words say (checked pixel by pixel against distances), its
// fitness is the image fitness of those counts, a failing derivation scores the worst fitness,
// and scoring leaves the genome's decision record for its children.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "genome/families/graph_family.hpp"
#include "graph/read_graph_grammar.hpp"
#include "score/image/drawing_scorer.hpp"

namespace drawing_scorer_test {

using namespace shapevo;

graph::GraphGrammar shippedTree() { return graph::readGraphGrammar(std::string(SHAPEVO_SOURCE_DIR) + "/grammars/graph/tree.yml"); }

/// A 64 x 64 target: a disc of radius 20 at (32, 40) is hit, the rest avoid.
ImageTarget discTarget() {
    const int n = 64;
    std::vector<std::uint8_t> lum(n * n, 255), alpha(n * n, 255);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            if ((x - 32) * (x - 32) + (y - 40) * (y - 40) <= 400) lum[std::size_t(y * n + x)] = 0;
    return makeImageTarget(n, n, lum, alpha, PixelRule::forCover(TargetCover::Dark));
}

/// The frame of the tree's canvas, 64 x 64.
graph::RasterFrame treeFrame(const GraphFamily& family) {
    Chromosome c;
    makeGraphGenome(c, 1);
    const graph::Drawing d = graph::drawingOf(family.derive(c).graph, family.grammar().names, family.grammar().path);
    return graph::frameFitting(graph::canvasOf(d, 0.5), 64, 64);
}

TEST(DrawingScorer, CountsAreTheRastersPixelsAgainstTheTargetsAndTheToleranceIsADisc) {
    const graph::GraphGrammar g = shippedTree();
    const GraphFamily family(g, {});
    const ImageTarget target = discTarget();
    const graph::RasterFrame frame = treeFrame(family);
    FitnessSettings fs;
    for (int tolerance : {0, 1, 3}) {
        const DrawingScorer scorer(family, target, frame, fs, tolerance);
        auto ws = scorer.makeWorkspace();
        auto& w = static_cast<DrawingScorer::Workspace&>(*ws);
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
            Chromosome c;
            makeGraphGenome(c, seed);
            SilhouetteCounts counts;
            const double f = scorer.score(c, w, &counts);
            // brute force, pixel by pixel
            SilhouetteCounts exact, tolerant;
            auto near = [&](int x, int y, auto&& is) {
                for (int dy = -tolerance; dy <= tolerance; ++dy)
                    for (int dx = -tolerance; dx <= tolerance; ++dx) {
                        const int xx = x + dx, yy = y + dy;
                        if (dx * dx + dy * dy <= tolerance * tolerance && xx >= 0 && yy >= 0 && xx < 64 && yy < 64 && is(xx, yy)) return true;
                    }
                return false;
            };
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 64; ++x) {
                    const bool m = w.raster.covered(x, y);
                    exact.covered += m;
                    exact.hit += m && target.isHit(x, y);
                    exact.avoided += m && target.isAvoid(x, y);
                    tolerant.hit += target.isHit(x, y) && near(x, y, [&](int a, int b) { return w.raster.covered(a, b); });
                    tolerant.avoided += m && target.isAvoid(x, y) && !near(x, y, [&](int a, int b) { return target.isHit(a, b); });
                }
            EXPECT_EQ(counts, exact) << "seed " << seed;
            EXPECT_GT(exact.covered, 0u);
            EXPECT_DOUBLE_EQ(f, imageFitness(fs, tolerance == 0 ? exact : tolerant, target.hitCount, std::uint32_t(w.steps)))
                << "seed " << seed << ", tolerance " << tolerance;
            ASSERT_TRUE(w.made);
            EXPECT_EQ(w.made->maker, &GraphDerivationRecord::kMaker);
        }
    }
}

TEST(DrawingScorer, AFailingDerivationScoresTheWorstFitnessAndIsCounted) {
    const graph::GraphGrammar g = shippedTree();
    graph::DeriveLimits limits;
    limits.maxElements = 50;  // the tree passes it: the derivation fails
    const GraphFamily family(g, limits);
    const ImageTarget target = discTarget();
    const DrawingScorer scorer(family, target, graph::RasterFrame{0, 0, 1, 64, 64}, FitnessSettings{}, 0);
    auto ws = scorer.makeWorkspace();
    Chromosome c;
    makeGraphGenome(c, 1);
    EXPECT_EQ(scorer.fitness(c, *ws), Scorer::kWorstFitness);
    EXPECT_EQ(scorer.anomalies().nonFinite, 1u);
}

}  // namespace drawing_scorer_test

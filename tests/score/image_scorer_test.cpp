// ImageScorer: derive + silhouette + counts + fitness. A model scored against its own
// silhouette is perfect; workspaces are reused without leftovers; the counts equal drawing the
// derived geometry directly; the model mask is the drawing.
#include <gtest/gtest.h>

#include <vector>

#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "score/image/image_scorer.hpp"
#include "../small_tree_grammar.hpp"
#include "silhouette_test_util.hpp"

namespace shapevo {
namespace {

Chromosome grown(const Grammar& g, std::uint32_t genes, std::uint64_t seed) {
    Rng rng(seed);
    const GenomeLimits limits{genes};
    Chromosome c;
    while (c.genes < genes && grow(g, c, rng, limits)) {
    }
    return c;
}

/// The mask as a target: model pixels black (hit), the rest white (avoid).
ImageTarget targetFromMask(const std::vector<std::uint8_t>& mask, int w, int h) {
    std::vector<std::uint8_t> lum(mask.size()), alpha(mask.size(), 255);
    for (std::size_t i = 0; i < mask.size(); ++i) lum[i] = mask[i] ? 0 : 255;
    return makeImageTarget(w, h, lum, alpha, PixelRule{});
}

TEST(ImageScorer, ModelMatchingItsOwnSilhouetteScoresPerfectly) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const Camera camera = test::smallTreeCamera();
    const Chromosome model = grown(g, 30, 5);
    ImageScorer::Workspace ws(camera);
    std::vector<std::uint8_t> mask;
    {
        const ImageTarget dummy = targetFromMask(std::vector<std::uint8_t>(160 * 120, 1), 160, 120);
        ImageScorer(g, camera, dummy, FitnessSettings{}).modelMask(model, ws, mask);
    }
    const ImageTarget target = targetFromMask(mask, 160, 120);
    ASSERT_GT(target.hitCount, 500u);
    FitnessSettings settings;
    const ImageScorer scorer(g, camera, target, settings);
    SilhouetteCounts counts;
    const double f = scorer.fitness(model, ws, &counts);
    EXPECT_EQ(counts.hit, target.hitCount);
    EXPECT_EQ(counts.covered, target.hitCount);
    EXPECT_EQ(counts.avoided, 0u);
    EXPECT_DOUBLE_EQ(silhouetteIoU(counts, target.hitCount), 1.0);
    EXPECT_DOUBLE_EQ(f, settings.alpha - settings.gamma * smootherstep(model.genes, settings.lengthOptimal, settings.lengthMax));
    const Chromosome other = grown(g, 30, 99);
    EXPECT_LT(scorer.fitness(other, ws, nullptr), f);
}

TEST(ImageScorer, WorkspaceReuseLeavesNothingBehindAndCountsEqualDirectDrawing) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const Camera camera = test::smallTreeCamera();
    std::vector<std::uint8_t> lum(160 * 120), alpha(160 * 120, 255);
    for (std::size_t i = 0; i < lum.size(); ++i) lum[i] = (i / 160 + i % 160) % 3 ? 255 : 0;  // diagonal stripes
    const ImageTarget target = makeImageTarget(160, 120, lum, alpha, PixelRule{});
    const ImageScorer scorer(g, camera, target, FitnessSettings{});
    std::vector<Chromosome> pop;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) pop.push_back(grown(g, 5 + std::uint32_t(seed) * 4, seed));
    std::vector<double> fresh;
    for (const Chromosome& c : pop) {
        auto ws = scorer.makeWorkspace();
        fresh.push_back(scorer.fitness(c, *ws));
    }
    auto ws = scorer.makeWorkspace();
    for (int round = 0; round < 3; ++round)
        for (std::size_t i = 0; i < pop.size(); ++i) EXPECT_EQ(scorer.fitness(pop[i], *ws), fresh[i]) << i;
    // counts equal drawing the derived geometry with a separate raster
    auto& w = static_cast<ImageScorer::Workspace&>(*ws);
    for (const Chromosome& c : pop) {
        SilhouetteCounts counts;
        scorer.fitness(c, w, &counts);
        Geometry geometry;
        DeriveScratch scratch;
        derive(g, c, geometry, scratch);
        SilhouetteRaster raster(camera);
        raster.add(geometry);
        std::vector<std::uint8_t> mask, direct;
        raster.fillMask(direct);
        EXPECT_EQ(raster.score(target), counts);
        silhouetteMask(geometry, camera, mask);
        EXPECT_EQ(mask, direct);
        std::uint64_t ones = 0;
        for (std::uint8_t m : mask) ones += m;
        EXPECT_EQ(ones, counts.covered);
    }
}

TEST(ImageScorer, TargetOfAnotherSizeIsRefused) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const ImageTarget small = makeImageTarget(4, 4, std::vector<std::uint8_t>(16, 0), std::vector<std::uint8_t>(16, 255), PixelRule{});
    EXPECT_THROW(ImageScorer(g, test::smallTreeCamera(), small, FitnessSettings{}), std::invalid_argument);
}

}  // namespace
}  // namespace shapevo

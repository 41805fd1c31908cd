// PCGR's Fig. 5, encapsulation (grammars/pcg/roof-tiles.pcg): the grid's gates and params make an
// include node whose rows and columns evolve; the fit's gate takes every cell and its bound
// margin insets a brick tile (a third graph, included by the second) into each. Checked from the
// derived model: rows x cols slabs and roofs, each slab its cell inset by the margin; the same
// fit graph included with another margin gives other tiles.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "base/random.hpp"
#include "genome/sample.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace pcg_roof_tiles_test {

/// roof-tiles.pcg with the fit's margin bound to `margin`, in `dir` (its includes by absolute path).
std::string roofWithMargin(const test::TempDir& dir, const std::string& margin) {
    std::string text = test::readFile(test::sourcePath("grammars/pcg/roof-tiles.pcg"));
    const auto replace = [&](const std::string& from, const std::string& to) {
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
    };
    replace("\"parts/grid.pcg\"", "\"" + test::sourcePath("grammars/pcg/parts/grid.pcg") + "\"");
    replace("\"parts/fit.pcg\"(margin: 0.1)", "\"" + test::sourcePath("grammars/pcg/parts/fit.pcg") + "\"(margin: " + margin + ")");
    const std::string path = dir.file("roof-" + margin + ".pcg");
    test::writeFile(path, text);
    return path;
}

}  // namespace pcg_roof_tiles_test

using namespace pcg_roof_tiles_test;

TEST(PcgRoofTiles, EachCellOfTheIncludedGridGetsABrickTileFittedByTheIncludedFit) {
    test::TempDir dir;
    const Grammar shipped = loadGrammar(test::sourcePath("grammars/pcg/roof-tiles.pcg"));
    const Grammar wide = loadGrammar(roofWithMargin(dir, "0.3"));
    ASSERT_EQ(shipped.rules[shipped.start].geneWords(), wide.rules[wide.start].geneWords());
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(shipped, c, rng, 10));
        const float width = test::startParam(shipped, c, "width"), rows = test::startParam(shipped, c, "grid__rows"),
                    cols = test::startParam(shipped, c, "grid__cols");
        for (const auto& [g, margin] : {std::pair<const Grammar*, float>{&shipped, 0.1f}, {&wide, 0.3f}}) {
            const Geometry geo = test::deriveComplete(*g, c);
            std::size_t slabs = 0, roofs = 0;
            for (const Primitive& p : geo.primitives) {
                if (p.kind == PrimitiveKind::Roof) {
                    ++roofs;
                    continue;
                }
                ++slabs;
                EXPECT_NEAR(2.0f * p.half.x, width / cols * (1.0f - margin), 1e-4f) << "margin " << margin;
                EXPECT_NEAR(2.0f * p.half.z, 6.0f / rows * (1.0f - margin), 1e-4f) << "margin " << margin;
                EXPECT_NEAR(2.0f * p.half.y, 0.2f, 1e-5f);
            }
            EXPECT_EQ(slabs, std::size_t(rows * cols));
            EXPECT_EQ(roofs, slabs);
        }
    }
}

}  // namespace shapevo

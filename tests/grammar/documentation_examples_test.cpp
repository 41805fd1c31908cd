// The grammars the documentation shows (docs/grammar-examples/, pictured in docs/figures/grammar/
// and quoted in grammars/README.md) parse and derive: a change to the language that breaks an
// example fails here, not in a reader's hands.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

TEST(DocumentationExamples, EveryExampleGrammarParsesAndDerivesPrimitives) {
    int examples = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("docs/grammar-examples"))) {
        if (entry.path().extension() != ".grammar") continue;
        SCOPED_TRACE(entry.path().string());
        const Grammar g = loadGrammar(entry.path().string());
        Rng rng(3);
        Chromosome c;
        plantRoot(g, c, rng);
        Geometry out;
        DeriveScratch scratch;
        EXPECT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
        EXPECT_GT(out.primitives.size(), 0u);
        EXPECT_EQ(out.appearance.size(), out.primitives.size());  // every example is coloured
        ++examples;
    }
    EXPECT_GE(examples, 7);
}

}  // namespace
}  // namespace shapevo

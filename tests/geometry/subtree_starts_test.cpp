// Deriving one changed subtree (geometry/derive.hpp: findSubtreeStarts, deriveSubtree): for every
// shipped grammar and every operator that names what it changed (genome Lineage), the child's
// primitives are the parent's, less the old subtree's at each of its starts, plus the new
// subtree's there — as multisets, bit for bit — and so are the task counts the limits check; a
// changed gene the derivation never reaches (no start) leaves the parent's model as it was.
// This is what scoring a child from its parent (score/image/image_from_parent.cpp) rests on.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "score/primitive_cache.hpp"

namespace shapevo {
namespace {

using Keys = std::vector<std::array<std::uint32_t, PrimitiveKey::kWords>>;

void appendKeys(const Geometry& geo, Keys& keys) {
    for (const Primitive& p : geo.primitives) {
        const PrimitiveKey k(p);
        std::array<std::uint32_t, PrimitiveKey::kWords> a;
        std::copy(std::begin(k.words), std::end(k.words), a.begin());
        keys.push_back(a);
    }
}

/// Parent keys less `removed` (each once), plus `added`; false if a removed one is missing.
bool patch(Keys parent, const Keys& removed, const Keys& added, Keys& out) {
    std::sort(parent.begin(), parent.end());
    for (const auto& k : removed) {
        const auto it = std::lower_bound(parent.begin(), parent.end(), k);
        if (it == parent.end() || *it != k) return false;
        parent.erase(it);
    }
    out = std::move(parent);
    out.insert(out.end(), added.begin(), added.end());
    std::sort(out.begin(), out.end());
    return true;
}

TEST(SubtreeStarts, AChildIsItsParentLessTheOldSubtreePlusTheNewAtEveryStartForEveryShippedGrammar) {
    const auto dummy = std::make_shared<EvaluatedModel>();
    std::size_t checked = 0, manyStarts = 0, unreached = 0;
    for (const std::string& path : test::shippedGrammarFiles()) {
        SCOPED_TRACE(path);
        const Grammar g = loadGrammar(path);
        const GenomeLimits limits{150, 40000};
        Rng rng(9);
        GenomeScratch scratch;
        DeriveScratch d;
        Geometry geo;
        std::vector<SubtreeStart> starts;
        for (int trial = 0; trial < 120; ++trial) {
            Chromosome a, b, x, y;
            growRandomLength(g, a, rng, limits, 2, 60);
            growRandomLength(g, b, rng, limits, 2, 60);
            a.lineage.parent = dummy;
            b.lineage.parent = dummy;
            x = a;
            const int op = trial % 4;
            if (op == 0) grow(g, x, rng, limits);
            else if (op == 1) cut(g, x, rng, scratch);
            else if (op == 2) alter(g, x, rng);
            else crossover(g, a, b, x, y, rng, limits, 3, scratch);
            const Lineage l = x.lineage;
            if (!l.changed()) continue;  // the operator could not apply
            ASSERT_EQ(l.parent, dummy);
            if (l.childGene == 0 || l.parentGene == 0) continue;  // the whole model: nothing to patch
            Keys parent, child, removed, added;
            if (derive(g, a, geo, d, limits.maxPrimitives) != DeriveStatus::Complete) continue;
            const std::size_t parentTasks = d.tasks;
            appendKeys(geo, parent);
            if (derive(g, x, geo, d, limits.maxPrimitives) != DeriveStatus::Complete) continue;
            const std::size_t childTasks = d.tasks;
            appendKeys(geo, child);
            std::sort(child.begin(), child.end());
            if (l.childGene != Lineage::kNone) ASSERT_EQ(findSubtreeStarts(g, x, l.childGene, d, starts), DeriveStatus::Complete);
            else ASSERT_EQ(findSubtreeStarts(g, a, l.parentGene, d, starts), DeriveStatus::Complete);
            // No start: the gene hangs where the derivation never goes (a child slot under an `if`
            // its scope fails, as tree.pcg's recursion): the child is the parent, which the check
            // below then proves (nothing removed, nothing added).
            unreached += starts.empty();
            manyStarts += starts.size() > 1;
            std::int64_t tasks = std::int64_t(parentTasks);
            for (const SubtreeStart& s : starts) {
                if (l.parentGene != Lineage::kNone) {
                    ASSERT_EQ(deriveSubtree(g, a, l.parentGene, s, geo, d, limits.maxPrimitives), DeriveStatus::Complete);
                    appendKeys(geo, removed);
                    tasks -= std::int64_t(d.tasks);
                }
                if (l.childGene != Lineage::kNone) {
                    ASSERT_EQ(deriveSubtree(g, x, l.childGene, s, geo, d, limits.maxPrimitives), DeriveStatus::Complete);
                    appendKeys(geo, added);
                    tasks += std::int64_t(d.tasks);
                }
            }
            Keys patched;
            ASSERT_TRUE(patch(parent, removed, added, patched)) << "operator " << op << ": an old primitive the parent lacks";
            ASSERT_TRUE(patched == child) << "operator " << op << ": " << patched.size() << " primitives against " << child.size();
            ASSERT_EQ(tasks, std::int64_t(childTasks)) << "operator " << op;
            ++checked;
        }
    }
    EXPECT_GT(checked, 300u);
    EXPECT_GT(manyStarts, 0u);  // mirrors and repeated pieces: a subtree derived at several starts
    EXPECT_LT(unreached, checked / 4) << "most changes are reached";
}

TEST(SubtreeStarts, ASecondChangeOrAnUnknownParentLeavesNoLineageToTrust) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/tree.grammar"));
    Rng rng(4);
    const GenomeLimits limits{100};
    Chromosome c;
    growRandomLength(g, c, rng, limits, 20, 30);
    ASSERT_TRUE(alter(g, c, rng));
    EXPECT_FALSE(c.lineage.changed());  // no parent: nothing named
    c.lineage.parent = std::make_shared<EvaluatedModel>();
    ASSERT_TRUE(alter(g, c, rng));
    EXPECT_TRUE(c.lineage.changed());
    Chromosome copy;
    copy.copyFrom(c);
    EXPECT_TRUE(copy.lineage.changed());
    ASSERT_TRUE(alter(g, c, rng));
    EXPECT_FALSE(c.lineage.changed());  // two changes: not one subtree any more
    EXPECT_FALSE(c.lineage.parent);
    copy.clear();
    EXPECT_FALSE(copy.lineage.parent);
    Chromosome other = c;
    other.lineage.parent = std::make_shared<EvaluatedModel>();
    EXPECT_TRUE(other == c);  // the lineage is not part of the value
}

}  // namespace
}  // namespace shapevo

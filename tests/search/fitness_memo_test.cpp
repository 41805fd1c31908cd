// Duplicates are not scored twice (search/fitness_memo.hpp, Evaluator): the memo finds only
// word-for-word equal chromosomes and stays within its bytes; an Evaluator with incremental
// scoring on scores each distinct chromosome of a batch once, gives every duplicate the same
// fitness as scoring it, keeps the anomaly sums, and does the same with 1 or 2 threads.
#include <gtest/gtest.h>

#include <atomic>

#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "score/tree_scorer.hpp"
#include "search/evaluator.hpp"
#include "../small_tree_grammar.hpp"

namespace shapevo {
namespace {

Chromosome words(std::initializer_list<std::uint32_t> w, std::uint32_t genes) {
    Chromosome c;
    c.words = w;
    c.genes = genes;
    return c;
}

TEST(FitnessMemo, FindsOnlyWordForWordEqualChromosomes) {
    FitnessMemo memo(64, 1 << 20);
    const Chromosome a = words({1, 0, 5, 7}, 1), b = words({1, 0, 5, 8}, 1), c = words({1, 0, 5, 7}, 2);
    FitnessMemo::Entry* e = memo.insert(a, FitnessMemo::hashOf(a));
    ASSERT_NE(e, nullptr);
    e->fitness = 0.5;
    ASSERT_NE(memo.find(a, FitnessMemo::hashOf(a)), nullptr);
    EXPECT_EQ(memo.find(a, FitnessMemo::hashOf(a))->fitness, 0.5);
    EXPECT_EQ(memo.find(b, FitnessMemo::hashOf(b)), nullptr);
    EXPECT_EQ(memo.find(b, FitnessMemo::hashOf(a)), nullptr);  // a colliding hash is not enough
    EXPECT_EQ(memo.find(c, FitnessMemo::hashOf(a)), nullptr);  // same words, other gene count
}

TEST(FitnessMemo, StaysWithinItsBytesAndRefusesHugeChromosomes) {
    const std::size_t maxBytes = 64 * 1024;
    FitnessMemo memo(1024, maxBytes);
    Rng rng(2);
    for (int i = 0; i < 5000; ++i) {
        Chromosome c;
        c.words.resize(1 + rng.below(2000));
        for (auto& w : c.words) w = rng.below(1000);
        c.genes = 1;
        if (FitnessMemo::Entry* e = memo.insert(c, FitnessMemo::hashOf(c))) e->fitness = i;
        ASSERT_LE(memo.bytesHeld(), maxBytes) << i;
    }
    Chromosome huge;
    huge.words.assign(maxBytes / 4 / 4 + 1, 3);  // more than a quarter of the bytes
    EXPECT_EQ(memo.insert(huge, FitnessMemo::hashOf(huge)), nullptr);
}

const char* const kTree = test::kSmallTree;

/// Scores by deriving (so anomalies are counted: max_primitives 3 truncates most trees) and counts
/// the models it scored.
class CountingScorer final : public TreeScorer {
public:
    explicit CountingScorer(const Grammar& g) : grammar_(g) { setMaxPrimitives(3); }
    std::unique_ptr<ScoreWorkspace> makeWorkspace() const override { return std::make_unique<ScoreWorkspace>(); }
    double fitness(const Chromosome& c, ScoreWorkspace& w) const override {
        scored.fetch_add(1);
        if (!deriveCounted(c, w)) return kWorstFitness;
        double f = 0;
        for (const Primitive& p : w.geometry.primitives) f += p.centre.y * 0.25 + p.half.x;
        return f;
    }
    const Grammar& grammar() const override { return grammar_; }
    mutable std::atomic<int> scored{0};

private:
    const Grammar& grammar_;
};

/// 300 individuals, many of them equal to an earlier one.
Population withDuplicates(const Grammar& g) {
    Rng rng(9);
    Population pop;
    const GenomeLimits limits{40};
    for (int i = 0; i < 300; ++i) {
        if (i >= 10 && rng.below(3) == 0) {
            pop.individuals.push_back(pop.individuals[rng.below(std::uint32_t(i))]);
            continue;
        }
        Chromosome c;
        for (std::uint32_t n = 1 + rng.below(12); c.genes < n && grow(g, c, rng, limits);) {
        }
        pop.individuals.push_back(c);
    }
    return pop;
}

TEST(EvaluatorDuplicates, EachDistinctModelIsScoredOnceAndDuplicatesGetItsFitnessAndAnomalies) {
    const Grammar g = parseGrammar(kTree, "tree.grammar");
    const Population start = withDuplicates(g);
    CountingScorer plain(g);
    Population want = start;
    Evaluator(plain, 1).evaluate(want);
    ASSERT_EQ(plain.scored.load(), 300);
    ASSERT_GT(plain.anomalies().truncated, 50u);
    for (int threads : {1, 2}) {
        SCOPED_TRACE(threads);
        CountingScorer memoized(g);
        memoized.setIncremental(1 << 20);
        Evaluator evaluator(memoized, threads);
        Population got = start;
        evaluator.evaluate(got);
        EXPECT_EQ(got.fitness, want.fitness);
        EXPECT_EQ(memoized.anomalies().truncated, plain.anomalies().truncated);
        EXPECT_EQ(memoized.anomalies().nonFinite, plain.anomalies().nonFinite);
        EXPECT_LT(memoized.scored.load(), 250);
        EXPECT_EQ(std::uint64_t(memoized.scored.load()) + evaluator.reused(), 300u);
        // a second batch (the elites kept at the front) finds every model remembered
        got.fitness.assign(got.size(), -7.0);
        evaluator.evaluate(got, 100);
        EXPECT_EQ(std::vector<double>(got.fitness.begin() + 100, got.fitness.end()),
                  std::vector<double>(want.fitness.begin() + 100, want.fitness.end()));
        EXPECT_EQ(evaluator.reused(), 300u - std::uint64_t(memoized.scored.load()) + 200u);
    }
}

TEST(EvaluatorDuplicates, WithIncrementalScoringOffEveryModelIsScored) {
    const Grammar g = parseGrammar(kTree, "tree.grammar");
    CountingScorer plain(g);
    Population pop = withDuplicates(g);
    Evaluator evaluator(plain, 2);
    evaluator.evaluate(pop);
    EXPECT_EQ(plain.scored.load(), 300);
    EXPECT_EQ(evaluator.reused(), 0u);
}

}  // namespace
}  // namespace shapevo

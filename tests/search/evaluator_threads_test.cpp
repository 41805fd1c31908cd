// Evaluator threads (issue 11, row 14): asking for more threads than the machine gives runs on all
// it gives, and threads() reports that number (what summary.json records), not the request.
#include <gtest/gtest.h>

#include <thread>

#include "function_scorer.hpp"
#include "grammar/front_ends.hpp"
#include "search/evaluator.hpp"

namespace shapevo {
namespace {

TEST(EvaluatorThreads, ARequestBeyondTheMachineIsClampedAndReportedAsUsed) {
    const Grammar g = parseGrammar("start S\nrule S { box }\n", "t.grammar");
    const test::FunctionScorer scorer(g, [](const Chromosome&) { return 0.0; });
    const int all = Evaluator::usableThreads(0);
    EXPECT_GE(all, 1);
    EXPECT_LE(unsigned(all), std::max(1u, std::thread::hardware_concurrency()));
    EXPECT_EQ(Evaluator::usableThreads(1), 1);
    EXPECT_EQ(Evaluator::usableThreads(1000), all);
    EXPECT_EQ(Evaluator(scorer, 1000).threads(), all);
    EXPECT_EQ(Evaluator(scorer, 0).threads(), all);
    EXPECT_EQ(Evaluator(scorer, 1).threads(), 1);
}

}  // namespace
}  // namespace shapevo

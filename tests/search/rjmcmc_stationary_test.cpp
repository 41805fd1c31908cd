// Detailed balance of the RJMCMC kernel, checked through its stationary distribution: on a
// 3-gene grammar with discrete parameters (21 derivations) and a made-up fitness, the visit
// frequencies of long runs must match prior(x) exp(f(x)/T) exactly (up to sampling noise), with
// jumps, diffusions, non-terminal selection weights, delayed rejection, parallel tempering (each
// chain at its own temperature) and the gene limit (truncated target).
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>

#include "function_scorer.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"
#include "search/rjmcmc.hpp"

namespace shapevo {
namespace {

const char* kChain = R"(
start A
rule A { param a = choice(0, 1, 2) box child B prob 0.5 }
rule B { param b = choice(0, 1) box child C prob 0.3 }
rule C { param c = choice(0, 1) box }
)";

struct Derivation {
    int a = 0, b = -1, c = -1;  ///< -1: gene absent
    int index() const { return b < 0 ? a : c < 0 ? 3 + a * 2 + b : 9 + a * 4 + b * 2 + c; }
};
constexpr int kStates = 21;

Derivation decode(const Grammar& g, const Chromosome& x) {
    Derivation d;
    d.a = int(x.param(0, g.rules[0], 0));
    if (x.child(0, 0) > 0) {
        const std::uint32_t b = std::uint32_t(x.child(0, 0));
        d.b = int(x.param(b, g.rules[1], 0));
        if (x.child(b, 0) > 0) d.c = int(x.param(b + std::uint32_t(x.child(b, 0)), g.rules[2], 0));
    }
    return d;
}

/// Not additive over genes: with an additive fitness, re-drawing a kept gene could never rescue
/// a rejected jump, and delayed rejection's second stage would always be refused.
double fitnessOf(const Derivation& d) {
    return 0.4 * d.a + (d.b >= 0 ? 0.3 - 0.5 * d.b : 0) + (d.c >= 0 ? (d.c == d.b ? 0.6 : -0.6) + 0.3 * d.a * d.c - 0.2 : 0);
}

/// prior(x) exp(f(x)/T), normalised over the derivations with at most maxGenes genes.
std::vector<double> exactTarget(double t, std::uint32_t maxGenes) {
    std::vector<double> p(kStates, 0.0);
    for (int a = 0; a < 3; ++a)
        for (int b = -1; b < 2; ++b)
            for (int c = -1; c < 2; ++c) {
                if (b < 0 && c >= 0) continue;
                const Derivation d{a, b, c};
                const std::uint32_t genes = 1 + (b >= 0) + (c >= 0);
                if (genes > maxGenes) continue;
                double prior = 1.0 / 3 * (b < 0 ? 0.5 : 0.5 * 0.5 * (c < 0 ? 0.7 : 0.3 * 0.5));
                p[std::size_t(d.index())] = prior * std::exp(fitnessOf(d) / t);
            }
    double sum = 0;
    for (double v : p) sum += v;
    for (double& v : p) v /= sum;
    return p;
}

struct Case {
    const char* name;
    std::uint32_t chains = 1;
    double ratio = 1.0;
    double depthBias = 1.0;
    bool delayedRejection = false;
    std::uint32_t maxGenes = 3;
    double temperature = 0.3;
    double jumpProbability = 0.5;
};

void PrintTo(const Case& k, std::ostream* os) { *os << k.name; }

class RjmcmcStationary : public ::testing::TestWithParam<Case> {};

TEST_P(RjmcmcStationary, VisitFrequenciesMatchTheTemperedPosterior) {
    const Case k = GetParam();
    const Grammar g = parseGrammar(kChain, "chain.grammar");
    test::FunctionScorer scorer(g, [&](const Chromosome& x) { return fitnessOf(decode(g, x)); });
    Evaluator evaluator(scorer, 1);
    RjmcmcSettings s;
    s.temperature = k.temperature;
    s.jumpProbability = k.jumpProbability;
    s.temperatureRatio = k.ratio;
    s.annealing = 1.0;
    s.depthBias = k.depthBias;
    s.delayedRejection = k.delayedRejection;
    PopulationSettings chains;
    chains.population = k.chains;
    chains.initialGenesMin = 1;
    chains.initialGenesMax = 3;
    const GenomeLimits limits{k.maxGenes};
    Rjmcmc mcmc(g, s, chains, limits, 2024);
    mcmc.initialize(evaluator);
    for (int i = 0; i < 1000; ++i) mcmc.step(evaluator);
    const int sweeps = 600000;
    std::vector<std::vector<double>> visits(k.chains, std::vector<double>(kStates, 0.0));
    for (int i = 0; i < sweeps; ++i) {
        mcmc.step(evaluator);
        for (std::uint32_t c = 0; c < k.chains; ++c) {
            const Chromosome& x = mcmc.population().individuals[c];
            ASSERT_DOUBLE_EQ(mcmc.population().fitness[c], fitnessOf(decode(g, x)));
            visits[c][std::size_t(decode(g, x).index())] += 1;
        }
        if (i % 5000 == 0) {
            for (const Chromosome& x : mcmc.population().individuals) ASSERT_EQ(validateChromosome(g, x, limits), "");
        }
    }
    for (std::uint32_t c = 0; c < k.chains; ++c) {
        const std::vector<double> exact = exactTarget(mcmc.temperature(c), k.maxGenes);
        double tv = 0;
        for (int i = 0; i < kStates; ++i) tv += std::abs(visits[c][std::size_t(i)] / sweeps - exact[std::size_t(i)]) / 2;
        EXPECT_LT(tv, 0.008) << k.name << " chain " << c << " at T = " << mcmc.temperature(c);
    }
    const auto& n = mcmc.counters();
    EXPECT_GT(n.jumpsAccepted, 1000u);
    EXPECT_GT(n.diffusionsAccepted, 1000u);
    if (k.delayedRejection) {
        EXPECT_GT(n.secondStagesAccepted, 1000u) << n.secondStages;
    }
    if (k.chains > 1) {
        EXPECT_GT(n.swapsAccepted, 100u);
    }
}

INSTANTIATE_TEST_SUITE_P(Kernels, RjmcmcStationary,
                         ::testing::Values(Case{"plain"}, Case{"depth_bias", 1, 1.0, 0.5},
                                           Case{"delayed_rejection", 1, 1.0, 1.0, true, 3, 0.3, 0.9}, Case{"jump_heavy", 1, 1.0, 1.0, false, 3, 0.3, 0.9},
                                           Case{"tempering", 2, 3.0, 1.0, true}, Case{"gene_limit", 1, 1.0, 1.0, false, 2}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace shapevo

// Smc: the SMC and SOSMC baselines of ShapeGenetics §7 (after Ritchie et al. 2015).
//
// Choices (see docs/search-methods.md for the reasoning):
// - Particles start empty. Each generation every particle grows by one geometric object
//   (genome/sequential_growth.hpp): undecided child positions are decided in chromosome order
//   (SMC) or in uniformly random order (SOSMC, GrowthOrder::Random), each expressed with its
//   slot's grammar probability or marked kRefused; refused positions are never grown again.
// - Weights follow the papers' likelihood, not the original code's raw-fitness roulette: the
//   target after each step is prior * exp(f / T), particles are proposed from the prior, so the
//   incremental weight is exp((f_new - f_old) / T) with f_old = the particle's fitness before this
//   generation's growth (its population fitness). Generation 1 grows from the empty chromosome,
//   whose fitness is the same for all, so its weights are exp(f / T).
// - Multinomial resampling after every step (the ShapeGenetics configs' "roulette wheel
//   resampling"); no rejuvenation moves (none in either paper's description).
// - Only particles that grew are re-evaluated; a generation in which no particle can grow does
//   nothing but count (all particles are complete derivations).
// - State = population + fitness + RNG + counters, so checkpoints resume exactly.
#pragma once
#include <vector>

#include "genome/sequential_growth.hpp"
#include "search/evaluation_batch.hpp"
#include "search/resampling.hpp"
#include "search/search_method.hpp"

namespace shapevo {

class Smc final : public SearchMethod {
public:
    Smc(const Grammar& g, const SmcSettings& settings, std::uint32_t population, const GenomeLimits& limits,
        GrowthOrder order, std::uint64_t seed);

    void initialize(Evaluator& evaluator) override;
    void step(Evaluator& evaluator) override;

private:
    void restored() override;
    /// Grow every particle, evaluate those that grew, resample by exp((f - before) / T).
    void growAndResample(Evaluator& evaluator, bool fromEmpty);

    const Grammar& grammar_;
    SmcSettings settings_;
    GenomeLimits limits_;
    GrowthOrder order_;
    std::vector<char> geometric_;
    Population next_;
    std::vector<double> logWeights_;
    std::vector<std::size_t> grown_, picks_;
    EvaluationBatch batch_;
    MultinomialResampler resampler_;
};

}  // namespace shapevo

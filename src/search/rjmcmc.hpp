// Rjmcmc: the RJMCMC baseline of ShapeGenetics §7 (after Talton et al. 2011), one Markov chain
// per individual, all chains advanced together in one "sweep" per generation.
//
// Choices (reasoning and derivations in docs/search-methods.md):
// - Target of chain i: prior(x) * exp(f(x) / T_i). Proposals come from the prior, so only
//   fitness differences and the jump's selection weights enter the acceptance rules
//   (search/mcmc_acceptance.hpp).
// - Each sweep, chain i proposes a jump with probability jump_probability (the configs'
//   basic_prob 50 %), else a diffusion: `diffusion_alters` alter mutations (one gene's parameters
//   redrawn from their prior each). A jump picks a non-terminal gene v with weight
//   depth_bias^depth(v) (non-terminal selection: terminals cannot change structure), cuts below
//   it and regrows v's children with the grammar's probabilities, reusing the cut genes' values
//   where they fit (genome/regrow.hpp). A proposal past genome.max_genes is rejected unevaluated.
// - All proposals of a sweep are evaluated in one batch; then accept/reject in chain order.
// - Delayed rejection (off by default: ShapeGenetics §8 lists only tempering, non-terminal
//   selection and annealing): a rejected jump gets a second stage, y2 = the rejected proposal
//   with one reused gene re-drawn ("adjust before being rejected"); y2 and the reverse path's
//   intermediate y1* are evaluated as a second batch.
// - Parallel tempering: chain i has T_i = T0 * ratio^(i/(n-1)) (ratio 12.9: a move accepted 70 %
//   of the time in the hottest chain is accepted 1 % in the coldest, ShapeGenetics §8). After
//   each sweep, neighbours (i, i+1) with i even (odd on odd generations) swap states with the
//   standard probability. Annealing divides every T by `annealing` each `annealing_interval`
//   generations. Temperatures are a function of (chain index, generation), and a chain's state
//   is its population slot, so checkpoints resume exactly.
#pragma once
#include <vector>

#include "genome/families/tree_family.hpp"
#include "genome/regrow.hpp"
#include "search/evaluation_batch.hpp"
#include "search/population_settings.hpp"
#include "search/search_method.hpp"

namespace shapevo {

class Rjmcmc final : public SearchMethod {
public:
    /// One chain per individual of `population` (its size and initial lengths; RJMCMC uses none of
    /// the GA's operators). It needs a tree's structure: `g` is the family's treeGrammar().
    Rjmcmc(const Grammar& g, const RjmcmcSettings& settings, const PopulationSettings& population,
           const GenomeLimits& limits, std::uint64_t seed);

    /// Generation 1: chains start at grown random derivations (like the GA's first population).
    void initialize(Evaluator& evaluator) override;
    /// One sweep: a proposal per chain, batch evaluation, accept/reject, tempering swaps.
    void step(Evaluator& evaluator) override;

    /// Temperature of chain `i` during the next sweep.
    double temperature(std::size_t i) const;

    /// Counts since construction, for tests and diagnostics.
    struct Counters {
        std::uint64_t diffusions = 0, diffusionsAccepted = 0, jumps = 0, jumpsAccepted = 0;
        std::uint64_t secondStages = 0, secondStagesAccepted = 0, swaps = 0, swapsAccepted = 0;
    };
    const Counters& counters() const { return counters_; }

private:
    void restored() override;
    enum class Move : std::uint8_t { None, Diffusion, Jump };
    struct Proposal {
        Move move = Move::None;
        double weightBefore = 0, weightAfter = 0;  ///< jump selection totals W(x), W(y)
        double fitness = 0;                        ///< f(y1) once evaluated
        std::size_t slot = 0;                      ///< index in the evaluation batch
    };
    void resize(std::size_t n);
    /// Build chain i's proposal into proposals_[i]; Move::None if there is none.
    void propose(std::size_t i);
    void secondStage(Evaluator& evaluator);

    const Grammar& grammar_;
    RjmcmcSettings settings_;
    PopulationSettings population_;
    GenomeLimits limits_;
    TreeOperators growth_;  ///< the initial chains' random growth
    std::vector<Chromosome> proposals_, second_, star_;
    std::vector<Proposal> info_;
    std::vector<std::vector<MatchedGene>> matched_;
    std::vector<double> temperature_;
    std::vector<std::size_t> delayed_;
    RegrowScratch regrow_;
    EvaluationBatch batch_;
    Counters counters_;
};

}  // namespace shapevo

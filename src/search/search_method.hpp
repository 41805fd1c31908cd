// SearchMethod: what the island loop needs from a search method (ShapeGenetics §7: GA, SMC,
// SOSMC and RJMCMC in one framework). Every method's whole state is its population with fitness,
// its Rng, the generation number and the evaluation count, so a checkpoint of those resumes any
// method exactly; this base class holds them, each method only its own scratch buffers. Fitness is only ever computed through the Evaluator (thread count never changes
// results); all randomness comes from rng() in a fixed order.
#pragma once
#include <array>
#include <cstdint>
#include <memory>

#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"
#include "genome/random.hpp"
#include "search/search_settings.hpp"
#include "search/evaluator.hpp"
#include "search/generation_stats.hpp"
#include "search/operator_outcomes.hpp"
#include "search/population.hpp"

namespace shapevo {

class SearchMethod {
public:
    explicit SearchMethod(std::uint64_t seed) : rng_(seed) {}
    virtual ~SearchMethod() = default;
    /// Generation 1: create and evaluate the first population.
    virtual void initialize(Evaluator& evaluator) = 0;
    /// One population-wide step (about one evaluation per individual).
    virtual void step(Evaluator& evaluator) = 0;
    /// Continue from a saved state (a checkpoint): population with fitness, RNG, counters.
    void restore(const Population& pop, const std::array<std::uint64_t, 4>& rng, std::uint32_t generation,
                 std::uint64_t evaluations) {
        pop_ = pop;
        rng_.setState(rng);
        generation_ = generation;
        evaluations_ = evaluations;
        restored();
    }
    const Population& population() const { return pop_; }
    /// Migration replaces individuals in place, with their fitness; methods read fitness from here.
    Population& population() { return pop_; }
    std::uint32_t generation() const { return generation_; }
    std::uint64_t evaluations() const { return evaluations_; }
    /// best, mean, std of the current population (seconds filled by the caller).
    GenerationStats stats() const { return populationStats(pop_, generation_, evaluations_); }
    Rng& rng() { return rng_; }
    /// Where this method's children land against their parents (null: it does not breed
    /// children from parents, e.g. SMC, RJMCMC).
    virtual const OperatorOutcomes* operatorOutcomes() const { return nullptr; }
    /// How many leading slots of the population migrants from other ranks may replace (the
    /// hybrid keeps its scout island, the last slots, to itself); all by default.
    virtual std::size_t migrantSlots() const { return pop_.size(); }

protected:
    /// After restore(): fit the method's own buffers to the restored population.
    virtual void restored() {}
    /// Generation 1 from random genomes: every individual made by ops.randomGenome (the tree
    /// family: grown to a length drawn from [minGenes, maxGenes]), in slot order, then all evaluated.
    void startFromRandomGrowth(GenomeOperators& ops, std::uint32_t minGenes, std::uint32_t maxGenes,
                               Evaluator& evaluator);

    Rng rng_;
    Population pop_;
    std::uint32_t generation_ = 0;
    std::uint64_t evaluations_ = 0;
};

}  // namespace shapevo

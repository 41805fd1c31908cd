// GeneticAlgorithm implementation; buffers are reused between generations (no allocation once
// every chromosome has reached its largest size).
#include "search/genetic_algorithm.hpp"

#include <algorithm>

#include "search/pair_breeding.hpp"

namespace shapevo {

GeneticAlgorithm::GeneticAlgorithm(const GenomeFamily& family, const PopulationSettings& population,
                                   const GaSettings& settings, const GenomeLimits& limits, std::uint64_t seed)
    : SearchMethod(seed), ops_(family.makeOperators(limits)), population_(population), settings_(settings) {
    pop_.individuals.resize(population.population);
    next_.individuals.resize(population.population);
    next_.fitness.resize(population.population);
    order_.resize(population.population);
    childOp_.resize(population.population + 1);
    parentFitness_.resize(population.population + 1);
    picked_.resize(population.population);
}

void GeneticAlgorithm::initialize(Evaluator& evaluator) {
    startFromRandomGrowth(*ops_, population_.initialGenesMin, population_.initialGenesMax, evaluator);
}

void GeneticAlgorithm::step(Evaluator& evaluator) {
    const std::size_t n = pop_.size(), elite = settings_.elitism;
    for (std::size_t i = 0; i < n; ++i) order_[i] = i;
    // best first, ties by index: a total order, so std::sort is deterministic and allocates nothing
    std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
        return pop_.fitness[a] > pop_.fitness[b] || (pop_.fitness[a] == pop_.fitness[b] && a < b);
    });
    for (std::size_t k = 0; k < elite; ++k) {
        next_.individuals[k] = pop_.individuals[order_[k]];
        next_.fitness[k] = pop_.fitness[order_[k]];
    }
    wheel_.prepare(pop_.fitness);
    std::fill(picked_.begin(), picked_.end(), 0);
    for (std::size_t k = elite; k < n; k += 2) {
        const std::size_t p1 = tournamentSelect(pop_.fitness, settings_.tournament, rng_);
        const std::size_t p2 = wheel_.select(rng_);
        picked_[p1] = picked_[p2] = 1;
        Chromosome& c1 = next_.individuals[k];
        const bool pair = k + 1 < n;
        Chromosome& c2 = pair ? next_.individuals[k + 1] : scratchChild_;
        const BredPair b = breedPair(*ops_, pop_, p1, p2, c1, c2, pair, settings_.mutation, settings_.crossoverRetries, rng_,
                                     [&](Chromosome& c) { return mutateByWeight(*ops_, c, rng_, settings_); });
        childOp_[k] = b.op1;
        childOp_[k + 1] = b.op2;
        parentFitness_[k] = b.parent1;
        parentFitness_[k + 1] = b.parent2;
    }
    outcomes_.parentsPicked += 2 * ((n - elite + 1) / 2);
    for (std::uint8_t p : picked_) outcomes_.distinctParents += p;
    std::swap(pop_, next_);
    evaluator.evaluate(pop_, elite);
    for (std::size_t k = elite; k < n; ++k) outcomes_.count(childOp_[k], pop_.fitness[k], parentFitness_[k]);
    evaluations_ += n - elite;
    ++generation_;
}

}  // namespace shapevo

// RandomSampling (random_sampling.hpp): draw, score, keep the best.
#include "search/random_sampling.hpp"

#include <algorithm>

namespace shapevo {

RandomSampling::RandomSampling(const GenomeFamily& family, const PopulationSettings& population, const GenomeLimits& limits,
                               std::uint64_t seed)
    : SearchMethod(seed), ops_(family.makeOperators(limits)), population_(population) {
    pop_.individuals.resize(population.population);
    next_.individuals.resize(population.population);
    order_.resize(2 * std::size_t(population.population));
}

void RandomSampling::initialize(Evaluator& evaluator) {
    startFromRandomGrowth(*ops_, population_.initialGenesMin, population_.initialGenesMax, evaluator);
}

void RandomSampling::step(Evaluator& evaluator) {
    const std::size_t n = pop_.size();
    next_.individuals.resize(n);
    for (Chromosome& c : next_.individuals) ops_->randomGenome(c, rng_, population_.initialGenesMin, population_.initialGenesMax);
    evaluator.evaluate(next_);
    evaluations_ += n;
    // the n best of old (indices [0, n)) and new ([n, 2n)), best first, ties by index
    order_.resize(2 * n);
    for (std::size_t i = 0; i < 2 * n; ++i) order_[i] = i;
    auto fitness = [&](std::size_t i) { return i < n ? pop_.fitness[i] : next_.fitness[i - n]; };
    std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
        return fitness(a) > fitness(b) || (fitness(a) == fitness(b) && a < b);
    });
    merged_.individuals.resize(n);
    merged_.fitness.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = order_[k];
        merged_.fitness[k] = fitness(i);
        std::swap(merged_.individuals[k], i < n ? pop_.individuals[i] : next_.individuals[i - n]);
    }
    std::swap(pop_, merged_);
    ++generation_;
}

}  // namespace shapevo

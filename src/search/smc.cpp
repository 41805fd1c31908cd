// Smc: grow one geometric object per particle, evaluate the grown ones in one batch, resample.
#include "search/smc.hpp"

namespace shapevo {

Smc::Smc(const Grammar& g, const SmcSettings& settings, std::uint32_t population, const GenomeLimits& limits,
         GrowthOrder order, std::uint64_t seed)
    : SearchMethod(seed), grammar_(g), settings_(settings), limits_(limits), order_(order), geometric_(geometricRules(g)) {
    pop_.individuals.resize(population);
    pop_.fitness.assign(population, 0.0);
    next_.individuals.resize(population);
    next_.fitness.assign(population, 0.0);
}

void Smc::initialize(Evaluator& evaluator) {
    for (Chromosome& c : pop_.individuals) c.clear();
    growAndResample(evaluator, true);
    generation_ = 1;
}

void Smc::step(Evaluator& evaluator) {
    growAndResample(evaluator, false);
    ++generation_;
}

void Smc::restored() {
    next_.individuals.resize(pop_.size());
    next_.fitness.resize(pop_.size());
}

void Smc::growAndResample(Evaluator& evaluator, bool fromEmpty) {
    const std::size_t n = pop_.size();
    pop_.fitness.resize(n, 0.0);
    batch_.clear();
    grown_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        if (growNextObject(grammar_, pop_.individuals[i], rng_, limits_, order_, geometric_)) {
            batch_.add(pop_.individuals[i]);
            grown_.push_back(i);
        }
    }
    if (grown_.empty()) return;  // every particle is complete: nothing changes
    evaluations_ += batch_.evaluate(evaluator);
    logWeights_.assign(n, 0.0);  // particles that did not grow keep their fitness: weight exp(0)
    for (std::size_t k = 0; k < grown_.size(); ++k) {
        const std::size_t i = grown_[k];
        const double before = fromEmpty ? 0.0 : pop_.fitness[i];
        pop_.fitness[i] = batch_.fitness(k);
        logWeights_[i] = (pop_.fitness[i] - before) / settings_.temperature;
    }
    resampler_.resample(logWeights_, rng_, picks_);
    for (std::size_t k = 0; k < n; ++k) {
        next_.individuals[k] = pop_.individuals[picks_[k]];  // copy-assign reuses k's buffer
        next_.fitness[k] = pop_.fitness[picks_[k]];
    }
    std::swap(pop_, next_);
}

}  // namespace shapevo

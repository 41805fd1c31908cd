// EvaluationBatch: evaluate chosen chromosomes (of any populations) in one Evaluator call.
// They are swapped into a contiguous Population (vector swaps: no copy, no allocation once warm),
// evaluated in parallel, and swapped back; fitness(k) is the k-th added one's fitness.
#pragma once
#include <vector>

#include "search/evaluator.hpp"
#include "search/population.hpp"

namespace shapevo {

class EvaluationBatch {
public:
    void clear() { members_.clear(); }
    /// Add a chromosome; returns its index in the batch. It must stay alive until evaluate().
    std::size_t add(Chromosome& c) {
        members_.push_back(&c);
        return members_.size() - 1;
    }
    std::size_t size() const { return members_.size(); }
    /// Evaluate every added chromosome; returns how many were evaluated.
    std::size_t evaluate(Evaluator& evaluator) {
        const std::size_t n = members_.size();
        pop_.individuals.resize(n);  // empty placeholders: the members' buffers are swapped in
        for (std::size_t k = 0; k < n; ++k) std::swap(pop_.individuals[k], *members_[k]);
        evaluator.evaluate(pop_);
        for (std::size_t k = 0; k < n; ++k) std::swap(pop_.individuals[k], *members_[k]);
        return n;
    }
    double fitness(std::size_t k) const { return pop_.fitness[k]; }

private:
    std::vector<Chromosome*> members_;
    Population pop_;
};

}  // namespace shapevo

// Breeding as ShapeGenetics Algorithm 1 does it, shared by the GA and the hybrid search so both
// draw from the Rng in the same order. breedPair: one pair of children from two parents — with
// probability `mutation` copies of the parents, each mutated by `mutate`, otherwise a crossover
// (Algorithm 2, with retries). mutateByWeight: one of grow, cut and alter picked by [ga]'s weights.
// Both apply the model family's operators (genome/genome_family.hpp), so they breed any family.
#pragma once
#include <algorithm>

#include "genome/genome_family.hpp"
#include "search/operator_outcomes.hpp"
#include "search/population.hpp"
#include "search/search_settings.hpp"

namespace shapevo {

/// Grow, cut or alter `c`, picked by ga's weights (one uniform draw); if the pick cannot apply
/// (nothing to cut, chromosome full) the next one in that order is tried. Returns the operator
/// applied, Copy if none could.
inline OperatorOutcomes::Op mutateByWeight(GenomeOperators& ops, Chromosome& c, Rng& rng, const GaSettings& ga) {
    const double r = rng.uniform() * (ga.growWeight + ga.cutWeight + ga.alterWeight);
    const int first = r < ga.growWeight ? 0 : r < ga.growWeight + ga.cutWeight ? 1 : 2;
    for (int k = 0; k < 3; ++k) {
        switch ((first + k) % 3) {
        case 0: if (ga.growWeight > 0 && ops.grow(c, rng)) return OperatorOutcomes::Grow; break;
        case 1: if (ga.cutWeight > 0 && ops.cut(c, rng)) return OperatorOutcomes::Cut; break;
        default: if (ga.alterWeight > 0 && ops.alter(c, rng)) return OperatorOutcomes::Alter; break;
        }
    }
    return OperatorOutcomes::Copy;
}

/// What made each child and the fitness it is compared with (a crossover child: the better parent's).
struct BredPair {
    OperatorOutcomes::Op op1 = OperatorOutcomes::Copy, op2 = OperatorOutcomes::Copy;
    double parent1 = 0, parent2 = 0;
};

/// Children of pop's p1 and p2 into c1 and c2 (c2 is discarded by the caller if !pair, and not
/// mutated). `mutate(Chromosome&)` returns the operator it applied.
template <class Mutate>
BredPair breedPair(GenomeOperators& ops, const Population& pop, std::size_t p1, std::size_t p2, Chromosome& c1,
                   Chromosome& c2, bool pair, double mutation, int crossoverRetries, Rng& rng, Mutate&& mutate) {
    BredPair b;
    if (rng.uniform() < mutation) {
        c1 = pop.individuals[p1];
        c2 = pop.individuals[p2];
        b.op1 = mutate(c1);
        b.op2 = pair ? mutate(c2) : OperatorOutcomes::Copy;
        b.parent1 = pop.fitness[p1];
        b.parent2 = pop.fitness[p2];
    } else {
        const bool crossed = ops.crossover(pop.individuals[p1], pop.individuals[p2], c1, c2, rng, crossoverRetries);
        b.op1 = b.op2 = crossed ? OperatorOutcomes::Crossover : OperatorOutcomes::Copy;
        b.parent1 = b.parent2 = std::max(pop.fitness[p1], pop.fitness[p2]);
    }
    return b;
}

}  // namespace shapevo

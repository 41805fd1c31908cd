// TreeFamily and TreeOperators: each member one call of the free function it stands for.
#include "genome/families/tree_family.hpp"

#include "genome/nudge.hpp"
#include "genome/operators.hpp"
#include "genome/validate.hpp"

namespace shapevo {

namespace {
constexpr double kUniformDepth = 1.0;  ///< regrow picks every non-terminal gene alike
}

void TreeOperators::randomGenome(Chromosome& c, Rng& rng, std::uint32_t minGenes, std::uint32_t maxGenes) {
    growRandomLength(grammar_, c, rng, limits_, minGenes, maxGenes);
}

bool TreeOperators::grow(Chromosome& c, Rng& rng) { return shapevo::grow(grammar_, c, rng, limits_); }

bool TreeOperators::cut(Chromosome& c, Rng& rng) { return shapevo::cut(grammar_, c, rng, scratch_); }

bool TreeOperators::alter(Chromosome& c, Rng& rng) { return shapevo::alter(grammar_, c, rng); }

bool TreeOperators::nudge(Chromosome& c, Rng& rng) { return shapevo::nudge(grammar_, c, rng); }

bool TreeOperators::crossover(const Chromosome& a, const Chromosome& b, Chromosome& childA, Chromosome& childB,
                              Rng& rng, int retries) {
    return shapevo::crossover(grammar_, a, b, childA, childB, rng, limits_, retries, scratch_);
}

bool TreeOperators::regrow(const Chromosome& x, Chromosome& y, Rng& rng) {
    const double total = jumpWeightTotal(grammar_, x, kUniformDepth, regrow_);
    if (total <= 0) return false;  // no gene with child slots: nothing drawn
    return regrowBelow(grammar_, x, pickJumpGene(grammar_, x, total, rng, regrow_), y, rng, limits_, regrow_);
}

std::string TreeFamily::check(const Chromosome& c, const GenomeLimits& limits) const {
    return validateChromosome(grammar_, c, limits);
}

}  // namespace shapevo

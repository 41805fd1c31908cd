// Models for the incremental-evaluation and derive tests: a root alone (rootOnly), and a stream
// of models the way a GA makes them: children of the last few models by grow, cut, alter and
// crossover (and, if asked, exact duplicates).
#pragma once
#include <cstdint>
#include <vector>

#include "genome/operators.hpp"

namespace shapevo::test {

/// A root gene of the grammar's start rule with every optional child slot left empty, its
/// parameters drawn from the prior with `seed`.
inline Chromosome rootOnly(const Grammar& g, std::uint64_t seed = 1) {
    Rng rng(seed);
    Chromosome c;
    plantRoot(g, c, rng);
    return c;
}

/// Append children to `models` until it holds `count`: each one made from one of the last
/// `recent` models by a random operator (crossover with any earlier model); with `duplicates`,
/// one in five is an unchanged copy.
inline void appendChildren(const Grammar& g, std::vector<Chromosome>& models, std::size_t count, Rng& rng,
                           const GenomeLimits& limits, std::uint32_t recent, bool duplicates) {
    GenomeScratch scratch;
    while (models.size() < count) {
        Chromosome child = models[models.size() - 1 - rng.below(recent)];
        const std::uint32_t pick = rng.below(duplicates ? 5 : 4);
        if (!(duplicates && pick == 3)) {
            switch (pick) {
            case 0: grow(g, child, rng, limits); break;
            case 1: cut(g, child, rng, scratch); break;
            case 2: alter(g, child, rng); break;
            default: {
                const Chromosome a = child, b = models[rng.below(std::uint32_t(models.size()))];
                Chromosome childB;
                crossover(g, a, b, child, childB, rng, limits, 5, scratch);
            }
            }
        }
        models.push_back(child);
    }
}

}  // namespace shapevo::test

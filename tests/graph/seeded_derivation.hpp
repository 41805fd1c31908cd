// deriveSeeded: the graph grammar tests' one way to derive — host graph 0, a seeded DrawSource,
// a step limit (0: the file's own) and otherwise the given limits.
#pragma once
#include <cstdint>

#include "graph/derive.hpp"

namespace shapevo::graph::test_support {

inline DeriveResult deriveSeeded(const GraphGrammar& g, std::uint64_t seed, std::int64_t steps = 0, DeriveLimits limits = {}) {
    SeededDraws draws(seed);
    limits.maxSteps = steps;
    return deriveGraph(g, 0, draws, limits);
}

}  // namespace shapevo::graph::test_support

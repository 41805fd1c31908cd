// breadthFirstTree: the benchmarks' large tree chromosomes. Every gene, in breadth-first order,
// gets all of its children until the chromosome holds `genes` genes; child `entry` is a gene of
// rule branch[entry % branch.size()]; parameters come from the priors with a fixed seed (2024).
#pragma once
#include <cstdint>
#include <deque>
#include <vector>

#include "genome/operators.hpp"

namespace shapevo::bench {

inline Chromosome breadthFirstTree(const Grammar& g, std::uint32_t genes, const std::vector<std::uint16_t>& branch) {
    Rng rng(2024);
    Chromosome c;
    plantRoot(g, c, rng);
    std::deque<std::uint32_t> open{0};
    while (c.genes < genes && !open.empty()) {
        const std::uint32_t parent = open.front();
        open.pop_front();
        const Rule& r = g.rules[c.rule(parent)];
        for (std::uint32_t entry = 0; entry < r.childOffsets && c.genes < genes; ++entry)
            open.push_back(appendGene(g, c, branch[entry % branch.size()], parent, entry, rng));
    }
    return c;
}

}  // namespace shapevo::bench

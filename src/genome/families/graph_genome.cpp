// Graph genome words (graph_genome.hpp).
#include "genome/families/graph_genome.hpp"

namespace shapevo {

using graph::kOverrideWords;

void makeGraphGenome(Chromosome& c, std::uint64_t seed) {
    c.words.assign({kGraphGenomeTag, std::uint32_t(seed), std::uint32_t(seed >> 32)});
    c.genes = 1;
    c.lineage = {};
}

std::string checkGraphGenome(const Chromosome& c, std::uint32_t maxGenes) {
    if (c.words.size() < kGraphGenomeHeader || c.words[0] != kGraphGenomeTag)
        return "not a graph-derivation genome (its first word is not the tag GRG1)";
    if ((c.words.size() - kGraphGenomeHeader) % kOverrideWords != 0)
        return "a graph-derivation genome of " + std::to_string(c.words.size()) + " words (3 + 4 per override expected)";
    const std::size_t n = graphOverrideCount(c);
    if (c.genes != n + 1)
        return "genes = " + std::to_string(c.genes) + " but the words hold " + std::to_string(n) + " overrides (genes = overrides + 1)";
    if (c.genes > maxGenes) return std::to_string(c.genes) + " genes, more than genome.max_genes = " + std::to_string(maxGenes);
    const auto o = graphOverrides(c);
    for (std::size_t i = 1; i < n; ++i)
        if (graph::overrideKey(o, i - 1) >= graph::overrideKey(o, i))
            return "override " + std::to_string(i) + "'s key is not above the one before (keys must ascend)";
    return {};
}

void setGraphOverride(Chromosome& c, std::uint64_t key, std::uint64_t word) {
    const auto o = graphOverrides(c);
    std::size_t lo = 0, hi = graphOverrideCount(c);
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (graph::overrideKey(o, mid) < key) lo = mid + 1;
        else hi = mid;
    }
    const std::size_t at = kGraphGenomeHeader + kOverrideWords * lo;
    const std::uint32_t w[kOverrideWords] = {std::uint32_t(key), std::uint32_t(key >> 32), std::uint32_t(word), std::uint32_t(word >> 32)};
    if (lo < graphOverrideCount(c) && graph::overrideKey(o, lo) == key) {
        c.words[at + 2] = w[2];
        c.words[at + 3] = w[3];
    } else {
        c.words.insert(c.words.begin() + std::ptrdiff_t(at), w, w + kOverrideWords);
        ++c.genes;
    }
    c.lineage = {};
}

void removeGraphOverride(Chromosome& c, std::size_t i) {
    const std::size_t at = kGraphGenomeHeader + kOverrideWords * i;
    c.words.erase(c.words.begin() + std::ptrdiff_t(at), c.words.begin() + std::ptrdiff_t(at + kOverrideWords));
    --c.genes;
    c.lineage = {};
}

}  // namespace shapevo

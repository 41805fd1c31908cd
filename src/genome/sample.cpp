// Uncontrolled derivations: breadth first from the root, each position decided once with its
// slot's probability; rejection for the size window.
#include "genome/sample.hpp"

#include "genome/operators.hpp"

namespace shapevo {

bool growUncontrolled(const Grammar& g, Chromosome& c, Rng& rng, std::uint32_t maxGenes) {
    c.clear();
    if (maxGenes == 0) return false;
    appendGene(g, c, g.start, 0, 0, rng);
    // Children are appended, so walking the buffer forward visits every gene once, parents first.
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        for (const Slot& s : g.rules[c.rule(pos)].slots) {
            for (std::uint32_t k = 0; k < s.maxCount; ++k) {
                if (s.probability <= 0) continue;
                if (!s.mandatory() && !(rng.uniform() < s.probability)) continue;
                if (c.genes >= maxGenes) return false;
                appendGene(g, c, pickAlternative(s, rng), pos, s.firstChild + k, rng);
            }
        }
    }
    return true;
}

SampleOutcome sampleDerivation(const Grammar& g, Chromosome& c, Rng& rng, std::uint32_t minGenes,
                               std::uint32_t maxGenes, std::uint32_t maxAttempts) {
    SampleOutcome out;
    while (out.attempts < maxAttempts) {
        ++out.attempts;
        if (growUncontrolled(g, c, rng, maxGenes) && c.genes >= minGenes) {
            out.found = true;
            return out;
        }
    }
    c.clear();
    return out;
}

}  // namespace shapevo

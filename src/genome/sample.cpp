// Uncontrolled derivations: breadth first from the root, each position decided once with its
// slot's probability; rejection for the size window.
#include "genome/sample.hpp"

#include <algorithm>

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
        if (!growUncontrolled(g, c, rng, maxGenes)) {
            ++out.tooLarge;
        } else if (c.genes >= minGenes) {
            out.found = true;
            return out;
        }
    }
    c.clear();
    return out;
}

bool hasOptionalRecursion(const Grammar& g) {
    std::vector<std::uint8_t> seen(g.rules.size());
    std::vector<std::uint16_t> todo;
    for (std::size_t r = 0; r < g.rules.size(); ++r)
        for (const Slot& s : g.rules[r].slots) {
            if (!s.optional) continue;
            std::fill(seen.begin(), seen.end(), 0);
            todo.assign(s.rules.begin(), s.rules.end());
            while (!todo.empty()) {
                const std::uint16_t x = todo.back();
                todo.pop_back();
                if (x == r) return true;
                if (seen[x]) continue;
                seen[x] = 1;
                for (const Slot& t : g.rules[x].slots) todo.insert(todo.end(), t.rules.begin(), t.rules.end());
            }
        }
    return false;
}

}  // namespace shapevo

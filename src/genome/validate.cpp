// Invariants of a chromosome: gene boundaries, offsets consistent both ways, parents before
// children, each child's rule allowed in its slot, mandatory children present, sibling limits
// (one offset per sibling position), parameters inside their priors' support, length limit.
#include "genome/validate.hpp"

#include <vector>

#include "genome/priors.hpp"

namespace shapevo {

std::string validateChromosome(const Grammar& g, const Chromosome& c, const GenomeLimits& limits) {
    if (c.empty()) return c.words.empty() ? "" : "no genes but " + std::to_string(c.size()) + " words";
    std::vector<char> start(c.size(), 0);
    std::uint32_t genes = 0;
    for (std::uint32_t pos = 0; pos < c.size();) {
        if (c.words[pos] >= g.rules.size()) return "gene at word " + std::to_string(pos) + " has unknown rule id";
        const std::uint32_t w = g.rules[c.rule(pos)].geneWords();
        if (pos + w > c.size()) return "gene at word " + std::to_string(pos) + " runs past the end";
        start[pos] = 1;
        ++genes;
        pos += w;
    }
    if (genes != c.genes) return "gene count " + std::to_string(c.genes) + " but " + std::to_string(genes) + " genes found";
    if (genes > limits.maxGenes) return "longer than the limit of " + std::to_string(limits.maxGenes) + " genes";
    if (c.rule(0) != g.start) return "root gene is not the start rule";
    if (c.parentOffset(0) != 0) return "root gene has a parent";
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        const Rule& r = g.rules[c.rule(pos)];
        const std::string at = "gene at word " + std::to_string(pos) + " (" + r.name + ")";
        if (pos != 0) {
            const std::int64_t parent = std::int64_t(pos) + c.parentOffset(pos);
            if (c.parentOffset(pos) >= 0 || parent < 0 || !start[parent]) return at + ": bad parent offset";
            const Rule& pr = g.rules[c.rule(std::uint32_t(parent))];
            int references = 0;
            for (std::uint32_t e = 0; e < pr.childOffsets; ++e)
                if (c.child(std::uint32_t(parent), e) > 0 &&
                    std::int64_t(parent) + c.child(std::uint32_t(parent), e) == std::int64_t(pos))
                    ++references;
            if (references != 1) return at + ": its parent does not point back to it exactly once";
        }
        for (const Slot& s : r.slots) {
            for (std::uint32_t k = 0; k < s.maxCount; ++k) {
                const std::int32_t off = c.child(pos, s.firstChild + k);
                if (off == kNotExpressed || off == kRefused) {
                    if (s.mandatory()) return at + ": mandatory child missing";
                    continue;
                }
                const std::int64_t child = std::int64_t(pos) + off;
                if (off < 0 || child >= std::int64_t(c.size()) || !start[child])
                    return at + ": child offset does not point to a later gene";
                if (std::int64_t(child) + c.parentOffset(std::uint32_t(child)) != std::int64_t(pos))
                    return at + ": child does not point back to it";
                bool allowed = false;
                for (std::uint16_t a : s.rules) allowed |= a == c.rule(std::uint32_t(child));
                if (!allowed) return at + ": child rule " + g.rules[c.rule(std::uint32_t(child))].name + " not allowed in slot";
            }
        }
        for (const Param& p : r.params)
            for (int k = 0; k < p.dims; ++k)
                if (!inSupport(g, p.prior[k], c.param(pos, r, p.first + k)))
                    return at + ": parameter " + p.name + " outside its prior's support";
    }
    return "";
}

}  // namespace shapevo

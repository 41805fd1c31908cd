// Crossover (ShapeGenetics Algorithm 2): swap subtrees at two connections that are the same
// edge of the generator graph, so both children are valid derivations by construction.
#include "genome/operators.hpp"

namespace shapevo {

namespace {

struct Connection {
    std::uint32_t parent = 0;  ///< position of the parent gene
    std::uint32_t entry = 0;   ///< child offset index inside the parent
    std::uint32_t child = 0;   ///< position of the child gene
    std::uint32_t edge = 0;
};

/// The `pick`-th expressed connection (on `edge`, or any edge if edge == UINT32_MAX); counts them
/// all if pick == UINT32_MAX. Returns the count.
std::uint32_t findConnection(const Grammar& g, const Chromosome& c, std::uint32_t edge, std::uint32_t pick, Connection& out) {
    std::uint32_t n = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        for (const Slot& s : g.rules[c.rule(pos)].slots) {
            if (edge != UINT32_MAX && s.edge != edge) continue;
            for (std::uint32_t k = 0; k < s.maxCount; ++k) {
                const std::int32_t off = c.child(pos, s.firstChild + k);
                if (off <= 0) continue;
                if (n == pick) {
                    out = {pos, s.firstChild + k, pos + std::uint32_t(off), s.edge};
                    return n + 1;
                }
                ++n;
            }
        }
    }
    return n;
}

/// child = parent with the subtree at `at` replaced by `donor`'s subtree at `donorRoot`.
void splice(const Grammar& g, const Chromosome& parent, const Connection& at, const Chromosome& donor,
            std::uint32_t donorRoot, Chromosome& child, GenomeScratch& scratch) {
    child.copyFrom(parent);
    Lineage before = parent.lineage;
    const std::uint32_t newParent = removeSubtree(g, child, at.child, at.parent, scratch);
    const std::uint32_t root = child.size();  // where the donor's subtree goes
    appendSubtree(g, child, newParent, at.entry, donor, donorRoot, scratch);
    child.noteChange(std::move(before), root, at.child);  // the parent gene keeps a child there: nothing else changes
}

}  // namespace

bool crossover(const Grammar& g, const Chromosome& a, const Chromosome& b, Chromosome& childA, Chromosome& childB,
               Rng& rng, const GenomeLimits& limits, int retries, GenomeScratch& scratch) {
    Connection ca, cb;
    const std::uint32_t na = findConnection(g, a, UINT32_MAX, UINT32_MAX, ca);
    for (int attempt = 0; attempt < retries && na > 0; ++attempt) {
        findConnection(g, a, UINT32_MAX, rng.below(na), ca);
        const std::uint32_t nb = findConnection(g, b, ca.edge, UINT32_MAX, cb);
        if (nb == 0) continue;
        findConnection(g, b, ca.edge, rng.below(nb), cb);
        splice(g, a, ca, b, cb.child, childA, scratch);
        splice(g, b, cb, a, ca.child, childB, scratch);
        if (childA.genes <= limits.maxGenes && childB.genes <= limits.maxGenes) return true;
    }
    childA.copyFrom(a);
    childB.copyFrom(b);
    return false;
}

}  // namespace shapevo

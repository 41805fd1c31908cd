// Mutations (ShapeGenetics §5): grow, cut and alter, each two sweeps over the chromosome at most.
#include "genome/operators.hpp"

#include <algorithm>

namespace shapevo {

namespace {
/// Whether the rule has a `terminal` block (what it makes depends on whether a gene has children).
bool hasTerminal(const Rule& r) {
    for (const Statement& st : r.statements)
        if (st.kind == StatementKind::TerminalBegin) return true;
    return false;
}
}  // namespace

bool grow(const Grammar& g, Chromosome& c, Rng& rng, const GenomeLimits& limits) {
    if (c.empty()) {
        if (g.mandatoryGenes[g.start] > limits.maxGenes) return false;
        plantRoot(g, c, rng);
        return true;
    }
    // Sweep 1: total weight of every non-expressed child position.
    double total = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords())
        for (const Slot& s : g.rules[c.rule(pos)].slots)
            for (std::uint32_t k = 0; k < s.maxCount; ++k)
                if (c.child(pos, s.firstChild + k) == kNotExpressed) total += s.probability;
    if (total <= 0) return false;
    // Sweep 2: find the chosen one.
    double r = rng.uniform() * total;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        for (const Slot& s : g.rules[c.rule(pos)].slots) {
            for (std::uint32_t k = 0; k < s.maxCount; ++k) {
                if (c.child(pos, s.firstChild + k) != kNotExpressed || s.probability <= 0) continue;
                r -= s.probability;
                if (r >= 0) continue;
                const std::uint16_t rule = pickAlternative(s, rng);
                if (c.genes + g.mandatoryGenes[rule] > limits.maxGenes) return false;
                // A gene with a terminal block and no children yet changes itself; otherwise only
                // the new subtree is new (the genes before it keep their places).
                const bool terminal = hasTerminal(g.rules[c.rule(pos)]) && !c.hasChildren(pos, g.rules[c.rule(pos)]);
                Lineage before = std::move(c.lineage);
                const std::uint32_t added = appendGene(g, c, rule, pos, s.firstChild + k, rng);
                completeMandatory(g, c, added, rng);
                if (terminal) c.noteChange(std::move(before), pos, pos);
                else c.noteChange(std::move(before), added, Lineage::kNone);
                return true;
            }
        }
    }
    return false;  // only reachable through rounding at the very end of the range
}

void growRandomLength(const Grammar& g, Chromosome& c, Rng& rng, const GenomeLimits& limits, std::uint32_t minGenes,
                      std::uint32_t maxGenes) {
    const std::uint32_t lo = std::min(minGenes, limits.maxGenes);
    const std::uint32_t hi = std::max(lo, std::min(maxGenes, limits.maxGenes));
    c.clear();
    const auto length = std::uint32_t(lo + rng.below(hi - lo + 1));
    while (c.genes < length && grow(g, c, rng, limits)) {
    }
}

bool cut(const Grammar& g, Chromosome& c, Rng& rng, GenomeScratch& scratch) {
    double total = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords())
        for (const Slot& s : g.rules[c.rule(pos)].slots)
            for (std::uint32_t k = 0; k < s.maxCount; ++k)
                if (c.child(pos, s.firstChild + k) > 0) total += s.cutWeight();
    if (total <= 0) return false;
    double r = rng.uniform() * total;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        for (const Slot& s : g.rules[c.rule(pos)].slots) {
            if (s.mandatory()) continue;
            for (std::uint32_t k = 0; k < s.maxCount; ++k) {
                const std::int32_t off = c.child(pos, s.firstChild + k);
                if (off <= 0) continue;
                r -= s.cutWeight();
                if (r >= 0) continue;
                const std::uint32_t removed = pos + std::uint32_t(off);
                Lineage before = std::move(c.lineage);
                const std::uint32_t now = removeSubtree(g, c, removed, pos, scratch);
                if (hasTerminal(g.rules[c.rule(now)]) && !c.hasChildren(now, g.rules[c.rule(now)]))
                    c.noteChange(std::move(before), now, pos);
                else
                    c.noteChange(std::move(before), Lineage::kNone, removed);
                return true;
            }
        }
    }
    return false;
}

bool alter(const Grammar& g, Chromosome& c, Rng& rng) {
    std::uint32_t candidates = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords())
        if (g.rules[c.rule(pos)].paramFloats > 0) ++candidates;
    if (candidates == 0) return false;
    std::uint32_t pick = rng.below(candidates);
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        if (g.rules[c.rule(pos)].paramFloats == 0) continue;
        if (pick-- == 0) {
            Lineage before = std::move(c.lineage);
            drawParams(g, c, pos, rng);
            c.noteChange(std::move(before), pos, pos);
            return true;
        }
    }
    return false;
}

}  // namespace shapevo

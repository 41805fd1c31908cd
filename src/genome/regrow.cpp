// Regrow: cut below a gene, regrow its children from the grammar breadth first, then pair old
// and new genes rule by rule in canonical pre-order and copy the paired parameter values.
#include "genome/regrow.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "genome/operators.hpp"

namespace shapevo {

double jumpWeightTotal(const Grammar& g, const Chromosome& c, double depthBias, RegrowScratch& s) {
    s.depthWeight.assign(c.size(), 0.0f);
    double total = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        // parents come first, so the parent's depth weight is known; the root has weight 1
        const float w = pos == 0 ? 1.0f : s.depthWeight[std::uint32_t(std::int32_t(pos) + c.parentOffset(pos))] * float(depthBias);
        s.depthWeight[pos] = w;
        if (!g.rules[c.rule(pos)].slots.empty()) total += w;
    }
    return total;
}

std::uint32_t pickJumpGene(const Grammar& g, const Chromosome& c, double total, Rng& rng, const RegrowScratch& s) {
    double r = rng.uniform() * total;
    std::uint32_t last = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        if (g.rules[c.rule(pos)].slots.empty()) continue;
        last = pos;
        r -= s.depthWeight[pos];
        if (r < 0) return pos;
    }
    return last;  // rounding at the very end of the range
}

void subtreePreorder(const Grammar& g, const Chromosome& c, std::uint32_t root, std::vector<std::uint32_t>& out,
                     std::vector<std::uint32_t>& stack) {
    out.clear();
    stack.clear();
    auto pushChildren = [&](std::uint32_t pos) {
        const Rule& r = g.rules[c.rule(pos)];
        for (std::uint32_t e = r.childOffsets; e-- > 0;)
            if (c.child(pos, e) > 0) stack.push_back(pos + std::uint32_t(c.child(pos, e)));
    };
    pushChildren(root);
    while (!stack.empty()) {
        const std::uint32_t pos = stack.back();
        stack.pop_back();
        out.push_back(pos);
        pushChildren(pos);
    }
}

bool regrowBelow(const Grammar& g, const Chromosome& x, std::uint32_t v, Chromosome& y, Rng& rng,
                 const GenomeLimits& limits, RegrowScratch& s, std::vector<MatchedGene>* matched) {
    subtreePreorder(g, x, v, s.oldGenes, s.stack);
    y.copyFrom(x);
    Lineage before = x.lineage;
    // Cut: descendants come after v, so v keeps its position.
    const Rule& vr = g.rules[y.rule(v)];
    for (std::uint32_t e = 0; e < vr.childOffsets; ++e) {
        const std::int32_t off = y.child(v, e);
        if (off > 0) removeSubtree(g, y, v + std::uint32_t(off), v, s.genome);
        else if (off == kRefused) y.setChild(v, e, kNotExpressed);
    }
    // Regrow breadth first from v: every position is decided once, with its slot's probability.
    const std::uint32_t firstNew = y.size();
    for (std::uint32_t pos = v; pos < y.size(); pos = pos == v ? firstNew : pos + g.rules[y.rule(pos)].geneWords()) {
        const Rule& r = g.rules[y.rule(pos)];
        for (const Slot& slot : r.slots) {
            for (std::uint32_t k = 0; k < slot.maxCount; ++k) {
                if (slot.probability <= 0) continue;
                if (!slot.mandatory() && rng.uniform() >= slot.probability) continue;
                const std::uint16_t rule = pickAlternative(slot, rng);
                if (y.genes + 1 > limits.maxGenes) return false;
                appendGene(g, y, rule, pos, slot.firstChild + k, rng);
            }
        }
        if (pos == v && firstNew == y.size()) break;  // nothing grew below v
    }
    // Pair the new genes with the cut ones, rule by rule in canonical pre-order.
    subtreePreorder(g, y, v, s.newGenes, s.stack);
    s.cursor.assign(g.rules.size(), 0);
    if (matched) {
        matched->clear();
        if (vr.paramFloats > 0) matched->push_back({v, v});
    }
    for (const std::uint32_t to : s.newGenes) {
        const std::uint16_t rule = y.rule(to);
        std::uint32_t& k = s.cursor[rule];
        while (k < s.oldGenes.size() && x.rule(s.oldGenes[k]) != rule) ++k;
        if (k == s.oldGenes.size()) continue;
        const std::uint32_t from = s.oldGenes[k++];
        const Rule& r = g.rules[rule];
        if (r.paramFloats == 0) continue;
        std::memcpy(&y.words[Chromosome::paramWord(to, r)], &x.words[Chromosome::paramWord(from, r)],
                    r.paramFloats * sizeof(std::uint32_t));
        if (matched) matched->push_back({from, to});
    }
    y.noteChange(std::move(before), v, v);  // v keeps its place; all below it is new
    return true;
}

}  // namespace shapevo

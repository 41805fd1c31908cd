// Structural building blocks: add a gene, complete mandatory children, remove a subtree,
// append a copied subtree. All in one forward sweep with relative offsets fixed on the way.
#include <algorithm>
#include <cstring>

#include "genome/operators.hpp"

namespace shapevo {

std::uint16_t pickAlternative(const Slot& s, Rng& rng) {
    if (s.rules.size() == 1) return s.rules[0];
    float total = 0;
    for (float w : s.weights) total += w;
    float r = float(rng.uniform()) * total;
    for (std::size_t i = 0; i < s.rules.size(); ++i) {
        if (r < s.weights[i]) return s.rules[i];
        r -= s.weights[i];
    }
    return s.rules.back();
}

std::uint32_t appendGene(const Grammar& g, Chromosome& c, std::uint16_t r, std::uint32_t parentPos, std::uint32_t entry,
                         Rng& rng) {
    const Rule& rule = g.rules[r];
    const std::uint32_t pos = c.size();
    c.words.resize(pos + rule.geneWords(), 0u);
    c.words[pos] = r;
    if (pos != parentPos) {
        c.setParentOffset(pos, std::int32_t(parentPos) - std::int32_t(pos));
        c.setChild(parentPos, entry, std::int32_t(pos - parentPos));
    }
    drawParams(g, c, pos, rng);
    ++c.genes;
    return pos;
}

void completeMandatory(const Grammar& g, Chromosome& c, std::uint32_t from, Rng& rng) {
    for (std::uint32_t pos = from; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        const std::uint16_t r = c.rule(pos);
        for (const Slot& s : g.rules[r].slots) {
            if (!s.mandatory()) continue;
            for (std::uint32_t k = 0; k < s.maxCount; ++k)
                if (c.child(pos, s.firstChild + k) == kNotExpressed)
                    appendGene(g, c, pickAlternative(s, rng), pos, s.firstChild + k, rng);
        }
    }
}

void plantRoot(const Grammar& g, Chromosome& c, Rng& rng) {
    c.clear();
    appendGene(g, c, g.start, 0, 0, rng);
    completeMandatory(g, c, 0, rng);
}

namespace {
/// In the (already moved) parent at `parentNew`, replace the child offset `oldValue` by `newValue`.
void retargetChild(const Grammar& g, Chromosome& c, std::uint32_t parentNew, std::int32_t oldValue, std::int32_t newValue) {
    const Rule& pr = g.rules[c.rule(parentNew)];
    for (std::uint32_t e = 0; e < pr.childOffsets; ++e) {
        if (c.child(parentNew, e) == oldValue) {
            c.setChild(parentNew, e, newValue);
            return;
        }
    }
}
}  // namespace

// Why retargeting by value is safe: children are swept in increasing old position, and a moved
// child's new offset is never larger than its old one; so an already-fixed sibling can never
// hold the old offset we are looking for.
std::uint32_t removeSubtree(const Grammar& g, Chromosome& c, std::uint32_t root, std::uint32_t keep,
                            GenomeScratch& scratch) {
    auto& newPos = scratch.newPos;
    newPos.assign(c.size(), GenomeScratch::kGone);
    std::uint32_t out = 0, genes = 0;
    for (std::uint32_t pos = 0; pos < c.size();) {
        const std::uint32_t w = g.rules[c.rule(pos)].geneWords();
        const std::int32_t po = c.parentOffset(pos);
        const std::uint32_t parentOld = std::uint32_t(std::int32_t(pos) + po);
        const bool removed = pos == root || (pos != 0 && newPos[parentOld] == GenomeScratch::kGone);
        if (removed) {
            if (pos == root) retargetChild(g, c, newPos[parentOld], -po, kNotExpressed);
        } else {
            if (out != pos) std::memmove(&c.words[out], &c.words[pos], w * sizeof(std::uint32_t));
            newPos[pos] = out;
            if (pos != 0) {
                const std::uint32_t parentNew = newPos[parentOld];
                c.setParentOffset(out, std::int32_t(parentNew) - std::int32_t(out));
                retargetChild(g, c, parentNew, -po, std::int32_t(out - parentNew));
            }
            out += w;
            ++genes;
        }
        pos += w;
    }
    c.words.resize(out);
    c.genes = genes;
    return newPos[keep];
}

void appendSubtree(const Grammar& g, Chromosome& dst, std::uint32_t parentPos, std::uint32_t entry,
                   const Chromosome& src, std::uint32_t srcRoot, GenomeScratch& scratch) {
    auto& newPos = scratch.newPos;
    newPos.assign(src.size(), GenomeScratch::kGone);
    for (std::uint32_t pos = srcRoot; pos < src.size();) {
        const std::uint32_t w = g.rules[src.rule(pos)].geneWords();
        const std::int32_t po = src.parentOffset(pos);
        const std::uint32_t parentOld = std::uint32_t(std::int32_t(pos) + po);
        const bool inside = pos == srcRoot || (parentOld >= srcRoot && newPos[parentOld] != GenomeScratch::kGone);
        if (inside) {
            const std::uint32_t out = dst.size();
            dst.words.insert(dst.words.end(), src.words.begin() + pos, src.words.begin() + pos + w);
            newPos[pos] = out;
            ++dst.genes;
            if (pos == srcRoot) {
                dst.setParentOffset(out, std::int32_t(parentPos) - std::int32_t(out));
                dst.setChild(parentPos, entry, std::int32_t(out - parentPos));
            } else {
                const std::uint32_t parentNew = newPos[parentOld];
                dst.setParentOffset(out, std::int32_t(parentNew) - std::int32_t(out));
                retargetChild(g, dst, parentNew, -po, std::int32_t(out - parentNew));
            }
        }
        pos += w;
    }
}

}  // namespace shapevo

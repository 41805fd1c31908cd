// Sequential growth: decide futures in chromosome order (SMC) or at random (SOSMC) until a new
// geometric object exists. Children are appended, so in chromosome order the first undecided
// position only moves forward during one call.
#include "genome/sequential_growth.hpp"

#include "genome/operators.hpp"

namespace shapevo {

namespace {

bool emitsGeometry(const Rule& r) {
    for (const Statement& s : r.statements) {
        switch (s.kind) {
        case StatementKind::Primitive: return true;
        default: break;
        }
    }
    return false;
}

struct Future {
    std::uint32_t pos = 0;    ///< gene
    std::uint16_t slot = 0;   ///< slot index in its rule
    std::uint32_t entry = 0;  ///< child offset index
};

/// The first undecided future at or after (pos, entry) in chromosome order.
bool firstUndecided(const Grammar& g, const Chromosome& c, std::uint32_t pos, std::uint32_t entry, Future& out) {
    for (; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords(), entry = 0) {
        const Rule& r = g.rules[c.rule(pos)];
        for (std::uint16_t si = 0; si < r.slots.size(); ++si) {
            const Slot& s = r.slots[si];
            for (std::uint32_t k = 0; k < s.maxCount; ++k) {
                const std::uint32_t e = s.firstChild + k;
                if (e < entry || c.child(pos, e) != kNotExpressed) continue;
                out = {pos, si, e};
                return true;
            }
        }
    }
    return false;
}

/// The `pick`-th undecided future in chromosome order.
Future nthUndecided(const Grammar& g, const Chromosome& c, std::uint32_t pick) {
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        const Rule& r = g.rules[c.rule(pos)];
        for (std::uint16_t si = 0; si < r.slots.size(); ++si)
            for (std::uint32_t k = 0; k < r.slots[si].maxCount; ++k)
                if (c.child(pos, r.slots[si].firstChild + k) == kNotExpressed && pick-- == 0)
                    return {pos, si, r.slots[si].firstChild + k};
    }
    return {};
}

bool anyGeometric(const Grammar& g, const Chromosome& c, std::uint32_t from, const std::vector<char>& geometric) {
    for (std::uint32_t pos = from; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords())
        if (geometric[c.rule(pos)]) return true;
    return false;
}

}  // namespace

std::vector<char> geometricRules(const Grammar& g) {
    std::vector<char> out(g.rules.size(), 0);
    for (std::size_t r = 0; r < g.rules.size(); ++r) out[r] = emitsGeometry(g.rules[r]) ? 1 : 0;
    return out;
}

std::uint32_t undecidedChildren(const Grammar& g, const Chromosome& c) {
    std::uint32_t n = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords())
        for (std::uint32_t e = 0; e < g.rules[c.rule(pos)].childOffsets; ++e) n += c.child(pos, e) == kNotExpressed;
    return n;
}

bool growNextObject(const Grammar& g, Chromosome& c, Rng& rng, const GenomeLimits& limits, GrowthOrder order,
                    const std::vector<char>& geometric) {
    bool grewAny = false;
    if (c.empty()) {
        if (g.mandatoryGenes[g.start] > limits.maxGenes) return false;
        plantRoot(g, c, rng);
        if (anyGeometric(g, c, 0, geometric)) return true;
        grewAny = true;
    }
    Future f;
    std::uint32_t cursorPos = 0, cursorEntry = 0;  // chromosome order: nothing before it is undecided
    for (;;) {
        if (order == GrowthOrder::Chromosome) {
            if (!firstUndecided(g, c, cursorPos, cursorEntry, f)) break;
            cursorPos = f.pos;
            cursorEntry = f.entry + 1;
        } else {
            const std::uint32_t n = undecidedChildren(g, c);
            if (n == 0) break;
            f = nthUndecided(g, c, rng.below(n));
        }
        const Slot& s = g.rules[c.rule(f.pos)].slots[f.slot];
        const bool express = s.probability > 0 && (s.mandatory() || rng.uniform() < s.probability);
        if (!express) {
            c.setChild(f.pos, f.entry, kRefused);
            continue;
        }
        const std::uint16_t rule = pickAlternative(s, rng);
        if (c.genes + g.mandatoryGenes[rule] > limits.maxGenes) {
            c.setChild(f.pos, f.entry, kRefused);
            continue;
        }
        const std::uint32_t first = appendGene(g, c, rule, f.pos, f.entry, rng);
        completeMandatory(g, c, first, rng);
        grewAny = true;
        if (anyGeometric(g, c, first, geometric)) break;
    }
    return grewAny;
}

}  // namespace shapevo

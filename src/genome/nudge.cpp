// Nudge: one parameter moved by a small random step inside its prior's support.
#include "genome/nudge.hpp"

#include <algorithm>
#include <cmath>

#include "genome/priors.hpp"

namespace shapevo {

namespace {

constexpr double kFinest = 0.003, kCoarsest = 0.3;  ///< step deviation, as a share of the support's width

bool canMove(const Grammar& g, const Prior& p) {
    switch (p.kind) {
    case PriorKind::Uniform:
    case PriorKind::Normal: return p.hi > p.lo;
    case PriorKind::Int: return std::floor(p.hi) > std::ceil(p.lo);
    case PriorKind::Choice: return p.choiceCount > 1 && std::any_of(g.choiceValues.begin() + p.choiceBegin,
                                                                     g.choiceValues.begin() + p.choiceBegin + p.choiceCount,
                                                                     [&](float v) { return v != g.choiceValues[p.choiceBegin]; });
    }
    return false;
}

float moved(const Grammar& g, const Prior& p, float v, Rng& rng) {
    switch (p.kind) {
    case PriorKind::Uniform:
    case PriorKind::Normal: {
        const double lo = p.lo, hi = p.hi, width = hi - lo;
        const double deviation = width * kFinest * std::pow(kCoarsest / kFinest, rng.uniform());
        double x = double(v) + deviation * rng.normal();
        // Reflect at the bounds (a step of more than a width is impossible in practice; clamp then).
        if (x < lo) x = lo + (lo - x);
        if (x > hi) x = hi - (x - hi);
        return std::clamp(float(std::clamp(x, lo, hi)), p.lo, p.hi);
    }
    case PriorKind::Int: {
        const float lo = std::ceil(p.lo), hi = std::floor(p.hi);
        const bool up = v <= lo ? true : v >= hi ? false : rng.below(2) == 1;
        return up ? v + 1.0f : v - 1.0f;
    }
    case PriorKind::Choice: {
        for (;;) {  // canMove guarantees a different value exists
            const float w = g.choiceValues[p.choiceBegin + rng.below(p.choiceCount)];
            if (w != v) return w;
        }
    }
    }
    return v;
}

}  // namespace

bool nudge(const Grammar& g, Chromosome& c, Rng& rng) {
    std::uint32_t candidates = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        const Rule& r = g.rules[c.rule(pos)];
        for (const Param& p : r.params)
            for (int k = 0; k < p.dims; ++k) candidates += canMove(g, p.prior[k]) ? 1 : 0;
    }
    if (candidates == 0) return false;
    std::uint32_t pick = rng.below(candidates);
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) {
        const Rule& r = g.rules[c.rule(pos)];
        for (const Param& p : r.params)
            for (int k = 0; k < p.dims; ++k) {
                if (!canMove(g, p.prior[k]) || pick-- != 0) continue;
                const std::uint32_t i = p.first + std::uint32_t(k);
                Lineage before = std::move(c.lineage);
                c.setParam(pos, r, i, moved(g, p.prior[k], c.param(pos, r, i), rng));
                c.noteChange(std::move(before), pos, pos);
                return true;
            }
    }
    return false;
}

}  // namespace shapevo

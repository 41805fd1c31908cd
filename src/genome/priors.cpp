// Priors: uniform, truncated normal, integer and choice, with their exact supports.
#include "genome/priors.hpp"

#include <cmath>

#include "genome/chromosome.hpp"
#include "genome/operators.hpp"

namespace shapevo {

float drawFromPrior(const Grammar& g, const Prior& p, Rng& rng) {
    switch (p.kind) {
    case PriorKind::Uniform: {
        const float v = float(double(p.lo) + (double(p.hi) - double(p.lo)) * rng.uniform());
        return std::min(std::max(v, p.lo), p.hi);
    }
    case PriorKind::Normal: {
        for (int attempt = 0; attempt < 64; ++attempt) {
            const float v = float(double(p.mu) + double(p.sigma) * rng.normal());
            if (v >= p.lo && v <= p.hi) return v;
        }
        // The mass inside [lo, hi] is tiny: fall back to uniform on the support.
        return std::min(std::max(float(double(p.lo) + (double(p.hi) - double(p.lo)) * rng.uniform()), p.lo), p.hi);
    }
    case PriorKind::Int: {
        const double lo = std::ceil(double(p.lo)), hi = std::floor(double(p.hi));
        const std::uint32_t n = std::uint32_t(hi - lo + 1);
        return float(lo + double(rng.below(n)));
    }
    case PriorKind::Choice: return g.choiceValues[p.choiceBegin + rng.below(p.choiceCount)];
    }
    return 0.0f;
}

bool inSupport(const Grammar& g, const Prior& p, float v) {
    if (!std::isfinite(v)) return false;
    switch (p.kind) {
    case PriorKind::Uniform:
    case PriorKind::Normal: return v >= p.lo && v <= p.hi;
    case PriorKind::Int: return v >= p.lo && v <= p.hi && v == std::floor(v);
    case PriorKind::Choice:
        for (std::uint32_t i = 0; i < p.choiceCount; ++i)
            if (g.choiceValues[p.choiceBegin + i] == v) return true;
        return false;
    }
    return false;
}

void drawParams(const Grammar& g, Chromosome& c, std::uint32_t pos, Rng& rng) {
    const Rule& r = g.rules[c.rule(pos)];
    for (const Param& p : r.params)
        for (int k = 0; k < p.dims; ++k) c.setParam(pos, r, p.first + k, drawFromPrior(g, p.prior[k], rng));
}

}  // namespace shapevo

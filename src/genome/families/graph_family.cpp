// GraphFamily's derivation and operators (graph_family.hpp).
#include "genome/families/graph_family.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/input_error.hpp"

namespace shapevo {

const char GraphDerivationRecord::kMaker = 0;

graph::DeriveResult GraphFamily::derive(const Chromosome& c, graph::DecisionRecord* record) const {
    graph::KeyedDraws draws(graphGenomeSeed(c), graphOverrides(c), record);
    return graph::deriveGraph(grammar_, 0, draws, limits_);
}

namespace {

using graph::DecisionRecord;

class GraphOperators final : public GenomeOperators {
public:
    GraphOperators(const GraphFamily& family, const GenomeLimits& limits) : family_(family), limits_(limits) {}

    void randomGenome(Chromosome& c, Rng& rng, std::uint32_t, std::uint32_t) override { makeGraphGenome(c, rng.next()); }

    bool grow(Chromosome& c, Rng& rng) override {
        if (c.genes >= limits_.maxGenes) return false;
        const DecisionRecord& r = recordOf(c, first_);
        if (r.decisions.empty()) return false;
        // Most firing levels only reorder steps that all happen anyway: three grows in four
        // change an option or an expression's draw, where the derivation made any.
        choices_.clear();
        for (std::uint32_t i = 0; i < r.decisions.size(); ++i)
            if (r.decisions[i].purpose != graph::DrawPurpose::Match) choices_.push_back(i);
        const bool drawn = !choices_.empty() && rng.uniform() < 0.75;
        for (int attempt = 0; attempt < 8; ++attempt) {
            const std::uint32_t pick = drawn ? choices_[rng.below(std::uint32_t(choices_.size()))] : rng.below(std::uint32_t(r.decisions.size()));
            const std::uint64_t key = r.decisions[pick].key;
            if (graph::findOverride(graphOverrides(c), key) >= 0) continue;
            setGraphOverride(c, key, rng.next());
            return true;
        }
        return false;
    }

    bool cut(Chromosome& c, Rng& rng) override {
        const std::size_t n = graphOverrideCount(c);
        if (n == 0) return false;
        removeGraphOverride(c, rng.below(std::uint32_t(n)));
        return true;
    }

    bool alter(Chromosome& c, Rng& rng) override {
        const std::size_t n = graphOverrideCount(c);
        if (n == 0) return false;
        setGraphOverride(c, graph::overrideKey(graphOverrides(c), rng.below(std::uint32_t(n))), rng.next());
        return true;
    }

    bool nudge(Chromosome& c, Rng& rng) override {
        const std::size_t n = graphOverrideCount(c);
        if (n == 0) return false;
        const std::size_t i = rng.below(std::uint32_t(n));
        const double u = graph::wordUniform(graph::overrideWord(graphOverrides(c), i));
        const double sigma = std::exp(std::log(0.003) + rng.uniform() * (std::log(0.3) - std::log(0.003)));
        double v = u + sigma * rng.normal();
        v = std::fmod(std::fabs(v), 2.0);  // reflect into [0, 1)
        if (v >= 1.0) v = 2.0 - v;
        if (v >= 1.0) v = std::nextafter(1.0, 0.0);
        setGraphOverride(c, graph::overrideKey(graphOverrides(c), i), std::uint64_t(std::ldexp(v, 53)) << 11);
        return true;
    }

    bool crossover(const Chromosome& a, const Chromosome& b, Chromosome& childA, Chromosome& childB, Rng& rng, int retries) override {
        const DecisionRecord& ra = recordOf(a, first_);
        const DecisionRecord& rb = recordOf(b, second_);
        for (int attempt = 0; attempt < std::max(1, retries) && ra.events.size() > 1; ++attempt) {
            const std::size_t e = 1 + rng.below(std::uint32_t(ra.events.size() - 1));
            std::size_t j = 0;
            for (std::size_t k = 1; k < rb.events.size() && j == 0; ++k)
                if (rb.events[k].eventKey == ra.events[e].eventKey) j = k;
            if (j == 0) continue;
            graftSubtree(a, ra, e, b, rb, j, childA);
            graftSubtree(b, rb, j, a, ra, e, childB);
            if (childA.genes <= limits_.maxGenes && childB.genes <= limits_.maxGenes) return true;
        }
        childA = a;
        childB = b;
        return false;
    }

    bool regrow(const Chromosome& x, Chromosome& y, Rng& rng) override {
        const DecisionRecord& r = recordOf(x, first_);
        if (r.events.size() <= 1) return false;
        const std::size_t e = 1 + rng.below(std::uint32_t(r.events.size() - 1));
        y.copyFrom(x);
        subtreeKeys(r, e, keysA_);
        dropOverrides(y, keysA_);
        if (y.genes >= limits_.maxGenes && graph::findOverride(graphOverrides(y), r.events[e].saltKey) < 0) return false;
        setGraphOverride(y, r.events[e].saltKey, rng.next());
        return true;
    }

private:
    /// The decision record of `c`: the one its scoring left, or a derivation made now into `scratch`.
    const DecisionRecord& recordOf(const Chromosome& c, DecisionRecord& scratch) {
        if (c.lineage.parent && c.lineage.parent->maker == &GraphDerivationRecord::kMaker)
            return static_cast<const GraphDerivationRecord&>(*c.lineage.parent).record;
        try {
            family_.derive(c, &scratch);
        } catch (const InputError&) {
            // what was decided up to the failure stays recorded; scoring gives the genome its worst fitness
        }
        return scratch;
    }

    /// The keys of event e's subtree in `r` (its events' salt keys and their decisions), sorted.
    void subtreeKeys(const DecisionRecord& r, std::size_t e, std::vector<std::uint64_t>& keys) {
        below_.assign(r.events.size(), 0);
        below_[e] = 1;
        for (std::size_t k = e + 1; k < r.events.size(); ++k) below_[k] = below_[r.events[k].parent];
        keys.clear();
        for (std::size_t k = e; k < r.events.size(); ++k)
            if (below_[k]) keys.push_back(r.events[k].saltKey);
        for (const DecisionRecord::Decision& d : r.decisions)
            if (d.event < below_.size() && below_[d.event]) keys.push_back(d.key);
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    }

    static void dropOverrides(Chromosome& c, const std::vector<std::uint64_t>& keys) {
        for (std::size_t i = graphOverrideCount(c); i-- > 0;)
            if (std::binary_search(keys.begin(), keys.end(), graph::overrideKey(graphOverrides(c), i))) removeGraphOverride(c, i);
    }

    /// child = `to` with its subtree at event e replaced by `from`'s subtree at event j (the same
    /// event key): e's seed becomes the one `from` had there, and `from`'s overrides below it come along.
    void graftSubtree(const Chromosome& to, const DecisionRecord& rTo, std::size_t e, const Chromosome& from,
                      const DecisionRecord& rFrom, std::size_t j, Chromosome& child) {
        child.copyFrom(to);
        subtreeKeys(rTo, e, keysA_);
        dropOverrides(child, keysA_);
        subtreeKeys(rFrom, j, keysB_);
        const auto o = graphOverrides(from);
        for (std::size_t i = 0; i < graphOverrideCount(from); ++i)
            if (std::binary_search(keysB_.begin(), keysB_.end(), graph::overrideKey(o, i)))
                setGraphOverride(child, graph::overrideKey(o, i), graph::overrideWord(o, i));
        setGraphOverride(child, rTo.events[e].saltKey, rFrom.events[j].seed);
    }

    const GraphFamily& family_;
    GenomeLimits limits_;
    DecisionRecord first_, second_;
    std::vector<std::uint64_t> keysA_, keysB_;
    std::vector<char> below_;
    std::vector<std::uint32_t> choices_;
};

}  // namespace

std::unique_ptr<GenomeOperators> GraphFamily::makeOperators(const GenomeLimits& limits) const {
    return std::make_unique<GraphOperators>(*this, limits);
}

}  // namespace shapevo

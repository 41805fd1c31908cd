// Grammar checks: every derivation must be able to end, and mandatory subtrees have a known size.
#include "grammar/grammar_checks.hpp"

#include <algorithm>

namespace shapevo {

namespace {

enum class Mark { None, Active, Done };

/// Depth-first over mandatory slots with an explicit stack (a chain of thousands of rules must
/// not overflow the C++ stack); a back edge is a derivation that can never end.
struct Walker {
    Grammar& g;
    const GrammarFailure& fail;
    std::vector<Mark> mark;

    struct Frame {
        int rule;
        std::size_t slot = 0, alternative = 0;
        std::uint64_t genes = 1, words = 0;
        std::uint64_t slotGenes = 0, slotWords = 0;  ///< largest alternative of the current slot
    };
    std::vector<Frame> path;

    void push(int r) {
        mark[r] = Mark::Active;
        Frame f{r};
        f.words = g.rules[r].geneWords();
        path.push_back(f);
    }

    void cycle(int c) {
        std::string text;
        auto from = std::find_if(path.begin(), path.end(), [c](const Frame& f) { return f.rule == c; });
        for (auto it = from; it != path.end(); ++it) text += g.rules[it->rule].name + " -> ";
        text += g.rules[c].name;
        fail(g.rules[c].where, "recursion never ends: " + text +
                                   " are all probability-1 children; give one of these child slots a prob below 1 "
                                   "(or mark it 'optional')");
    }

    void visit(int root) {
        push(root);
        while (!path.empty()) {
            Frame& f = path.back();
            const Rule& rule = g.rules[f.rule];
            while (f.slot < rule.slots.size() && !rule.slots[f.slot].mandatory()) ++f.slot;
            if (f.slot == rule.slots.size()) {
                if (f.genes > 1000000) fail(rule.where, "rule " + rule.name + " always derives more than 1,000,000 genes");
                g.mandatoryGenes[f.rule] = std::uint32_t(f.genes);
                g.mandatoryWords[f.rule] = std::uint32_t(f.words);
                mark[f.rule] = Mark::Done;
                path.pop_back();
                continue;
            }
            const Slot& s = rule.slots[f.slot];
            if (f.alternative == s.rules.size()) {
                f.genes += f.slotGenes * s.maxCount;
                f.words += f.slotWords * s.maxCount;
                f.slotGenes = f.slotWords = 0;
                f.alternative = 0;
                ++f.slot;
                continue;
            }
            const int c = s.rules[f.alternative];
            if (mark[c] == Mark::Active) cycle(c);
            if (mark[c] == Mark::None) {
                push(c);  // f may dangle now; come back to this alternative when c is done
                continue;
            }
            f.slotGenes = std::max<std::uint64_t>(f.slotGenes, g.mandatoryGenes[c]);
            f.slotWords = std::max<std::uint64_t>(f.slotWords, g.mandatoryWords[c]);
            ++f.alternative;
        }
    }
};

}  // namespace

void checkGrammar(Grammar& g, const GrammarFailure& fail) {
    g.mandatoryGenes.assign(g.rules.size(), 0);
    g.mandatoryWords.assign(g.rules.size(), 0);
    Walker w{g, fail, std::vector<Mark>(g.rules.size(), Mark::None), {}};
    for (std::size_t r = 0; r < g.rules.size(); ++r)
        if (w.mark[r] == Mark::None) w.visit(int(r));
}

}  // namespace shapevo

// GraphFamily: the graph-derivation model family (2D graph grammars) behind the GenomeFamily
// seam (genome/genome_family.hpp). Its genome (graph_genome.hpp) is a root seed and overrides of
// keyed decisions (graph/keyed_draws.hpp): a derivation answers each decision — which event
// fires (firing levels), which option, each random draw of an expression, the global variables —
// by a key naming what it acts on (graph/lineage_key.hpp), so one override changes only the
// descendants of what its decision acts on. Operators:
//   grow    an override for a decision the parent's derivation made and no override names yet
//           (an option or an expression's draw three times in four, where there is one)
//   cut     drop an override (the decision goes back to its seed's value)
//   alter   redraw an override's word
//   nudge   move an override's value a small step (a fraction of [0, 1) drawn log-uniformly in
//           [0.003, 0.3]), reflected into [0, 1)
//   regrow  give one event of the parent's derivation a seed of its own: its whole subtree is
//           drawn anew (and the overrides below it are dropped)
//   crossover  at an event both parents' derivations have (the same key), each child takes the
//           other parent's subtree there: its seed and its overrides below it
// What the derivation decided comes from the parent's record: the one scoring left in the
// chromosome's lineage (GraphDerivationRecord) or, after a resume or a migration, a derivation
// made by the operator; both are the same function of the genome, so results never depend on it.
#pragma once
#include <memory>
#include <string>

#include "genome/families/graph_genome.hpp"
#include "genome/genome_family.hpp"
#include "graph/derive.hpp"
#include "graph/drawing.hpp"
#include "graph/graph_grammar.hpp"

namespace shapevo {

/// What scoring a graph genome leaves for its children: the derivation's decision record.
struct GraphDerivationRecord final : EvaluatedModel {
    static const char kMaker;  ///< maker = &kMaker marks a record
    GraphDerivationRecord() { maker = &kMaker; }
    graph::DecisionRecord record;
};

class GraphFamily final : public GenomeFamily {
public:
    GraphFamily(const graph::GraphGrammar& grammar, const graph::DeriveLimits& limits) : grammar_(grammar), limits_(limits) {}
    std::string_view name() const override { return "graph derivation"; }
    std::unique_ptr<GenomeOperators> makeOperators(const GenomeLimits& limits) const override;
    std::string check(const Chromosome& c, const GenomeLimits& limits) const override { return checkGraphGenome(c, limits.maxGenes); }
    const std::string& sourceText() const override { return grammar_.source; }
    const Grammar* treeGrammar() const override { return nullptr; }
    const GraphFamily* graphFamily() const override { return this; }
    std::uint32_t largestGeneWords() const override { return std::uint32_t(graph::kOverrideWords); }

    const graph::GraphGrammar& grammar() const { return grammar_; }
    const graph::DeriveLimits& limits() const { return limits_; }
    /// Derive genome `c` (valid) from host graph 0; `record` (may be null) gets its decisions.
    /// @throw InputError as deriveGraph does (an expression that fails, a limit passed).
    graph::DeriveResult derive(const Chromosome& c, graph::DecisionRecord* record = nullptr) const;
    /// The drawing of a graph this grammar derived (graph/drawing.hpp's rules).
    graph::Drawing drawing(const graph::HostGraph& derived) const { return graph::drawingOf(derived, grammar_.names, grammar_.path); }
    /// Derive genome `c` and draw it. @throw InputError as derive does.
    graph::Drawing drawing(const Chromosome& c) const { return drawing(derive(c).graph); }

private:
    const graph::GraphGrammar& grammar_;
    graph::DeriveLimits limits_;
};

}  // namespace shapevo

// GenomeFamily: a model family's genome as the search methods, islands, migration, checkpoints
// and genome files see it — the contract of the plug-in family "model families"
// (docs/architecture.md). A family stores its genome in a Chromosome (packed 32-bit words and a
// gene count), so populations, evaluation batches, migration and checkpoints move bytes without
// knowing the family; what the words mean belongs to the family alone:
//  - check(): whether words read back (checkpoint, migrant, genome file) are a valid genome;
//  - makeOperators(): the operators a search method applies, with their own scratch buffers
//    (one object per search method, never shared between threads);
//  - treeGrammar(): the derivation-tree grammar for the methods that need a tree's structure
//    (SMC, SOSMC, RJMCMC); nullptr for a family that has none.
// Members: the derivation-tree family (genome/families/tree_family.hpp: grammars, CastleMaker
// rules) and the graph-derivation family (genome/families/graph_family.hpp: 2D graph grammars).
// The family is chosen once per run; a tree run calls the same operator code as before, through
// one virtual call per operator application (an operator's work is O(chromosome)).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "genome/chromosome.hpp"
#include "genome/random.hpp"

namespace shapevo {

class GraphFamily;

/// A family's genetic operators, as search methods apply them. Every output is a valid genome of
/// the family within the limits the operators were made with (property tests prove it per family).
/// All randomness comes from the Rng passed in, in a fixed order.
class GenomeOperators {
public:
    virtual ~GenomeOperators() = default;
    /// A random starting genome in `c` (cleared first). The tree family grows it to a length drawn
    /// from [minGenes, maxGenes] (growRandomLength); a family without lengths may ignore them.
    virtual void randomGenome(Chromosome& c, Rng& rng, std::uint32_t minGenes, std::uint32_t maxGenes) = 0;
    /// Add a decision (tree: express a child). False if nothing can grow within the limits.
    virtual bool grow(Chromosome& c, Rng& rng) = 0;
    /// Remove a decision (tree: cut a subtree). False if nothing can go.
    virtual bool cut(Chromosome& c, Rng& rng) = 0;
    /// Redraw one decision's values. False if there is none.
    virtual bool alter(Chromosome& c, Rng& rng) = 0;
    /// A small step of one continuous value (local refinement). False if none can move.
    virtual bool nudge(Chromosome& c, Rng& rng) = 0;
    /// Two children of `a` and `b`; up to `retries` attempts. False: children = copies of the parents.
    virtual bool crossover(const Chromosome& a, const Chromosome& b, Chromosome& childA, Chromosome& childB, Rng& rng,
                           int retries) = 0;
    /// y = x with one part drawn anew below a point picked uniformly (tree: regrow below a
    /// non-terminal gene). False, without drawing from `rng`, if `x` has no such point; false
    /// after drawing if the result would pass the limits. Callers tell the two apart by the Rng's
    /// state (the hybrid's local move falls back to a nudge or an alter only in the first case).
    virtual bool regrow(const Chromosome& x, Chromosome& y, Rng& rng) = 0;
};

class GenomeFamily {
public:
    virtual ~GenomeFamily() = default;
    /// "derivation tree", "graph derivation": messages and inspect.
    virtual std::string_view name() const = 0;
    /// Operators within `limits`, with their own scratch (one per search method).
    virtual std::unique_ptr<GenomeOperators> makeOperators(const GenomeLimits& limits) const = 0;
    /// Empty if `c` is a valid genome of this family within `limits`; otherwise what is wrong first.
    virtual std::string check(const Chromosome& c, const GenomeLimits& limits) const = 0;
    /// The text a genome file's hash names (genome/genome_file.hpp): the grammar file's text.
    virtual const std::string& sourceText() const = 0;
    /// The tree grammar (SMC, SOSMC, RJMCMC, diversity); nullptr for a family without one.
    virtual const Grammar* treeGrammar() const = 0;
    /// The words of a family's largest gene (the memory estimate), for a family without a tree
    /// grammar (a tree's come from its rules).
    virtual std::uint32_t largestGeneWords() const { return 1; }
    /// The graph-derivation family itself (what scores a drawing needs); nullptr for another.
    virtual const GraphFamily* graphFamily() const { return nullptr; }
};

}  // namespace shapevo

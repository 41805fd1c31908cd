// Genetic operators on packed chromosomes (ShapeGenetics §5): grow, cut, alter, crossover.
// Each is O(chromosome length), allocates nothing once its buffers are warm, and always leaves
// a valid derivation of the grammar (see validate.hpp for the invariants).
#pragma once
#include "genome/chromosome.hpp"
#include "genome/random.hpp"

namespace shapevo {

/// Start a chromosome: the start rule's gene plus its mandatory (probability-1) children.
void plantRoot(const Grammar& g, Chromosome& c, Rng& rng);

/// Grow: express one non-expressed child, chosen with probability proportional to its slot's
/// probability, draw its parameters, and add its mandatory children. An empty chromosome gets
/// its root. Returns false if nothing can grow within the limits.
bool grow(const Grammar& g, Chromosome& c, Rng& rng, const GenomeLimits& limits);

/// A random starting chromosome: `c` is cleared, a length is drawn uniformly from
/// [minGenes, maxGenes] (both capped by limits.maxGenes; maxGenes below minGenes counts as
/// minGenes) and grow() is applied until the chromosome has that many genes or cannot grow.
void growRandomLength(const Grammar& g, Chromosome& c, Rng& rng, const GenomeLimits& limits, std::uint32_t minGenes,
                      std::uint32_t maxGenes);

/// Cut: remove one expressed child and its subtree, chosen with probability proportional to
/// 1 - its slot's probability (mandatory children are never cut). Returns false if none can go.
bool cut(const Grammar& g, Chromosome& c, Rng& rng, GenomeScratch& scratch);

/// Alter: redraw every parameter of one gene (chosen uniformly among genes with parameters).
bool alter(const Grammar& g, Chromosome& c, Rng& rng);

/// Crossover (Algorithm 2): pick a connection of `a` uniformly, a connection of `b` on the same
/// generator-graph edge uniformly, and swap the subtrees. Up to `retries` attempts; children
/// longer than the limits are rejected. Returns false (children = copies of the parents) if no
/// attempt succeeded.
bool crossover(const Grammar& g, const Chromosome& a, const Chromosome& b, Chromosome& childA, Chromosome& childB,
               Rng& rng, const GenomeLimits& limits, int retries, GenomeScratch& scratch);

// --- building blocks, shared by the operators and by the search methods -------------------

/// Draw all parameters of the gene at `pos` from their priors.
void drawParams(const Grammar& g, Chromosome& c, std::uint32_t pos, Rng& rng);
/// Pick one of a slot's alternatives by weight.
std::uint16_t pickAlternative(const Slot& s, Rng& rng);
/// Append a gene of rule `r` as child `entry` of the gene at `parentPos` (no parent: the root).
/// Parameters are drawn from their priors. Returns its position.
std::uint32_t appendGene(const Grammar& g, Chromosome& c, std::uint16_t r, std::uint32_t parentPos, std::uint32_t entry,
                         Rng& rng);
/// Express every still-empty mandatory child of genes at or after `from`, recursively.
void completeMandatory(const Grammar& g, Chromosome& c, std::uint32_t from, Rng& rng);
/// Remove the subtree rooted at `root` in place, compacting the buffer and fixing offsets.
/// Returns the new position of `keep` (a gene outside the subtree).
std::uint32_t removeSubtree(const Grammar& g, Chromosome& c, std::uint32_t root, std::uint32_t keep,
                            GenomeScratch& scratch);
/// Append a copy of `src`'s subtree at `srcRoot` as child `entry` of `dst`'s gene at `parentPos`.
void appendSubtree(const Grammar& g, Chromosome& dst, std::uint32_t parentPos, std::uint32_t entry,
                   const Chromosome& src, std::uint32_t srcRoot, GenomeScratch& scratch);

}  // namespace shapevo

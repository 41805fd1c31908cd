// Regrow: the jump move of RJMCMC (ShapeGenetics §7 after Talton et al. 2011) as genome
// operators. A jump picks a non-terminal gene v, cuts everything below it and regrows v's
// children from the grammar (each position expressed with its slot probability, recursively).
// The new genes reuse the cut subtree's parameter values where they fit: in canonical pre-order
// (children by child-offset index), the k-th new gene of rule r takes the values of the k-th cut
// gene of rule r; only genes without such a partner keep freshly drawn values. The pairing
// depends on the two tree shapes only, so the reverse jump pairs the same genes (Jacobian 1).
#pragma once
#include <vector>

#include "genome/chromosome.hpp"
#include "genome/random.hpp"

namespace shapevo {

/// A gene kept or paired across a jump: position in the old chromosome, position in the new one.
struct MatchedGene {
    std::uint32_t from = 0, to = 0;
};

struct RegrowScratch {
    GenomeScratch genome;
    std::vector<std::uint32_t> stack, oldGenes, newGenes, cursor;
    std::vector<float> depthWeight;  ///< per word position: depth_bias^depth of the gene there
};

/// Non-terminal selection weight total of `c`: the sum over genes whose rule has child slots of
/// depthBias^depth (root depth 0). Fills s.depthWeight for pickJumpGene.
double jumpWeightTotal(const Grammar& g, const Chromosome& c, double depthBias, RegrowScratch& s);

/// A gene chosen with probability weight / total (call jumpWeightTotal on `c` first; total > 0).
std::uint32_t pickJumpGene(const Grammar& g, const Chromosome& c, double total, Rng& rng, const RegrowScratch& s);

/// y = x with every descendant of the gene at `v` cut and v's children regrown as described
/// above. Returns false, with y unspecified, if the regrown tree would pass limits.maxGenes (the
/// proposal lies outside the space and is rejected). If `matched` is given it receives v and
/// every paired gene that has parameters.
bool regrowBelow(const Grammar& g, const Chromosome& x, std::uint32_t v, Chromosome& y, Rng& rng,
                 const GenomeLimits& limits, RegrowScratch& s, std::vector<MatchedGene>* matched = nullptr);

/// The genes of the subtree at `root` (itself excluded) in canonical pre-order: children in
/// child-offset order, depth first.
void subtreePreorder(const Grammar& g, const Chromosome& c, std::uint32_t root, std::vector<std::uint32_t>& out,
                     std::vector<std::uint32_t>& stack);

}  // namespace shapevo

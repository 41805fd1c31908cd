// TreeFamily: the derivation-tree model family (grammars, CastleMaker rules, procedural content
// graphs: everything that compiles into a Grammar) behind the model-family seam
// (genome/genome_family.hpp). Its genome is the packed derivation tree of genome/chromosome.hpp;
// check() is validateChromosome and its operators call the free functions of
// genome/operators.hpp, genome/nudge.hpp and genome/regrow.hpp with the same arguments and so
// draw from the Rng in exactly the same order: a search through the family is the same search as
// one calling those functions directly (tests/genome/tree_family_test.cpp proves it).
// The family holds a reference to its Grammar, which must outlive it and its operators.
#pragma once
#include <memory>
#include <string>
#include <string_view>

#include "genome/genome_family.hpp"
#include "genome/regrow.hpp"

namespace shapevo {

/// The tree family's operators: one object per search method, with its own scratch buffers.
class TreeOperators final : public GenomeOperators {
public:
    TreeOperators(const Grammar& g, const GenomeLimits& limits) : grammar_(g), limits_(limits) {}

    void randomGenome(Chromosome& c, Rng& rng, std::uint32_t minGenes, std::uint32_t maxGenes) override;
    bool grow(Chromosome& c, Rng& rng) override;
    bool cut(Chromosome& c, Rng& rng) override;
    bool alter(Chromosome& c, Rng& rng) override;
    bool nudge(Chromosome& c, Rng& rng) override;
    bool crossover(const Chromosome& a, const Chromosome& b, Chromosome& childA, Chromosome& childB, Rng& rng,
                   int retries) override;
    /// RJMCMC's jump with every non-terminal gene alike (depth bias 1): jumpWeightTotal, then, if
    /// some gene has child slots, pickJumpGene and regrowBelow.
    bool regrow(const Chromosome& x, Chromosome& y, Rng& rng) override;

private:
    const Grammar& grammar_;
    GenomeLimits limits_;
    GenomeScratch scratch_;
    RegrowScratch regrow_;
};

class TreeFamily final : public GenomeFamily {
public:
    explicit TreeFamily(const Grammar& g) : grammar_(g) {}

    std::string_view name() const override { return "derivation tree"; }
    std::unique_ptr<GenomeOperators> makeOperators(const GenomeLimits& limits) const override {
        return std::make_unique<TreeOperators>(grammar_, limits);
    }
    /// validateChromosome: its messages unchanged.
    std::string check(const Chromosome& c, const GenomeLimits& limits) const override;
    /// The grammar's source text (Grammar::source).
    const std::string& sourceText() const override { return grammar_.source; }
    const Grammar* treeGrammar() const override { return &grammar_; }

private:
    const Grammar& grammar_;
};

}  // namespace shapevo

// measureDiversity: sort the individuals by their words (lexicographically, genes first) and count
// the runs of equal ones, once for the genomes and (with a tree grammar) once for their structures.
#include "search/population_diversity.hpp"

#include <algorithm>

namespace shapevo {

namespace {

/// Number of distinct word vectors among `v` (sorted through `order`).
std::size_t distinct(const std::vector<const std::vector<std::uint32_t>*>& v, std::vector<std::size_t>& order) {
    order.resize(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return *v[a] < *v[b]; });
    std::size_t n = v.empty() ? 0 : 1;
    for (std::size_t i = 1; i < order.size(); ++i) n += *v[order[i]] != *v[order[i - 1]];
    return n;
}

}  // namespace

Diversity measureDiversity(const GenomeFamily& family, const Population& pop, DiversityScratch& scratch) {
    Diversity d;
    const Grammar* g = family.treeGrammar();
    const std::size_t n = pop.size();
    std::vector<const std::vector<std::uint32_t>*> words(n);
    scratch.structures.resize(g ? n : 0);
    double genes = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Chromosome& c = pop.individuals[i];
        words[i] = &c.words;
        genes += c.genes;
        d.maxGenes = std::max(d.maxGenes, c.genes);
        if (!g) continue;
        std::vector<std::uint32_t>& s = scratch.structures[i];
        s.assign(c.words.begin(), c.words.end());
        for (std::uint32_t pos = 0; pos < s.size();) {  // genes in order: zero each gene's parameter block
            const Rule& r = g->rules[c.rule(pos)];
            const std::uint32_t params = Chromosome::paramWord(pos, r);
            std::fill(s.begin() + params, s.begin() + pos + r.geneWords(), 0u);
            pos += r.geneWords();
        }
    }
    d.meanGenes = n ? genes / double(n) : 0;
    d.distinctGenomes = distinct(words, scratch.order);
    if (!g) return d;
    for (std::size_t i = 0; i < n; ++i) words[i] = &scratch.structures[i];
    d.distinctStructures = distinct(words, scratch.order);
    d.structuresCounted = true;
    return d;
}

}  // namespace shapevo

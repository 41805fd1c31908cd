// The [ga] and [search] sections' readers.
#include "search/search_sections.hpp"

#include "base/input_error.hpp"
#include "search/search_methods.hpp"

namespace shapevo {

// [ga] holds the sizes of every method (population, generations, initial lengths: they apply to
// hybrid, GA, SMC, SOSMC and RJMCMC alike) and the GA's own operators. Keys are read in the order
// they always were, so the first error a config meets stays the same.
void readGaSection(SectionReader& r, PopulationSettings& p, GaSettings& g) {
    constexpr double big = 1e12;
    r.count("population", p.population, 2, 1e7,
            "individuals per island (per MPI rank); the sizes of [ga] apply to every search method");
    r.count("generations", p.generations, 1, 1e9, "generations per run (generation 1 is the initial population); with run.wall_time and no generations, "
            "the wall time alone ends the run; in async island mode every island does at least this many (one that "
            "finishes first goes on until the slowest has)");
    r.count("elitism", g.elitism, 0, 1e7,
            "the best individuals kept unchanged in the next generation; smaller than population");
    r.count("tournament", g.tournament, 1, 1e7, "individuals drawn per tournament selection; at most population");
    r.number("mutation", g.mutation, 0, 1,
             "GA: probability that a pair of parents is mutated rather than crossed over");
    r.number("grow", g.growWeight, 0, big, "relative weight of the grow mutation");
    r.number("cut", g.cutWeight, 0, big, "relative weight of the cut mutation");
    r.number("alter", g.alterWeight, 0, big, "relative weight of the alter mutation");
    std::uint32_t retries = std::uint32_t(g.crossoverRetries);
    r.count("crossover_retries", retries, 1, 1000,
            "crossover attempts before a pair is mutated instead (the paper's MaxRetries)");
    g.crossoverRetries = int(retries);
    r.count("initial_genes_min", p.initialGenesMin, 1, 1e7,
            "initial chromosomes grow to a length drawn uniformly in [initial_genes_min, initial_genes_max]; at most "
            "genome.max_genes");
    r.count("initial_genes_max", p.initialGenesMax, 1, 1e7,
            "see initial_genes_min; when given, at most genome.max_genes (growth stops there for the default)");
    const auto n = [](std::uint32_t v) { return std::to_string(v); };
    if (g.elitism >= p.population)
        r.failKeys({"ga.elitism", "ga.population"}, "[ga]",
                   "elitism must be smaller than population (ga.elitism = " + n(g.elitism) + ", ga.population = " + n(p.population) + ")");
    if (g.tournament > p.population)
        r.failKeys({"ga.tournament", "ga.population"}, "[ga]",
                   "tournament must not exceed population (ga.tournament = " + n(g.tournament) + ", ga.population = " + n(p.population) + ")");
    if (g.growWeight + g.cutWeight + g.alterWeight <= 0)
        r.failKeys({"ga.grow", "ga.cut", "ga.alter"}, "[ga]", "grow, cut and alter weights must not all be 0");
}

void readSearchSection(SectionReader& r, SearchSettings& s) {
    r.string("method", s.method, "the search method: " + searchMethodNames() + "; see docs/search-methods.md");
    if (!findSearchMethod(s.method))
        r.fail("method", "search.method must be " + searchMethodNames() + ", got \"" + shortened(s.method) + "\"");
    r.flag("diagnostics", s.diagnostics,
           "write diagnostics.csv: per generation of rank 0's island, diversity, lengths, cost per evaluation and "
           "each operator's better, equal and worse children");
    for (const SearchMethodEntry& e : searchMethods()) e.readSettings(r, s);
}

}  // namespace shapevo

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
    r.count("population", p.population, 2, 1e7);
    r.count("generations", p.generations, 1, 1e9);
    r.count("elitism", g.elitism, 0, 1e7);
    r.count("tournament", g.tournament, 1, 1e7);
    r.number("mutation", g.mutation, 0, 1);
    r.number("grow", g.growWeight, 0, big);
    r.number("cut", g.cutWeight, 0, big);
    r.number("alter", g.alterWeight, 0, big);
    std::uint32_t retries = std::uint32_t(g.crossoverRetries);
    r.count("crossover_retries", retries, 1, 1000);
    g.crossoverRetries = int(retries);
    r.count("initial_genes_min", p.initialGenesMin, 1, 1e7);
    r.count("initial_genes_max", p.initialGenesMax, 1, 1e7);
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
    r.string("method", s.method);
    if (!findSearchMethod(s.method))
        r.fail("method", "search.method must be " + searchMethodNames() + ", got \"" + shortened(s.method) + "\"");
    r.flag("diagnostics", s.diagnostics);
    for (const SearchMethodEntry& e : searchMethods()) e.readSettings(r, s);
}

}  // namespace shapevo

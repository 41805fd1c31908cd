// The table of search methods and the factory that reads it.
#include "search/search_methods.hpp"

#include <array>
#include <stdexcept>
#include <vector>

#include "base/input_error.hpp"
#include "base/word_list.hpp"
#include "grammar/front_ends.hpp"
#include "search/genetic_algorithm.hpp"
#include "search/hybrid_search.hpp"
#include "search/random_sampling.hpp"
#include "search/rjmcmc.hpp"
#include "search/smc.hpp"

namespace shapevo {

namespace {

constexpr double kBig = 1e12;

void readNothing(SectionReader&, SearchSettings&) {}

void readSmc(SectionReader& r, SearchSettings& s) {
    r.number("smc_temperature", s.smc.temperature, 1e-300, kBig, "SMC and SOSMC: weights are exp(fitness gain / T)");
}

void readRjmcmc(SectionReader& r, SearchSettings& s) {
    RjmcmcSettings& m = s.rjmcmc;
    r.number("rjmcmc_jump_probability", m.jumpProbability, 0, 1,
             "RJMCMC: probability that a proposal is a jump (regrow) rather than a diffusion");
    r.count("rjmcmc_diffusion_alters", m.diffusionAlters, 1, 1e6, "RJMCMC: alter mutations per diffusion move");
    r.number("rjmcmc_temperature", m.temperature, 1e-300, kBig,
             "RJMCMC: the coldest chain's temperature at generation 1");
    r.number("rjmcmc_temperature_ratio", m.temperatureRatio, 1, kBig,
             "RJMCMC: hottest chain's temperature / coldest chain's");
    r.number("rjmcmc_annealing", m.annealing, 1, kBig,
             "RJMCMC: every temperature is divided by this once per rjmcmc_annealing_interval generations (1: no "
             "annealing)");
    r.count("rjmcmc_annealing_interval", m.annealingInterval, 1, 1e9, "RJMCMC: generations between annealing steps");
    r.number("rjmcmc_depth_bias", m.depthBias, 1e-6, 1,
             "RJMCMC: a jump picks a non-terminal at depth d with weight bias^d (1: uniform; smaller favours the root)");
    r.flag("rjmcmc_delayed_rejection", m.delayedRejection,
           "RJMCMC: try a second proposal after a rejected jump (off in the authors' code)");
}

void readHybrid(SectionReader& r, SearchSettings& s) {
    HybridSettings& h = s.hybrid;
    r.count("hybrid_islands", h.islands, 1, 1e6, "hybrid: sub-populations of one process (at most population / 2)");
    r.count("hybrid_migration_interval", h.migrationInterval, 0, 1e9,
            "hybrid: generations between migrations among its sub-populations (0: never)");
    r.count("hybrid_restart_interval", h.restartInterval, 0, 1e9,
            "hybrid: generations between restarts of the worst sub-population (0: never)");
    r.count("hybrid_scout_interval", h.scoutInterval, 0, 1e9,
            "hybrid: generations a scout sub-population (the last, with 3 or more) evolves alone before it replaces "
            "the worst if better and starts again (0: no scout)");
    r.number("hybrid_mutation", h.mutation, 0, 1,
             "hybrid: probability that a pair is mutated rather than crossed over");
    r.number("hybrid_regrow", h.regrow, 0, 1, "hybrid: share of mutations that regrow a subtree");
    r.number("hybrid_refine", h.refine, 0, 1,
             "hybrid: local moves of the elites per generation, per sub-population member");
    r.number("hybrid_refine_jump", h.refineJump, 0, 1, "hybrid: probability that a local move is a regrow");
    r.number("hybrid_refine_nudge", h.refineNudge, 0, 1,
             "hybrid: on odd sub-populations, probability that a local move that is not a regrow is a nudge (else an "
             "alter)");
}

std::unique_ptr<SearchMethod> makeHybrid(const SearchSettings& s, const PopulationSettings& p, const GaSettings& ga,
                                         const GenomeFamily& family, const GenomeLimits& limits, std::uint64_t seed) {
    return std::make_unique<HybridSearch>(family, s.hybrid, p, ga, limits, seed);
}
std::unique_ptr<SearchMethod> makeGa(const SearchSettings&, const PopulationSettings& p, const GaSettings& ga,
                                     const GenomeFamily& family, const GenomeLimits& limits, std::uint64_t seed) {
    return std::make_unique<GeneticAlgorithm>(family, p, ga, limits, seed);
}
std::unique_ptr<SearchMethod> makeRandom(const SearchSettings&, const PopulationSettings& p, const GaSettings&,
                                         const GenomeFamily& family, const GenomeLimits& limits, std::uint64_t seed) {
    return std::make_unique<RandomSampling>(family, p, limits, seed);
}
// needsTree: makeSearchMethod has checked that treeGrammar() is not null
std::unique_ptr<SearchMethod> makeSmc(const SearchSettings& s, const PopulationSettings& p, const GaSettings&,
                                      const GenomeFamily& family, const GenomeLimits& limits, std::uint64_t seed) {
    return std::make_unique<Smc>(*family.treeGrammar(), s.smc, p.population, limits, GrowthOrder::Chromosome, seed);
}
std::unique_ptr<SearchMethod> makeSosmc(const SearchSettings& s, const PopulationSettings& p, const GaSettings&,
                                        const GenomeFamily& family, const GenomeLimits& limits, std::uint64_t seed) {
    return std::make_unique<Smc>(*family.treeGrammar(), s.smc, p.population, limits, GrowthOrder::Random, seed);
}
std::unique_ptr<SearchMethod> makeRjmcmc(const SearchSettings& s, const PopulationSettings& p, const GaSettings&,
                                         const GenomeFamily& family, const GenomeLimits& limits, std::uint64_t seed) {
    return std::make_unique<Rjmcmc>(*family.treeGrammar(), s.rjmcmc, p, limits, seed);
}

// populationCopies: GA pop_ + next_; SMC pop_ + next_; RJMCMC pop_ + proposals_ + second_ + star_.
// hybrid: pop_ + next_ (+ a few refine proposals). random: pop_ + next_ + merged_.
// needsTree: SMC and SOSMC decide a tree's child positions one by one (genome/sequential_growth.hpp),
// RJMCMC regrows below a non-terminal with a reversible pairing of the tree's genes (genome/regrow.hpp).
constexpr std::array<SearchMethodEntry, 6> kMethods{{
    {"hybrid", "GA islands in one process, mostly mutation, elites refined by local moves (the default)", readHybrid,
     makeHybrid, 3, false},
    {"ga", "genetic algorithm on whole derivations (ShapeGenetics)", readNothing, makeGa, 2, false},
    {"smc", "sequential Monte Carlo, growing in chromosome order (Ritchie et al. 2015)", readSmc, makeSmc, 2, true},
    {"sosmc", "stochastically-ordered SMC, growing in random order (Ritchie et al. 2015)", readSmc, makeSosmc, 2, true},
    {"rjmcmc", "reversible-jump MCMC with parallel tempering (Talton et al. 2011)", readRjmcmc, makeRjmcmc, 4, true},
    {"random", "random sampling: the best of as many random derivations (the baseline to beat)", readNothing, makeRandom, 3,
     false},
}};

}  // namespace

std::span<const SearchMethodEntry> searchMethods() { return kMethods; }

const SearchMethodEntry* findSearchMethod(std::string_view name) {
    for (const SearchMethodEntry& e : kMethods)
        if (e.name == name) return &e;
    return nullptr;
}

std::string searchMethodNames() {
    return wordList(kMethods.size(), [](std::size_t i) { return "\"" + std::string(kMethods[i].name) + "\""; });
}

std::string methodFamilyProblem(const SearchSettings& search, const GenomeFamily& family) {
    const SearchMethodEntry* e = findSearchMethod(search.method);
    if (!e || !e->needsTree || family.treeGrammar()) return "";
    std::vector<std::string> able;  // quoted: "hybrid"
    for (const SearchMethodEntry& m : kMethods)
        if (!m.needsTree) able.push_back('"' + std::string(m.name) + '"');
    return "search.method = \"" + std::string(e->name) + "\" needs a derivation-tree grammar (a " + grammarExtensions() +
           " file); " + std::string(family.name()) + " genomes run with " +
           wordList(able.size(), [&](std::size_t i) { return able[i]; });
}

std::unique_ptr<SearchMethod> makeSearchMethod(const SearchSettings& search, const PopulationSettings& population,
                                               const GaSettings& ga, const GenomeFamily& family,
                                               const GenomeLimits& limits, std::uint64_t seed,
                                               const std::string& configFile) {
    const SearchMethodEntry* e = findSearchMethod(search.method);
    if (!e) throw std::invalid_argument("no search method named \"" + search.method + "\" (expected " + searchMethodNames() + ")");
    if (const std::string problem = methodFamilyProblem(search, family); !problem.empty())
        throw InputError(configFile, "search.method", problem);
    return e->make(search, population, ga, family, limits, seed);
}

}  // namespace shapevo

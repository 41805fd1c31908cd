// SearchSettings: which search method an island runs (config [search] method = a name from the
// table in search/search_methods.cpp) and the settings of the methods; GaSettings: the genetic
// algorithm's operators ([ga]), used by the GA and the hybrid. The sizes every method uses
// (population, generations, initial lengths) are PopulationSettings (search/population_settings.hpp),
// also read from [ga]. Defaults and their sources are in docs/search-methods.md.
#pragma once
#include <cstdint>
#include <string>

namespace shapevo {

/// SMC and SOSMC (Ritchie et al. 2015): particles grow one geometric object per generation and
/// are resampled with weights exp((f_new - f_old) / temperature).
struct SmcSettings {
    double temperature = 0.01;  ///< fitness units per factor e of particle weight
};

/// RJMCMC (Talton et al. 2011): one chain per individual, target prior(x) * exp(f(x) / T).
struct RjmcmcSettings {
    double jumpProbability = 0.5;       ///< jump (cut + regrow) vs diffusion (alter), per proposal
    std::uint32_t diffusionAlters = 1;  ///< alter mutations in one diffusion proposal
    double temperature = 0.002;         ///< coldest chain's temperature at generation 1
    /// hottest / coldest temperature: a move with 70 % acceptance in the hottest chain has 1 % in
    /// the coldest (ShapeGenetics §8): ln(0.01) / ln(0.7)
    double temperatureRatio = 12.911;
    double annealing = 1.1;                 ///< every temperature is divided by this ...
    std::uint32_t annealingInterval = 10;   ///< ... once per this many generations (1 = every sweep)
    double depthBias = 1.0;                 ///< non-terminal selection weight depth_bias^depth
    bool delayedRejection = false;          ///< second stage after a rejected jump (Green & Mira)
};

/// The genetic algorithm's operators ([ga]), used by the GA and the hybrid search; the sizes
/// every method uses are PopulationSettings.
struct GaSettings {
    std::uint32_t elitism = 30;
    std::uint32_t tournament = 10;
    double mutation = 0.30;                             ///< probability that a pair is mutated, not crossed
    double growWeight = 1.0, cutWeight = 1.0, alterWeight = 1.0;  ///< split of the mutations
    int crossoverRetries = 3;
};

/// The hybrid search (search/hybrid_search.hpp): GA islands inside one process whose elites are
/// refined by local moves. [ga] gives elitism, tournament, grow/cut/alter weights and crossover
/// retries (GaSettings), and the sizes (PopulationSettings).
struct HybridSettings {
    std::uint32_t islands = 4;            ///< sub-populations of one process (population split evenly)
    std::uint32_t migrationInterval = 10; ///< generations between migrations around the in-process ring
    std::uint32_t restartInterval = 100;  ///< generations between restarts of the worst island (0: never)
    /// Generations a scout island (the last, with 3 or more islands) evolves alone before it is
    /// adopted (if better than the worst other island) and starts again (0: no scout).
    std::uint32_t scoutInterval = 400;
    double mutation = 0.6;                ///< probability that a pair is mutated, not crossed
    double regrow = 0.25;                 ///< share of mutations that regrow a subtree (the rest: [ga]'s weights)
    double refine = 0.5;                  ///< local moves of elites per generation, per island member
    double refineJump = 0.5;              ///< probability that a local move is a regrow
    double refineNudge = 1.0;             ///< odd islands: probability that a local move that is not a regrow is a
                                          ///< nudge (else an alter; even islands always alter)
};

struct SearchSettings {
    std::string method = "hybrid";  ///< a name in searchMethods() (search/search_methods.hpp)
    bool diagnostics = false;   ///< write diagnostics.csv (run/diagnostics_log.hpp)
    SmcSettings smc;
    RjmcmcSettings rjmcmc;
    HybridSettings hybrid;
};

}  // namespace shapevo

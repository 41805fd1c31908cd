// PopulationSettings: the sizes every search method uses (hybrid, GA, SMC, SOSMC, RJMCMC) — how
// many individuals (particles, chains) an island keeps, how many generations a run lasts, and
// how long a grown initial individual is. Read from [ga] for compatibility with existing configs
// (search/search_sections.cpp); the island loop, the memory estimate and the progress line read
// them here. Defaults and their sources are in docs/search-methods.md.
#pragma once
#include <cstdint>

namespace shapevo {

/// PopulationSettings::generations of a run limited by its wall time alone (run/run_limit.hpp).
inline constexpr std::uint32_t kNoGenerationLimit = UINT32_MAX;

struct PopulationSettings {
    std::uint32_t population = 200;   ///< individuals of one island (particles for SMC, chains for RJMCMC)
    std::uint32_t generations = 50;   ///< a run stops after this many generations (kNoGenerationLimit: none)
    std::uint32_t initialGenesMin = 2, initialGenesMax = 40;  ///< initial length drawn uniformly in between
};

}  // namespace shapevo

// The search methods: one table, one entry per method (its config name, a one-line summary, the
// reader of its [search] keys, its factory). Every factory gets the sizes (PopulationSettings)
// and the GA's operators (GaSettings; only the GA and the hybrid use them). Config, CLI help,
// tests and benchmarks all read this table, so a new method is its class plus one entry in
// search_methods.cpp.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "base/section_reader.hpp"
#include "search/population_settings.hpp"
#include "search/search_method.hpp"

namespace shapevo {

struct SearchMethodEntry {
    std::string_view name;     ///< the value of search.method in a config
    std::string_view summary;  ///< one line for --help and messages
    /// Reads the method's own keys of [search] into `s` (those it does not know stay unread).
    void (*readSettings)(SectionReader& search, SearchSettings& s);
    std::unique_ptr<SearchMethod> (*make)(const SearchSettings& search, const PopulationSettings& population,
                                          const GaSettings& ga, const Grammar& g, const GenomeLimits& limits,
                                          std::uint64_t seed);
    /// Whole populations of chromosomes the method keeps (the memory estimate, memory_estimate.hpp).
    std::uint32_t populationCopies = 2;
};

/// The method `search.method` names (@throw std::invalid_argument if none), seeded with `seed`;
/// `population` gives population size and initial lengths to every method, `ga` elitism,
/// tournament, mutation and operator weights to the GA and the hybrid.
std::unique_ptr<SearchMethod> makeSearchMethod(const SearchSettings& search, const PopulationSettings& population,
                                               const GaSettings& ga, const Grammar& g, const GenomeLimits& limits,
                                               std::uint64_t seed);

/// Every method, the default ("hybrid") first.
std::span<const SearchMethodEntry> searchMethods();

/// The entry named `name`, or nullptr.
const SearchMethodEntry* findSearchMethod(std::string_view name);

/// The names for a message: "\"hybrid\", \"ga\", \"smc\", \"sosmc\" or \"rjmcmc\"".
std::string searchMethodNames();

}  // namespace shapevo

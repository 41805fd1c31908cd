// The search methods: one table, one entry per method (its config name, a one-line summary, the
// reader of its [search] keys, its factory, whether it needs a derivation tree). Every factory
// gets the sizes (PopulationSettings), the GA's operators (GaSettings; only the GA and the hybrid
// use them) and the model family (genome/genome_family.hpp): the GA and the hybrid breed any
// family through its operators; SMC, SOSMC and RJMCMC grow and regrow a tree's structure and run
// only a family with a tree grammar. Config, CLI help, tests and benchmarks all read this table,
// so a new method is its class plus one entry in search_methods.cpp.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "base/section_reader.hpp"
#include "genome/genome_family.hpp"
#include "search/population_settings.hpp"
#include "search/search_method.hpp"

namespace shapevo {

struct SearchMethodEntry {
    std::string_view name;     ///< the value of search.method in a config
    std::string_view summary;  ///< one line for --help and messages
    /// Reads the method's own keys of [search] into `s` (those it does not know stay unread).
    void (*readSettings)(SectionReader& search, SearchSettings& s);
    /// Makes the method for `family` (one with a tree grammar if needsTree).
    std::unique_ptr<SearchMethod> (*make)(const SearchSettings& search, const PopulationSettings& population,
                                          const GaSettings& ga, const GenomeFamily& family, const GenomeLimits& limits,
                                          std::uint64_t seed);
    /// Whole populations of chromosomes the method keeps (the memory estimate, memory_estimate.hpp).
    std::uint32_t populationCopies = 2;
    /// Whether it works on a derivation tree's structure (GenomeFamily::treeGrammar() not null).
    bool needsTree = false;
};

/// The method `search.method` names (@throw std::invalid_argument if none), seeded with `seed`,
/// for genomes of `family`; `population` gives population size and initial lengths to every
/// method, `ga` elitism, tournament, mutation and operator weights to the GA and the hybrid.
/// @throw InputError(configFile, "search.method", ...) if the method needs a tree and `family`
/// has no tree grammar (methodFamilyProblem).
std::unique_ptr<SearchMethod> makeSearchMethod(const SearchSettings& search, const PopulationSettings& population,
                                               const GaSettings& ga, const GenomeFamily& family,
                                               const GenomeLimits& limits, std::uint64_t seed,
                                               const std::string& configFile);

/// Empty if the method `search.method` names can search `family`'s genomes; otherwise why not,
/// naming the method, the config key and the methods that can, e.g. `search.method = "smc" needs a
/// derivation-tree grammar (.grammar, .rule, .pcg); a graph derivation runs with "hybrid" or "ga"`.
std::string methodFamilyProblem(const SearchSettings& search, const GenomeFamily& family);

/// Every method, the default ("hybrid") first.
std::span<const SearchMethodEntry> searchMethods();

/// The entry named `name`, or nullptr.
const SearchMethodEntry* findSearchMethod(std::string_view name);

/// The names for a message: "\"hybrid\", \"ga\", \"smc\", \"sosmc\" or \"rjmcmc\"".
std::string searchMethodNames();

}  // namespace shapevo

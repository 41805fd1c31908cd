// run/memory_check and search/memory_estimate: the documented estimate (population x (copies + 2)
// x (sizeof(Chromosome) + 8 + max_genes x 4 x the largest gene's words)) against the memory
// given; a run that does not fit is an InputError with the estimate, one that fits passes.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "run/config_file.hpp"
#include "run/memory_check.hpp"
#include "search/memory_estimate.hpp"
#include "search/search_methods.hpp"

namespace shapevo {
namespace {

constexpr std::uint64_t kGiB = 1024ull * 1024 * 1024;

struct Spaceship {
    RunSettings s = loadConfig(test::sourcePath("configs/spaceship.toml"));
    Grammar g = loadGrammar(s.grammarPath);
    TreeFamily family{g};
};

TEST(MemoryCheck, TheEstimateIsTheDocumentedFormula) {
    Spaceship x;
    std::uint32_t largest = 0;
    for (const Rule& r : x.g.rules) largest = std::max(largest, r.geneWords());
    for (const SearchMethodEntry& m : searchMethods()) {
        x.s.search.method = std::string(m.name);
        const MemoryEstimate e = searchMemoryEstimate(x.family, x.s.search, x.s.population, x.s.limits);
        EXPECT_EQ(e.copies, m.populationCopies + 2) << m.name;
        EXPECT_EQ(e.largestGeneWords, largest);
        EXPECT_DOUBLE_EQ(e.bytes, 200.0 * e.copies * (sizeof(Chromosome) + 8.0 + 100.0 * 4.0 * largest)) << m.name;
    }
}

TEST(MemoryCheck, ARunThatDoesNotFitIsRefusedWithTheEstimate) {
    Spaceship x;
    EXPECT_NO_THROW(requireMemoryFits(x.s, x.family, 1, kGiB)) << "the demo fits in 1 GiB";
    x.s.population.population = 1'000'000;  // 1e6 x 4 x (40 + 100 x 4 x W) bytes: several GiB
    try {
        requireMemoryFits(x.s, x.family, 1, kGiB);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), x.s.configPath);
        EXPECT_EQ(e.where(), "ga.population");
        for (const char* part : {"ga.population = 1000000 with genome.max_genes = 100 may need ", "population 1000000 x 5 copies",
                                 "more than the 1.0 GiB this process may use"})
            EXPECT_NE(e.message().find(part), std::string::npos) << part << " in " << e.what();
    }
    EXPECT_NO_THROW(requireMemoryFits(x.s, x.family, 1, 0)) << "unknown memory: no check";
}

TEST(MemoryCheck, IslandsOnOneMachineAddUp) {
    Spaceship x;
    const double one = searchMemoryEstimate(x.family, x.s.search, x.s.population, x.s.limits).bytes;
    const auto fitsOnce = std::uint64_t(one * 1.5);
    EXPECT_NO_THROW(requireMemoryFits(x.s, x.family, 1, fitsOnce));
    EXPECT_THROW(requireMemoryFits(x.s, x.family, 2, fitsOnce), InputError);
}

TEST(MemoryCheck, UsableMemoryIsKnownOnLinux) {
    const std::uint64_t m = usableMemoryBytes();
    EXPECT_GT(m, 64ull * 1024 * 1024);
}

}  // namespace
}  // namespace shapevo

// run/config_file: one config is read once and each stage gets its own part (search method and
// its keys from the method table, migration, checkpoint, target); a method name outside the table
// is an error listing the table's names.
#include <gtest/gtest.h>

#include <string>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "run/config_file.hpp"
#include "search/search_methods.hpp"

namespace shapevo {
namespace {

const std::string kSpaceship = test::sourcePath("configs/spaceship.toml");

TEST(ConfigFile, EachStageGetsItsOwnPart) {
    const RunSettings s = loadConfig(kSpaceship, {"search.method=rjmcmc", "search.rjmcmc_temperature=0.5",
                                                  "search.smc_temperature=0.25", "migration.interval=7",
                                                  "checkpoint.keep=9", "ga.population=60"});
    EXPECT_EQ(s.search.method, "rjmcmc");
    EXPECT_EQ(s.search.rjmcmc.temperature, 0.5);
    EXPECT_EQ(s.search.smc.temperature, 0.25) << "every method's keys are read, whichever runs";
    EXPECT_EQ(s.migration.interval, 7u);
    EXPECT_EQ(s.checkpoint.keep, 9);
    EXPECT_EQ(s.population.population, 60u);
    EXPECT_EQ(s.target->kind().name, "volume");
    EXPECT_FALSE(s.target->inputFiles().empty());
}

TEST(ConfigFile, EveryMethodOfTheTableIsAcceptedByName) {
    for (const SearchMethodEntry& m : searchMethods()) {
        const RunSettings s = loadConfig(kSpaceship, {"search.method=" + std::string(m.name)});
        EXPECT_EQ(s.search.method, m.name);
    }
}

TEST(ConfigFile, AnUnknownMethodIsAnErrorListingTheTable) {
    try {
        loadConfig(kSpaceship, {"search.method=annealing"});
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        for (const SearchMethodEntry& m : searchMethods())
            EXPECT_NE(what.find("\"" + std::string(m.name) + "\""), std::string::npos) << what;
        EXPECT_NE(what.find("annealing"), std::string::npos) << what;
    }
}

TEST(ConfigFile, AMethodKeyOfTheWrongTypeNamesTheKey) {
    try {
        loadConfig(kSpaceship, {"search.rjmcmc_delayed_rejection=7"});
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("search.rjmcmc_delayed_rejection must be true or false"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace shapevo

// SpaceshipFixture: the shipped spaceship grammar scored against its reachable volume target, the
// scene the search tests run their methods on.
#pragma once
#include "../test_support.hpp"
#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "score/volume/volume_scorer.hpp"

namespace shapevo::test {

struct SpaceshipFixture {
    Grammar grammar = loadGrammar(sourcePath("grammars/spaceship.grammar"));
    TreeFamily family{grammar};  ///< the grammar's genome, as the search methods take it
    VolumeTarget target = loadVolumeTarget({{sourcePath("targets/spaceship-reachable.vdb"), false}});
    FitnessSettings fitness;
    VolumeScorer scorer{grammar, target, fitness};
};

}  // namespace shapevo::test

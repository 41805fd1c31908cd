// readGraphSection (graph_section.hpp).
#include "graph/graph_section.hpp"

namespace shapevo::graph {

void readGraphSection(SectionReader& s, DeriveLimits& limits) {
    std::uint64_t steps = std::uint64_t(limits.maxSteps);
    s.wholeNumber64("max_steps", steps,
                    "graph grammars: steps per derivation; 0 = the file's options.max_derivations.all (or until no production applies)");
    limits.maxSteps = std::int64_t(steps);
    std::uint32_t elements = std::uint32_t(limits.maxElements);
    s.count("max_elements", elements, 1, 100'000'000,
            "graph grammars: a derivation that passes this many vertices + edges stops with an error naming the step");
    limits.maxElements = elements;
    std::uint32_t matches = std::uint32_t(limits.maxMatches);
    s.count("max_matches", matches, 1, 100'000'000,
            "graph grammars: matches one production may hold at once; more is an error naming the production (a mother graph of "
            "unconstrained vertices matches in combinatorially many ways)");
    limits.maxMatches = matches;
    std::uint32_t search = std::uint32_t(limits.maxSearchSteps);
    s.count("max_search_steps", search, 1, 4'000'000'000.0,
            "graph grammars: element bindings one step's matching may try; more is an error naming the production");
    limits.maxSearchSteps = search;
    s.flag("fix_geometric_ordering", limits.fixGeometricOrdering,
           "graph grammars: compare a vertex with the nearest mapped vertex after it along each axis (the original compares with the "
           "farthest, which admits more matches); off reproduces the original");
    s.flag("draw_option_once", limits.drawOptionOnce,
           "graph grammars: one weighted draw of the option both filters the matches (generation: oldest) and is applied (the "
           "original draws twice); off reproduces the original");
}

}  // namespace shapevo::graph

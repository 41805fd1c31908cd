// OperatorOutcomes: where each operator's children land against their parents (better, equal,
// worse fitness), and how many distinct parents selection picked: the figures that show whether a
// search is still making progress or has stalled (search.diagnostics, docs/search-diagnosis.md).
// Counts are sums since the run (or resume) began; a reader takes differences.
#pragma once
#include <array>
#include <cstdint>

namespace shapevo {

struct OperatorOutcomes {
    enum Op { Grow, Cut, Alter, Crossover, Regrow, Refine, Copy, kOps };  ///< Copy: no operator applied (all refused)
    enum Result { Better, Equal, Worse, kResults };
    /// regrow: a subtree cut and grown anew (the hybrid search's mutation); refine: a local move of
    /// an elite kept only if not worse (the hybrid search, search/hybrid_search.hpp)
    static constexpr const char* kOpNames[kOps] = {"grow", "cut", "alter", "crossover", "regrow", "refine", "copy"};
    static constexpr const char* kResultNames[kResults] = {"better", "equal", "worse"};

    std::array<std::array<std::uint64_t, kResults>, kOps> children{};  ///< [operator][result]
    std::uint64_t parentsPicked = 0;    ///< selections made
    std::uint64_t distinctParents = 0;  ///< of them, distinct individuals per generation (summed)

    void count(Op op, double child, double parent) {
        ++children[op][child > parent ? Better : child == parent ? Equal : Worse];
    }
};

}  // namespace shapevo

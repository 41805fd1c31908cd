// KeyedDraws: a keyed DrawSource (draw_source.hpp) — every decision of a derivation answered by
// its key: an override's word where one is given, otherwise defaultWord(seed, key) with the seed
// of the event the decision is made in. An event's seed is inherited from its lineage parent
// unless an override gives its salt key a seed of its own (so one override draws a whole
// subtree anew). It can record what a derivation asked — every event (its key, salt key, seed,
// parent event) and every decision (its key, its event) — for the genome's operators, which pick
// what to change from it.
// Overrides are 4 words each — key low, key high, word low, word high — in ascending key order
// (the graph genome's layout, genome/families/graph_genome.hpp); lookups are binary searches.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "graph/draw_source.hpp"

namespace shapevo::graph {

inline constexpr std::size_t kOverrideWords = 4;

struct DecisionRecord {
    struct Event {
        std::uint64_t eventKey = 0, saltKey = 0, seed = 0;
        std::uint32_t parent = 0;  ///< the lineage parent's event (0: the start)
    };
    struct Decision {
        std::uint64_t key = 0;
        std::uint32_t event = 0;
        DrawPurpose purpose = DrawPurpose::Match;  ///< Match: a firing level or a pick among the oldest
    };
    std::vector<Event> events;        ///< index = event (step; 0 = the start)
    std::vector<Decision> decisions;  ///< in the order they were made (a key may repeat)
    void clear() {
        events.clear();
        decisions.clear();
    }
};

/// The key of override `i` of `overrides`, and its word.
inline std::uint64_t overrideKey(std::span<const std::uint32_t> overrides, std::size_t i) {
    return std::uint64_t(overrides[kOverrideWords * i]) | std::uint64_t(overrides[kOverrideWords * i + 1]) << 32;
}
inline std::uint64_t overrideWord(std::span<const std::uint32_t> overrides, std::size_t i) {
    return std::uint64_t(overrides[kOverrideWords * i + 2]) | std::uint64_t(overrides[kOverrideWords * i + 3]) << 32;
}
/// The index of the override of `key`, or -1.
std::ptrdiff_t findOverride(std::span<const std::uint32_t> overrides, std::uint64_t key);

class KeyedDraws final : public DrawSource {
public:
    /// `overrides` must outlive the derivation; `record` (may be null) is cleared and filled.
    KeyedDraws(std::uint64_t seed, std::span<const std::uint32_t> overrides, DecisionRecord* record = nullptr);

    double uniform(DrawPurpose purpose) override { return wordUniform(next(purpose)); }
    std::uint64_t below(std::uint64_t n, DrawPurpose purpose) override { return wordBelow(next(purpose), n); }
    bool keyed() const override { return true; }
    std::uint64_t rootSeed() override { return seed_; }
    std::uint64_t word(std::uint64_t key, const DrawContext& context, DrawPurpose purpose) override;
    std::uint64_t eventSeed(std::uint64_t eventKey, std::uint64_t saltKey, std::uint64_t inherited, std::uint32_t event,
                            std::uint32_t parentEvent) override;
    void enterContext(std::uint64_t key, const DrawContext& context) override {
        contextKey_ = key;
        context_ = context;
        counter_ = 0;
    }

private:
    std::uint64_t next(DrawPurpose purpose);

    std::uint64_t seed_;
    std::span<const std::uint32_t> overrides_;
    DecisionRecord* record_;
    std::uint64_t contextKey_ = 0, counter_ = 0;
    DrawContext context_;
};

}  // namespace shapevo::graph

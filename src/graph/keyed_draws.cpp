// KeyedDraws: overrides by binary search, defaults from the context's seed (keyed_draws.hpp).
#include "graph/keyed_draws.hpp"

#include "graph/lineage_key.hpp"

namespace shapevo::graph {

std::ptrdiff_t findOverride(std::span<const std::uint32_t> overrides, std::uint64_t key) {
    std::size_t lo = 0, hi = overrides.size() / kOverrideWords;
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        const std::uint64_t k = overrideKey(overrides, mid);
        if (k == key) return std::ptrdiff_t(mid);
        if (k < key) lo = mid + 1;
        else hi = mid;
    }
    return -1;
}

KeyedDraws::KeyedDraws(std::uint64_t seed, std::span<const std::uint32_t> overrides, DecisionRecord* record)
    : seed_(seed), overrides_(overrides), record_(record) {
    context_ = DrawContext{seed, 0};
    if (record_) {
        record_->clear();
        record_->events.push_back(DecisionRecord::Event{0, 0, seed, 0});
    }
}

std::uint64_t KeyedDraws::word(std::uint64_t key, const DrawContext& context, DrawPurpose purpose) {
    if (record_) record_->decisions.push_back(DecisionRecord::Decision{key, context.event, purpose});
    const std::ptrdiff_t i = findOverride(overrides_, key);
    return i >= 0 ? overrideWord(overrides_, std::size_t(i)) : defaultWord(context.seed, key);
}

std::uint64_t KeyedDraws::eventSeed(std::uint64_t eventKey, std::uint64_t saltKey, std::uint64_t inherited, std::uint32_t event,
                                    std::uint32_t parentEvent) {
    const std::ptrdiff_t i = findOverride(overrides_, saltKey);
    const std::uint64_t seed = i >= 0 ? overrideWord(overrides_, std::size_t(i)) : inherited;
    if (record_) {
        if (record_->events.size() <= event) record_->events.resize(std::size_t(event) + 1);
        record_->events[event] = DecisionRecord::Event{eventKey, saltKey, seed, parentEvent};
    }
    return seed;
}

std::uint64_t KeyedDraws::next(DrawPurpose purpose) { return word(mixKey(contextKey_, counter_++), context_, purpose); }

}  // namespace shapevo::graph

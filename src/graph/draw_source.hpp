// DrawSource: where a derivation's random decisions come from — which production, which option,
// which match, and each random.* draw in an expression. A seeded source (SeededDraws) gives one
// derivation per seed on every machine, drawing in sequence. A keyed source (keyed() true: a
// genome, graph/keyed_draws.hpp) answers each decision by a key naming what it acts on
// (lineage_key.hpp); the derivation then picks events by firing levels instead of sequential
// draws (derive.hpp), so a changed decision changes only its own descendants. Every draw is
// specified here, not by the standard library.
#pragma once
#include <cstdint>

#include "base/random.hpp"

namespace shapevo::graph {

/// What a decision is about, so that a genome can key it (a seeded source ignores it).
enum class DrawPurpose : std::uint8_t { Production, Option, Match, Expression };

/// Where a keyed decision belongs: the event (derivation step, 0 = the start) it is made in, and
/// the seed its default value is drawn with (the event's seed, inherited down the lineage).
struct DrawContext {
    std::uint64_t seed = 0;
    std::uint32_t event = 0;
};

class DrawSource {
public:
    virtual ~DrawSource() = default;
    /// Uniform in [0, 1). A keyed source: the next draw of the current context (enterContext).
    virtual double uniform(DrawPurpose purpose) = 0;
    /// Uniform integer in [0, n); n > 0. A keyed source: the next draw of the current context.
    virtual std::uint64_t below(std::uint64_t n, DrawPurpose purpose) = 0;

    // --- keyed sources only (the derivation calls these only when keyed() is true) ---
    virtual bool keyed() const { return false; }
    /// The seed of the start (the host graph, the global and run variables).
    virtual std::uint64_t rootSeed() { return 0; }
    /// The 64 random bits of decision `key`, made in `context`, about `purpose`.
    virtual std::uint64_t word(std::uint64_t key, const DrawContext& context, DrawPurpose purpose) {
        (void)key, (void)context, (void)purpose;
        return 0;
    }
    /// The seed of event `event` whose salt key is `saltKey`, whose lineage parent has seed
    /// `inherited` and whose parent event is `parentEvent` (a genome may give it a seed of its own).
    virtual std::uint64_t eventSeed(std::uint64_t eventKey, std::uint64_t saltKey, std::uint64_t inherited, std::uint32_t event,
                                    std::uint32_t parentEvent) {
        (void)eventKey, (void)saltKey, (void)event, (void)parentEvent;
        return inherited;
    }
    /// Expression draws from now on are the decisions mixKey(key, n), n = 0, 1, ..., in `context`.
    virtual void enterContext(std::uint64_t key, const DrawContext& context) { (void)key, (void)context; }
};

/// A word's uniform value in [0, 1) (its 53 high bits), and an integer in [0, n) from it.
inline double wordUniform(std::uint64_t w) { return double(w >> 11) * 0x1.0p-53; }
inline std::uint64_t wordBelow(std::uint64_t w, std::uint64_t n) {
    return std::uint64_t((static_cast<unsigned __int128>(w) * n) >> 64);
}

/// The seeded source: xoshiro256** (base/random.hpp).
class SeededDraws final : public DrawSource {
public:
    explicit SeededDraws(std::uint64_t seed) : rng_(seed) {}
    double uniform(DrawPurpose) override { return rng_.uniform(); }
    std::uint64_t below(std::uint64_t n, DrawPurpose) override {
        // Rejection on 64 bits: the values at or above 2^64 mod n are a multiple of n, so exact.
        const std::uint64_t threshold = (0 - n) % n;
        std::uint64_t r;
        do r = rng_.next();
        while (r < threshold);
        return r % n;
    }

private:
    Rng rng_;
};

}  // namespace shapevo::graph

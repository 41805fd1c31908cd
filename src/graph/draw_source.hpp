// DrawSource: where a derivation's random decisions come from — which production, which option,
// which match, and each random.* draw in an expression. A seeded source (SeededDraws) gives one
// derivation per seed on every machine; a genome (issue 42) can answer the same questions, keyed
// by what each decision acts on. Every draw is specified here, not by the standard library.
#pragma once
#include <cstdint>

#include "base/random.hpp"

namespace shapevo::graph {

/// What a decision is about, so that a genome can key it (a seeded source ignores it).
enum class DrawPurpose : std::uint8_t { Production, Option, Match, Expression };

class DrawSource {
public:
    virtual ~DrawSource() = default;
    /// Uniform in [0, 1).
    virtual double uniform(DrawPurpose purpose) = 0;
    /// Uniform integer in [0, n); n > 0.
    virtual std::uint64_t below(std::uint64_t n, DrawPurpose purpose) = 0;
};

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

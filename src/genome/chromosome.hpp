// Chromosome: one derivation tree packed into one contiguous buffer of 32-bit words.
//
// Gene layout (words): [rule id] [parent offset] [child offset x Rule::childOffsets] [params].
// Every offset is relative to the gene's own first word: parent offset < 0 (0 for the root at
// word 0), child offset > 0, 0 = "not expressed", kRefused = "decided not expressed" (SMC).
// Invariant: a parent always comes before its children, so one forward sweep sees parents first.
// Parameters are floats stored bit for bit. A subtree copies with memcpy plus one offset fix per
// gene; the whole chromosome is sent between ranks as bytes.
#pragma once
#include <bit>
#include <climits>
#include <cstdint>
#include <vector>

#include "grammar/grammar.hpp"

namespace shapevo {

inline constexpr std::int32_t kNotExpressed = 0;
inline constexpr std::int32_t kRefused = INT32_MIN;

struct Chromosome {
    std::vector<std::uint32_t> words;
    std::uint32_t genes = 0;

    void clear() {
        words.clear();
        genes = 0;
    }
    bool empty() const { return genes == 0; }
    std::uint32_t size() const { return std::uint32_t(words.size()); }

    std::uint16_t rule(std::uint32_t pos) const { return std::uint16_t(words[pos]); }
    std::int32_t parentOffset(std::uint32_t pos) const { return std::int32_t(words[pos + 1]); }
    std::int32_t child(std::uint32_t pos, std::uint32_t entry) const { return std::int32_t(words[pos + 2 + entry]); }
    void setParentOffset(std::uint32_t pos, std::int32_t v) { words[pos + 1] = std::uint32_t(v); }
    void setChild(std::uint32_t pos, std::uint32_t entry, std::int32_t v) { words[pos + 2 + entry] = std::uint32_t(v); }
    /// First word of the parameter block of the gene at `pos` (rule `r`).
    static std::uint32_t paramWord(std::uint32_t pos, const Rule& r) { return pos + 2 + r.childOffsets; }
    float param(std::uint32_t pos, const Rule& r, std::uint32_t i) const {
        return std::bit_cast<float>(words[paramWord(pos, r) + i]);
    }
    void setParam(std::uint32_t pos, const Rule& r, std::uint32_t i, float v) {
        words[paramWord(pos, r) + i] = std::bit_cast<std::uint32_t>(v);
    }
    bool operator==(const Chromosome&) const = default;
};

/// Limits every operator respects.
struct GenomeLimits {
    std::uint32_t maxGenes = 100;
    /// genome.max_primitives: a derivation stops after this many primitives (geometry/derive.hpp)
    std::uint32_t maxPrimitives = 1u << 18;
};

/// Reusable buffers for the operators, sized on first use; no allocation per gene or per call
/// once warm.
struct GenomeScratch {
    std::vector<std::uint32_t> newPos;  ///< old word position -> new word position (or kGone)
    static constexpr std::uint32_t kGone = UINT32_MAX;
};

}  // namespace shapevo

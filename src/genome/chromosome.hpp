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
#include <memory>
#include <vector>

#include "grammar/grammar.hpp"

namespace shapevo {

inline constexpr std::int32_t kNotExpressed = 0;
inline constexpr std::int32_t kRefused = INT32_MIN;

/// Where a chromosome comes from, for incremental evaluation: a hint, never part of its value
/// (not compared, saved or sent). Set by the Evaluator after scoring (`parent` = what scoring it
/// left for its children, opaque here; nothing changed) and by the operators that know what they changed (one
/// subtree: the gene at `childGene` of the chromosome took the place of the gene at `parentGene`
/// of the model `parent`; either may be kNone: a subtree added where the parent had none, or
/// removed). Any other change (setParam, setChild, setParentOffset: every change goes through
/// them) forgets the lineage, so a lineage with no change always means "equal to `parent`".
struct EvaluatedModel {
    virtual ~EvaluatedModel() = default;
    const void* maker = nullptr;  ///< the scorer that made it (only it reads it)
};
struct Lineage {
    static constexpr std::uint32_t kNone = UINT32_MAX;
    std::shared_ptr<const EvaluatedModel> parent;  ///< null: unknown
    std::uint32_t childGene = kNone, parentGene = kNone;
    bool changed() const { return parent && (childGene != kNone || parentGene != kNone); }
};

struct Chromosome {
    std::vector<std::uint32_t> words;
    std::uint32_t genes = 0;
    Lineage lineage;

    void clear() {
        words.clear();
        genes = 0;
        lineage = {};
    }
    bool empty() const { return genes == 0; }
    std::uint32_t size() const { return std::uint32_t(words.size()); }

    std::uint16_t rule(std::uint32_t pos) const { return std::uint16_t(words[pos]); }
    std::int32_t parentOffset(std::uint32_t pos) const { return std::int32_t(words[pos + 1]); }
    std::int32_t child(std::uint32_t pos, std::uint32_t entry) const { return std::int32_t(words[pos + 2 + entry]); }
    // Every change forgets the lineage (an operator that knows what it changed names it after: noteChange).
    void setParentOffset(std::uint32_t pos, std::int32_t v) {
        forgetLineage();
        words[pos + 1] = std::uint32_t(v);
    }
    void setChild(std::uint32_t pos, std::uint32_t entry, std::int32_t v) {
        forgetLineage();
        words[pos + 2 + entry] = std::uint32_t(v);
    }
    /// First word of the parameter block of the gene at `pos` (rule `r`).
    static std::uint32_t paramWord(std::uint32_t pos, const Rule& r) { return pos + 2 + r.childOffsets; }
    float param(std::uint32_t pos, const Rule& r, std::uint32_t i) const {
        return std::bit_cast<float>(words[paramWord(pos, r) + i]);
    }
    void setParam(std::uint32_t pos, const Rule& r, std::uint32_t i, float v) {
        forgetLineage();
        words[paramWord(pos, r) + i] = std::bit_cast<std::uint32_t>(v);
    }
    /// Whether the gene at `pos` (rule `r`) has an expressed child.
    bool hasChildren(std::uint32_t pos, const Rule& r) const {
        for (std::uint32_t k = 0; k < r.childOffsets; ++k)
            if (child(pos, k) > 0) return true;
        return false;
    }
    void forgetLineage() {
        if (lineage.parent) lineage = {};
    }
    /// Same genes (the lineage is not compared).
    bool operator==(const Chromosome& o) const { return genes == o.genes && words == o.words; }
    /// After an operator changed one subtree of a copy of an evaluated model (see Lineage): give
    /// back the lineage it had before (`before`: the changes forgot it) and name the change, if
    /// the copy was unchanged before; otherwise the lineage becomes unknown.
    void noteChange(Lineage&& before, std::uint32_t childGene, std::uint32_t parentGene) {
        lineage = std::move(before);
        if (lineage.parent && !lineage.changed()) {
            lineage.childGene = childGene;
            lineage.parentGene = parentGene;
        } else {
            lineage = {};
        }
    }
    /// Become a copy of `o`, lineage included, keeping this buffer's capacity.
    void copyFrom(const Chromosome& o) {
        words.assign(o.words.begin(), o.words.end());
        genes = o.genes;
        lineage = o.lineage;
    }
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

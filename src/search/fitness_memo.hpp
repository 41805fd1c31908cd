// FitnessMemo: the fitness of the chromosomes scored most recently, so that a child equal to a
// model already scored (a crossover of two equal parents, a cut that removed what a grow added, an
// elite's copy) takes its fitness instead of being scored again.
//
// Promises:
//  - Exact: an entry is found only for a chromosome whose gene count and every word equal the
//    stored one (compared, not only hashed); fitness is a pure function of the chromosome, so a
//    reused fitness is the one scoring would give. The derive status is kept too, so a duplicate
//    counts its anomaly again (Scorer::countAgain) and anomaly sums do not change.
//  - Bounded: at most `capacity` entries in buckets of four (the least recently used one
//    replaced) holding at most `maxBytes` of chromosome words: past that, entries are freed in
//    turn, and a chromosome of more than a quarter of it is not remembered. An entry's buffer is
//    reused, so inserting allocates nothing once warm (for chromosomes no longer than before).
//  - Deterministic: what is found depends only on the order of find/insert calls, which the
//    Evaluator makes in population order on one thread.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "base/hash.hpp"
#include "genome/chromosome.hpp"
#include "geometry/derive.hpp"

namespace shapevo {

class FitnessMemo {
public:
    struct Entry {
        Chromosome chromosome;
        std::uint64_t hash = 0, used = 0;  ///< used = 0: free
        double fitness = 0;
        DeriveStatus status = DeriveStatus::Complete;
        std::int64_t pending = -1;  ///< >= 0: inserted for the batch index whose score is not known yet
        /// What scoring it left for its children (Lineage::parent), while a model holds it: a
        /// duplicate takes it, so that its children too are scored from their parent.
        std::weak_ptr<const EvaluatedModel> model;
    };

    FitnessMemo(std::size_t capacity, std::size_t maxBytes) : maxBytes_(maxBytes) {
        std::size_t buckets = 1;
        while (buckets * kWays < capacity) buckets *= 2;
        entries_.resize(buckets * kWays);
        mask_ = buckets - 1;
    }

    static std::uint64_t hashOf(const Chromosome& c) {
        return hash64(c.words.data(), c.words.size() * sizeof(std::uint32_t)) ^ c.genes;
    }

    /// The entry holding exactly `c` (hash `h` = hashOf(c)), or null.
    Entry* find(const Chromosome& c, std::uint64_t h) {
        Entry* bucket = &entries_[(h & mask_) * kWays];
        for (std::size_t w = 0; w < kWays; ++w) {
            Entry& e = bucket[w];
            if (e.used != 0 && e.hash == h && e.chromosome.genes == c.genes && e.chromosome.words == c.words) {
                e.used = ++clock_;
                return &e;
            }
        }
        return nullptr;
    }

    /// A new entry for `c` (replacing its bucket's least recently used one), or null when `c` is
    /// too large to remember; fill its fitness and status (or pending) before the next find.
    Entry* insert(const Chromosome& c, std::uint64_t h) {
        const std::size_t need = bytesOf(c.words.size());
        if (need > maxBytes_ / 4) return nullptr;
        Entry* bucket = &entries_[(h & mask_) * kWays];
        Entry* victim = bucket;
        for (std::size_t w = 1; w < kWays && victim->used != 0; ++w)
            if (bucket[w].used < victim->used) victim = &bucket[w];
        held_ -= bytesOf(victim->chromosome.words.capacity());
        if (held_ + std::max(need, bytesOf(victim->chromosome.words.capacity())) > maxBytes_) {
            release(*victim);
            for (std::size_t k = 0; held_ + need > maxBytes_ && k < entries_.size(); ++k) {  // free others in turn
                Entry& e = entries_[sweep_++ % entries_.size()];
                if (&e == victim) continue;
                held_ -= bytesOf(e.chromosome.words.capacity());
                release(e);
            }
        }
        victim->chromosome.words.assign(c.words.begin(), c.words.end());
        held_ += bytesOf(victim->chromosome.words.capacity());
        victim->chromosome.genes = c.genes;
        victim->hash = h;
        victim->used = ++clock_;
        victim->pending = -1;
        victim->model.reset();
        return victim;
    }

    std::size_t capacity() const { return entries_.size(); }
    /// Bytes of chromosome words held (never above maxBytes).
    std::size_t bytesHeld() const { return held_; }

private:
    static std::size_t bytesOf(std::size_t words) { return words * sizeof(std::uint32_t); }
    static void release(Entry& e) {
        std::vector<std::uint32_t>().swap(e.chromosome.words);
        e.used = 0;
        e.pending = -1;
        e.model.reset();
    }

    static constexpr std::size_t kWays = 4;
    std::vector<Entry> entries_;
    std::size_t mask_ = 0, maxBytes_, held_ = 0, sweep_ = 0;
    std::uint64_t clock_ = 0;
};

}  // namespace shapevo

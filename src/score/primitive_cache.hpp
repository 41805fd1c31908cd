// PrimitiveCache: what rasterizing or voxelizing one primitive wrote, kept by the primitive's exact
// numbers, so that a model made mostly of primitives seen before (a child is mostly its parent)
// replays their rows instead of computing them again.
//
// Promises:
//  - Exact: an entry is found only for a primitive whose kind, parameter block (KindParams, byte
//    for byte) and every float of its frame (compared bit for bit) equal those it was stored
//    with; the hash only picks the bucket. What a primitive writes depends on nothing else (the camera or grid is fixed per cache), so a replay writes the
//    very rows a computation would.
//  - Bounded: at most `bytes` of records and entries, taken as needed: the entry table starts at
//    128 KB and grows (x4) while over half full, up to a quarter of `bytes` and to 4x the entries
//    whose records the ring holds; the records' ring starts at 256 KB and grows (x4) to the rest
//    when one lookup in 16 finds records already overwritten, or a primitive does not fit. A few
//    reallocations in all (none once grown), in zero pages (base/zero_pages.hpp).
//  - Records live in one ring: storing overwrites the oldest, and an entry whose records were
//    overwritten is simply not found (a miss, never a wrong answer); records found before a store
//    are checked again (stillHolds) before they are used.
//  - A lookup reads one cache line of its bucket's tags, then only the entry whose tag matches,
//    then the records: drawThroughCache asks for each of these for all of a model's primitives
//    before it waits on any (the waits overlap).
//  - Derived data only: a cold cache gives the same results as a warm one, only slower.
//  - A model larger than it can hold (holds()) is not put through it: its scorer draws it the
//    full way, as fast as without a cache, and says once that the cache is full.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "base/hash.hpp"
#include "base/zero_pages.hpp"
#include "geometry/subtree_memo.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// A primitive's numbers packed without padding (the key of PrimitiveCache; compared bytewise):
/// its kind in one word, its kind's parameter block as it is (KindParams: bytes, every unused one
/// zero, so no kind's parameter can be left out), then the frame's 15 floats.
struct PrimitiveKey {
    static constexpr std::size_t kParamWords = KindParams::kBytes / 4;
    static constexpr std::size_t kWords = 1 + kParamWords + (3 + 9 + 3);
    std::uint32_t words[kWords];
    PrimitiveKey() = default;
    explicit PrimitiveKey(const Primitive& p) {
        words[0] = std::uint32_t(p.kind);
        std::memcpy(&words[1], p.params.bytes, KindParams::kBytes);
        std::memcpy(&words[1 + kParamWords], &p.centre[0], 12);
        std::memcpy(&words[4 + kParamWords], &p.axes[0][0], 36);
        std::memcpy(&words[13 + kParamWords], &p.half[0], 12);
    }
    std::uint64_t hash() const { return quickHash(words, kWords); }
    bool operator==(const PrimitiveKey& o) const { return std::memcmp(words, o.words, sizeof words) == 0; }
};
static_assert(KindParams::kBytes % 4 == 0, "the parameter block is whole words of the key");

/// A subtree's primitives, as found by the derivation's memo (geometry/subtree_memo.hpp): its
/// start, which names its output exactly (the key of a PrimitiveCache of whole subtrees).
struct SubtreeKey {
    std::uint32_t words[SubtreeMemo::Start::kMaxWords];
    std::uint32_t count;
    SubtreeKey() = default;
    explicit SubtreeKey(const SubtreeMemo::Start& s) : count(s.count) {
        std::memcpy(words, s.words, s.count * 4);
        std::memset(words + s.count, 0, sizeof words - s.count * 4);
    }
    /// Equal to the start's own hash (SubtreeMemo::Start::hash), which callers may use instead.
    std::uint64_t hash() const { return quickHash(words, count); }
    bool operator==(const SubtreeKey& o) const { return count == o.count && std::memcmp(words, o.words, count * 4) == 0; }
};

/// Records kept per key (a primitive's exact numbers by default; SubtreeKey for whole subtrees).
template <class Record, class Key = PrimitiveKey>
class PrimitiveCache {
public:
    /// What a lookup finds: the records in the order they were written, and the number stored with them.
    struct Found {
        std::span<const Record> records;
        std::uint64_t extra = 0;
        std::uint64_t at = 0;  ///< where the records lie in the ring (stillHolds)
    };
    struct Stats {
        std::uint64_t hits = 0, misses = 0, stored = 0, tooLarge = 0;
    };

    /// About `bytes` in all (at least a small minimum): up to a quarter for entries, the rest for
    /// records; both start small and grow as the header says, so a short run touches little memory.
    explicit PrimitiveCache(std::size_t bytes) {
        bytes = std::max<std::size_t>(bytes, 64 * 1024);
        maxBuckets_ = 1;
        while (maxBuckets_ * 2 * sizeof(Bucket) <= bytes / 4) maxBuckets_ *= 2;
        ringMax_ = std::max<std::size_t>(1, (bytes - maxBuckets_ * sizeof(Bucket)) / sizeof(Record));
        growRing(std::min(ringMax_, kFirstRingBytes / sizeof(Record)));
        resize(std::min<std::size_t>(maxBuckets_, kFirstBuckets));
    }

    /// Bring the tags of the bucket of hash `h` towards the cache (looking up many keys: prefetch
    /// them all first, then prefetchEntry() them all, then find()).
    void prefetch(std::uint64_t h) const { __builtin_prefetch(&table_[h & mask_]); }
    /// Once its tags are at hand: bring the entry whose tag is `h`, if any, towards the cache.
    void prefetchEntry(std::uint64_t h) const {
        const Bucket& b = table_[h & mask_];
        for (std::size_t w = 0; w < kWays; ++w)
            if (b.hash[w] == h) {
                const char* const e = reinterpret_cast<const char*>(&b.entry[w]);
                for (std::size_t at = 0; at < sizeof(Entry); at += 64) __builtin_prefetch(e + at);
                __builtin_prefetch(e + sizeof(Entry) - 1);  // (an entry may straddle one line more)
                return;
            }
    }

    /// The records stored for `key` (hash `h` = key.hash()) into `out`; false if there are none.
    bool find(const Key& key, std::uint64_t h, Found& out) {
        Bucket& b = table_[h & mask_];
        for (std::size_t w = 0; w < kWays; ++w) {
            if (b.hash[w] != h || b.count[w] == 0) continue;
            Entry& e = b.entry[w];
            if (!(e.key == key)) continue;
            if (!live(b.count[w], e.at)) {  // seen, but its records were overwritten: the ring may be too small
                ++stale_;
                continue;
            }
            e.used = ++clock_;
            out.records = b.count[w] == kEmpty ? std::span<const Record>()
                                               : std::span<const Record>(&ring_[e.at % ringSize_], b.count[w]);
            out.extra = e.extra;
            out.at = e.at;
            ++stats_.hits;
            return true;
        }
        ++stats_.misses;
        return false;
    }

    /// Whether the records `found` (by find()) are still there: no store() since overwrote them
    /// or replaced the ring.
    bool stillHolds(const Found& found) const {
        return found.records.empty() || (found.at >= ringStart_ && head_ - found.at <= ringSize_);
    }

    // (find() counts lookups as hits + misses; store() grows the ring when one in 16 lookups since
    // the ring last grew and wrapped found records already overwritten, or a primitive did not fit.)

    /// Store `records` (and `extra`) for `key`, replacing the least recently used entry of its
    /// bucket. A primitive with more records than a quarter of the ring is not stored.
    void store(const Key& key, std::uint64_t h, std::span<const Record> records, std::uint64_t extra) {
        const std::size_t n = records.size();
        const bool wantsMore = n > ringSize_ / 4 || (head_ - ringStart_ > ringSize_ &&
                                                      stale_ * 16 > stats_.hits + stats_.misses - lookupsAtGrowth_);
        if (wantsMore && ringSize_ < ringMax_) growRing(std::min(ringMax_, std::max(ringSize_ * 4, n * 4)));
        else if (wantsMore) full_ = true;
        const std::size_t size = ringSize_;
        if (n > size / 4) {
            ++stats_.tooLarge;
            return;
        }
        // Contiguous in the ring: skip its tail when the records would wrap.
        if (n > 0 && head_ % size + n > size) head_ += size - head_ % size;
        const std::uint64_t at = head_;
        head_ += n;
        if (n > 0) std::memcpy(&ring_[at % size], records.data(), n * sizeof(Record));
        Bucket& b = table_[h & mask_];
        std::size_t victim = 0;
        for (std::size_t w = 0; w < kWays; ++w) {
            if (b.count[w] == 0 || !live(b.count[w], b.entry[w].at)) {
                victim = w;
                entriesUsed_ += b.entry[w].used == 0;  // (a stale entry was counted when first used)
                break;
            }
            if (b.entry[w].used < b.entry[victim].used) victim = w;
        }
        Entry& e = b.entry[victim];
        e.key = key;
        b.hash[victim] = h;
        e.at = at;
        b.count[victim] = n == 0 ? kEmpty : std::uint32_t(n);
        e.extra = extra;
        e.used = ++clock_;
        ++stats_.stored;
        recordsStored_ += n;
        // Grow the table while over half full, but only to ~4x the entries whose records the ring
        // can hold at once (more would only keep entries of overwritten records).
        const std::size_t entries = buckets() * kWays;
        if (entriesUsed_ * 2 > entries &&
            double(entries) < 4.0 * double(ringSize_) * double(stats_.stored) / double(std::max<std::uint64_t>(recordsStored_, 1))) {
            if (buckets() < maxBuckets_) resize(std::min(maxBuckets_, buckets() * 4));
            else full_ = true;
        }
    }

    const Stats& stats() const { return stats_; }
    /// Whether a model of `primitives` primitives fits: at most half the entries of the table at
    /// its full size. A larger model would evict its own entries from their buckets and miss most
    /// of them every time (a 50,000-gene tree's 83,000 primitives in 65,536 entries: 2x slower
    /// than drawing it); its scorer draws it the full way instead.
    bool holds(std::size_t primitives) const { return primitives * 2 <= maxBuckets_ * kWays; }
    /// It has reached `bytes` and would have grown: primitives too large for it, records still
    /// asked for (one lookup in 16) overwritten, or an entry table over half full that could not
    /// grow. What it cannot keep is drawn the full way.
    bool full() const { return full_; }
    /// Bytes of entries and records written so far (what the system had to map; at most bytes()).
    std::size_t bytesUsed() const {
        return buckets() * sizeof(Bucket) + std::min<std::uint64_t>(head_ - ringStart_, ringSize_) * sizeof(Record);
    }
    std::size_t bytes() const { return maxBuckets_ * sizeof(Bucket) + ringMax_ * sizeof(Record); }

private:
    static constexpr std::size_t kWays = 4;
    static constexpr std::size_t kFirstBuckets = 256;  ///< 1,024 entries, ~128 KB
    static constexpr std::size_t kFirstRingBytes = 256 << 10;
    /// count of an entry that wrote no record (a primitive reaching no pixel or voxel)
    static constexpr std::uint32_t kEmpty = UINT32_MAX;
    struct Entry {
        Key key;
        std::uint64_t at, extra, used;  ///< used: 0 never used
    };
    /// A bucket, all zero when free: the tags of its ways first, in the one cache line a
    /// prefetch() brings, so that a lookup reads no entry but the one whose tag matches.
    struct alignas(64) Bucket {
        std::uint64_t hash[kWays];
        std::uint32_t count[kWays];  ///< 0: free; kEmpty: stored with no records
        Entry entry[kWays];
    };
    /// An entry's records are still in the ring (none was overwritten since it was stored).
    bool live(std::uint32_t count, std::uint64_t at) const {
        return count == kEmpty || (at >= ringStart_ && head_ - at <= ringSize_);
    }

    /// A ring of `records` records, empty: every record of the old one is forgotten (their entries
    /// become stale, misses). Rare: the ring only grows (x4), from 256 KB to its share of `bytes`.
    void growRing(std::size_t records) {
        ring_ = ZeroPages<Record>();
        ring_ = ZeroPages<Record>(records);
        ringSize_ = records;
        ringStart_ = head_;
        stale_ = 0;
        lookupsAtGrowth_ = stats_.hits + stats_.misses;
    }
    std::size_t buckets() const { return mask_ + 1; }

    /// A table of `buckets` buckets holding the live entries of the current one (rare: the table
    /// only grows, at most log4 of its final size times).
    void resize(std::size_t buckets) {
        ZeroPages<Bucket> old = std::move(table_);
        const std::size_t oldCount = old.size();
        table_ = ZeroPages<Bucket>(buckets);  // all-zero buckets are free ones
        mask_ = buckets - 1;
        entriesUsed_ = 0;
        for (std::size_t i = 0; i < oldCount; ++i)
            for (std::size_t v = 0; v < kWays; ++v) {
                const Bucket& from = old[i];
                if (from.entry[v].used == 0 || !live(from.count[v], from.entry[v].at)) continue;
                Bucket& to = table_[from.hash[v] & mask_];
                for (std::size_t w = 0; w < kWays; ++w)
                    if (to.entry[w].used == 0) {
                        to.hash[w] = from.hash[v];
                        to.count[w] = from.count[v];
                        to.entry[w] = from.entry[v];
                        ++entriesUsed_;
                        break;
                    }
            }
    }

    ZeroPages<Bucket> table_;
    ZeroPages<Record> ring_;
    std::size_t maxBuckets_ = 1, ringMax_ = 1, ringSize_ = 0, mask_ = 0;
    std::uint64_t head_ = 0, clock_ = 0, entriesUsed_ = 0, recordsStored_ = 0;
    std::uint64_t ringStart_ = 0, stale_ = 0, lookupsAtGrowth_ = 0;
    bool full_ = false;  ///< head_, stale finds and lookups since the ring grew
    Stats stats_;
};

/// One primitive on its way through the cache: its index in the model, its key's hash and what
/// the cache holds for it (`hit`: found).
template <class Record>
struct CacheProbe {
    std::uint32_t index;
    bool hit;
    std::uint64_t hash;
    typename PrimitiveCache<Record>::Found found;
};

/// Draw every primitive through `cache`: `drawDirect(p, i)` first (i: its index), which draws a
/// primitive that is cheaper to draw than to look up, or skips one drawn otherwise, and returns
/// true (such primitives never touch the cache); then `replay(found, i)` for one stored before;
/// otherwise `compute(p, records)` draws it, appending what it wrote to `records` (cleared
/// first), and returns the number to keep with them (Found::extra), and `computed(records,
/// extra, i)` sees what was kept. Drawing is order-independent (OR of rows), so they may
/// interleave; replay and compute are called in the order of the primitives.
/// `probes` and `records` are scratch space kept between calls (no allocation once warm).
template <class Record, class DrawDirect, class Replay, class Compute, class Computed>
void drawThroughCache(PrimitiveCache<Record>& cache, const std::vector<Primitive>& primitives,
                      std::vector<CacheProbe<Record>>& probes, std::vector<Record>& records, DrawDirect&& drawDirect,
                      Replay&& replay, Compute&& compute, Computed&& computed) {
    // Every lookup waits on memory three times (its bucket's tags, the entry, its records): ask
    // for every bucket first, then for every entry whose tag matches, then look every key up and
    // ask for the records found, then use them, so that the waits overlap instead of adding up.
    probes.clear();
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        if (drawDirect(primitives[i], i)) continue;
        const std::uint64_t h = PrimitiveKey(primitives[i]).hash();
        cache.prefetch(h);
        probes.push_back({std::uint32_t(i), false, h, {}});
    }
    for (const CacheProbe<Record>& probe : probes) cache.prefetchEntry(probe.hash);
    for (CacheProbe<Record>& probe : probes) {
        probe.hit = cache.find(PrimitiveKey(primitives[probe.index]), probe.hash, probe.found);
        if (!probe.hit) continue;
        const char* const first = reinterpret_cast<const char*>(probe.found.records.data());
        const std::size_t bytes = std::min<std::size_t>(probe.found.records.size_bytes(), 8 * 64);
        for (std::size_t b = 0; b < bytes; b += 64) __builtin_prefetch(first + b);
    }
    for (const CacheProbe<Record>& probe : probes) {
        // (a store below may overwrite records found above: those are drawn again)
        if (probe.hit && cache.stillHolds(probe.found)) {
            replay(probe.found, probe.index);
            continue;
        }
        const Primitive& p = primitives[probe.index];
        records.clear();
        const std::uint64_t extra = compute(p, records);
        cache.store(PrimitiveKey(p), probe.hash, records, extra);
        computed(std::span<const Record>(records), extra, probe.index);
    }
}

}  // namespace shapevo

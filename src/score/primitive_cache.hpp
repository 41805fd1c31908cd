// PrimitiveCache: what rasterizing or voxelizing one primitive wrote, kept by the primitive's exact
// numbers, so that a model made mostly of primitives seen before (a child is mostly its parent)
// replays their rows instead of computing them again.
//
// Promises:
//  - Exact: an entry is found only for a primitive whose kind, mesh index and every float (compared
//    bit for bit) equal those it was stored with; the hash only picks the bucket. What a primitive
//    writes depends on nothing else (the camera or grid is fixed per cache), so a replay writes the
//    very rows a computation would.
//  - Bounded: `bytes` of records and entries, reserved once at construction (zero pages the
//    system maps only when first written, so a small run never touches most of it); storing never
//    allocates. Records live in one ring: storing overwrites the oldest, and an entry whose records
//    were overwritten is simply not found (a miss, never a wrong answer).
//  - Derived data only: a cold cache gives the same results as a warm one, only slower.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <span>
#include <vector>

#include "base/hash.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// A primitive's numbers packed without padding (the key of PrimitiveCache; compared bytewise).
struct PrimitiveKey {
    static constexpr std::size_t kBytes = 1 + 2 + 4 * (1 + 3 + 9 + 3 + 1);
    unsigned char bytes[kBytes];
    PrimitiveKey() = default;
    explicit PrimitiveKey(const Primitive& p) {
        unsigned char* at = bytes;
        auto put = [&](const void* v, std::size_t n) {
            std::memcpy(at, v, n);
            at += n;
        };
        put(&p.kind, 1);
        put(&p.mesh, 2);
        put(&p.taper, 4);
        put(&p.centre[0], 12);
        put(&p.axes[0][0], 36);
        put(&p.half[0], 12);
        put(&p.taperZ, 4);
    }
    std::uint64_t hash() const { return hash64(bytes, kBytes); }
    bool operator==(const PrimitiveKey& o) const { return std::memcmp(bytes, o.bytes, kBytes) == 0; }
};

template <class Record>
class PrimitiveCache {
public:
    /// What a lookup finds: the records in the order they were written, and the number stored with them.
    struct Found {
        std::span<const Record> records;
        std::uint64_t extra = 0;
    };
    struct Stats {
        std::uint64_t hits = 0, misses = 0, stored = 0, tooLarge = 0;
    };

    /// About `bytes` in all (at least a small minimum): a quarter for entries, the rest for records.
    explicit PrimitiveCache(std::size_t bytes) {
        bytes = std::max<std::size_t>(bytes, 64 * 1024);
        std::size_t buckets = 1;
        while (buckets * 2 * kWays * sizeof(Entry) <= bytes / 4) buckets *= 2;
        entryCount_ = buckets * kWays;
        // calloc: all-zero entries are free ones, and large blocks come as untouched zero pages.
        entries_.reset(static_cast<Entry*>(std::calloc(entryCount_, sizeof(Entry))));
        if (!entries_) throw std::bad_alloc();
        mask_ = buckets - 1;
        ringSize_ = std::max<std::size_t>(1, (bytes - entryCount_ * sizeof(Entry)) / sizeof(Record));
        ring_ = std::make_unique_for_overwrite<Record[]>(ringSize_);  // never read before written
    }

    /// Bring the bucket of hash `h` towards the cache (looking up many keys: prefetch them all first).
    void prefetch(std::uint64_t h) const { __builtin_prefetch(&entries_[(h & mask_) * kWays]); }

    /// The records stored for `key` (hash `h` = key.hash()) into `out`; false if there are none.
    bool find(const PrimitiveKey& key, std::uint64_t h, Found& out) {
        Entry* bucket = &entries_[(h & mask_) * kWays];
        for (std::size_t w = 0; w < kWays; ++w) {
            Entry& e = bucket[w];
            if (e.hash != h || e.count == 0 || !live(e) || !(e.key == key)) continue;
            e.used = ++clock_;
            out.records = e.count == kEmpty ? std::span<const Record>()
                                            : std::span<const Record>(&ring_[e.at % ringSize_], e.count);
            out.extra = e.extra;
            ++stats_.hits;
            return true;
        }
        ++stats_.misses;
        return false;
    }

    /// Store `records` (and `extra`) for `key`, replacing the least recently used entry of its
    /// bucket. A primitive with more records than a quarter of the ring is not stored.
    void store(const PrimitiveKey& key, std::uint64_t h, std::span<const Record> records, std::uint64_t extra) {
        const std::size_t n = records.size(), size = ringSize_;
        if (n > size / 4) {
            ++stats_.tooLarge;
            return;
        }
        // Contiguous in the ring: skip its tail when the records would wrap.
        if (n > 0 && head_ % size + n > size) head_ += size - head_ % size;
        const std::uint64_t at = head_;
        head_ += n;
        if (n > 0) std::memcpy(&ring_[at % size], records.data(), n * sizeof(Record));
        Entry* bucket = &entries_[(h & mask_) * kWays];
        Entry* victim = bucket;
        for (std::size_t w = 0; w < kWays; ++w) {
            Entry& e = bucket[w];
            if (e.count == 0 || !live(e)) {
                victim = &e;
                break;
            }
            if (e.used < victim->used) victim = &e;
        }
        victim->key = key;
        victim->hash = h;
        victim->at = at;
        victim->count = n == 0 ? kEmpty : std::uint32_t(n);
        victim->extra = extra;
        victim->used = ++clock_;
        ++stats_.stored;
    }

    const Stats& stats() const { return stats_; }
    std::size_t bytes() const { return entryCount_ * sizeof(Entry) + ringSize_ * sizeof(Record); }

private:
    static constexpr std::size_t kWays = 4;
    /// count of an entry that wrote no record (a primitive reaching no pixel or voxel)
    static constexpr std::uint32_t kEmpty = UINT32_MAX;
    struct Entry {  // all zero: free
        PrimitiveKey key;
        std::uint64_t hash, at, extra, used;
        std::uint32_t count;  ///< 0: free; kEmpty: stored with no records
    };
    struct Free {
        void operator()(Entry* e) const { std::free(e); }
    };
    /// Its records are still in the ring (none was overwritten since it was stored).
    bool live(const Entry& e) const { return e.count == kEmpty || head_ - e.at <= ringSize_; }

    std::unique_ptr<Entry[], Free> entries_;
    std::unique_ptr<Record[]> ring_;
    std::size_t entryCount_ = 0, ringSize_ = 0, mask_ = 0;
    std::uint64_t head_ = 0, clock_ = 0;
    Stats stats_;
};

/// Draw every primitive through `cache`: `replay(found)` for one stored before; otherwise
/// `compute(p, records)` draws it, appending what it wrote to `records` (cleared first), and
/// returns the number to keep with them (Found::extra). `hashes` and `records` are scratch space
/// kept between calls (no allocation once warm).
template <class Record, class Replay, class Compute>
void drawThroughCache(PrimitiveCache<Record>& cache, const std::vector<Primitive>& primitives,
                      std::vector<std::uint64_t>& hashes, std::vector<Record>& records, Replay&& replay,
                      Compute&& compute) {
    hashes.resize(primitives.size());
    for (std::size_t i = 0; i < primitives.size(); ++i) {  // the lookups wait on memory: ask for it all first
        hashes[i] = PrimitiveKey(primitives[i]).hash();
        cache.prefetch(hashes[i]);
    }
    typename PrimitiveCache<Record>::Found found;
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        const PrimitiveKey key(primitives[i]);
        if (cache.find(key, hashes[i], found)) {
            replay(found);
            continue;
        }
        records.clear();
        const std::uint64_t extra = compute(primitives[i], records);
        cache.store(key, hashes[i], records, extra);
    }
}

}  // namespace shapevo

// SubtreeMemo: numbering subtrees by content, and their outputs by number and start (see the header).
#include "geometry/subtree_memo.hpp"

#include <algorithm>
#include <cstring>

#include "base/hash.hpp"

namespace shapevo {

namespace {
constexpr std::uint32_t kPrimitiveWords = sizeof(Primitive) / 4;
constexpr std::uint32_t kLookWords = sizeof(Appearance) / 4;
static_assert(sizeof(Primitive) % 4 == 0 && sizeof(Appearance) % 4 == 0, "records are whole words");
static_assert(std::is_trivially_copyable_v<Primitive> && std::is_trivially_copyable_v<Appearance>);
}  // namespace

SubtreeMemo::Start::Start(std::uint64_t content, std::uint32_t key, const std::uint32_t* place, const Appearance* look,
                          const Scope& s, const float* carried, std::uint32_t carriedCount) {
    words[0] = std::uint32_t(content);
    words[1] = std::uint32_t(content >> 32);
    words[2] = key;
    std::uint32_t n = 3;
    if (place) words[n++] = *place;
    if (look) {
        std::memcpy(&words[n], &look->color[0], 12);
        words[n + 3] = std::uint32_t(look->material) | std::uint32_t(look->texture) << 16;
        words[n + 4] = look->frame;
        n += 5;
    }
    std::memcpy(&words[n], &s.origin[0], 12);
    std::memcpy(&words[n + 3], &s.axes[0][0], 36);
    std::memcpy(&words[n + 12], &s.size[0], 12);
    n += 15;
    if (carriedCount > 0) std::memcpy(&words[n], carried, carriedCount * sizeof(float));
    count = n + carriedCount;
    hash = quickHash(words, count);
}

SubtreeMemo::Ring::Ring(std::size_t bytes, std::size_t maxTableBytes) {
    static_assert(sizeof(Entry) % 8 == 0);
    bytes = std::max<std::size_t>(bytes, 128 * 1024) / 8 * 8;
    std::size_t buckets = 1;
    while (buckets * 2 * kWays * sizeof(Entry) <= std::min(maxTableBytes, bytes / 8 * 7)) buckets *= 2;
    mask_ = buckets - 1;
    const std::size_t tableBytes = buckets * kWays * sizeof(Entry);
    memory_ = ZeroPages<std::uint64_t>(bytes / 8);
    entries_ = reinterpret_cast<Entry*>(&memory_[0]);
    ring_ = reinterpret_cast<std::uint32_t*>(&memory_[tableBytes / 8]);
    ringSize_ = (bytes - tableBytes) / 4;
}

SubtreeMemo::Ring::Entry* SubtreeMemo::Ring::find(std::uint64_t h, const std::uint32_t* key, std::uint32_t n) {
    Entry* bucket = &entries_[(h & mask_) * kWays];
    for (std::size_t w = 0; w < kWays; ++w) {
        Entry& e = bucket[w];
        if (e.hash != h || !live(e) || e.words < n || std::memcmp(records(e), key, std::size_t(n) * 4) != 0) continue;
        e.used = ++clock_;
        if (head_ - e.at > ringSize_ / 2) moveToHead(e);
        return &e;
    }
    return nullptr;
}

void SubtreeMemo::Ring::moveToHead(Entry& e) {
    const std::size_t size = ringSize_;
    if (head_ % size + e.words > size) head_ += size - head_ % size;  // contiguous: skip the ring's tail
    // Still intact: skipping writes nothing, and the records were live. They may overlap their
    // new place (when about to be overwritten): memmove.
    std::memmove(&ring_[head_ % size], &ring_[e.at % size], std::size_t(e.words) * 4);
    e.at = head_;
    head_ += e.words;
}

SubtreeMemo::Ring::Entry* SubtreeMemo::Ring::add(std::uint64_t h, std::size_t words, std::uint32_t*& records) {
    const std::size_t size = ringSize_;
    if (words == 0 || words > size / 8) return nullptr;
    if (head_ % size + words > size) head_ += size - head_ % size;  // contiguous: skip the ring's tail
    const std::uint64_t at = head_;
    head_ += words;
    records = &ring_[at % size];
    Entry* bucket = &entries_[(h & mask_) * kWays];
    Entry* victim = bucket;
    for (std::size_t w = 0; w < kWays; ++w) {
        Entry& e = bucket[w];
        if (!live(e)) {
            victim = &e;
            break;
        }
        if (e.used < victim->used) victim = &e;
    }
    *victim = Entry{h, at, ++clock_, 0, std::uint32_t(words), 0};
    return victim;
}

// A quarter of the bytes for contents, the rest for outputs. A content is a dozen words, about
// its entry's size, and a forgotten one renumbers all its ancestors, so up to three quarters of
// the contents' bytes are entries, so buckets stay far from full: 32 MB has 131,072 (with an eighth,
// as for outputs, 8,192 entries: a 10,000-gene model got ~4,000 new numbers between one
// derivation of it and the next, and found almost none of its subtrees). An output is a few
// hundred words: an eighth of its bytes are entries.
SubtreeMemo::SubtreeMemo(std::size_t bytes) : contents_(bytes / 4, bytes / 16 * 3), outputs_(bytes - bytes / 4, bytes / 32 * 3) {}

void SubtreeMemo::identify(const Grammar& g, const Chromosome& c) {
    storedWords_ = 0;
    if (contentAt_.size() < c.size()) contentAt_.resize(c.size());
    genes_.clear();
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) genes_.push_back(pos);
    // Children come after their parents: backwards, every child is numbered before its parent.
    for (std::size_t i = genes_.size(); i-- > 0;) {
        const std::uint32_t pos = genes_[i];
        const Rule& r = g.rules[c.rule(pos)];
        const std::uint32_t n = 1 + 2u * r.childOffsets + r.paramFloats;
        if (key_.size() < n) key_.resize(n);
        std::uint32_t* key = key_.data();
        *key++ = c.rule(pos);
        for (std::uint32_t k = 0; k < r.childOffsets; ++k) {
            const std::int32_t off = c.child(pos, k);
            const std::uint64_t child = off > 0 ? contentAt_[pos + std::uint32_t(off)] : 0;  // numbers start at 1
            *key++ = std::uint32_t(child);
            *key++ = std::uint32_t(child >> 32);
        }
        std::memcpy(key, c.words.data() + Chromosome::paramWord(pos, r), std::size_t(r.paramFloats) * 4);
        const std::uint64_t h = quickHash(key_.data(), n);
        if (const Ring::Entry* e = contents_.find(h, key_.data(), n); e && e->words == n) {
            contentAt_[pos] = e->value;
            continue;
        }
        contentAt_[pos] = ++lastNumber_;
        std::uint32_t* records = nullptr;
        if (Ring::Entry* e = contents_.add(h, n, records)) {
            std::memcpy(records, key_.data(), std::size_t(n) * 4);
            e->value = lastNumber_;
            ++stats_.contents;
        }
    }
}

bool SubtreeMemo::find(const Start& start, Found& out) {
    const Ring::Entry* e = outputs_.find(start.hash, start.words, start.count);
    if (!e) {
        ++stats_.misses;
        return false;
    }
    out.primitives = outputs_.records(*e) + start.count;
    out.looks = out.primitives + std::size_t(e->count) * kPrimitiveWords;
    out.count = e->count;
    out.tasks = std::uint32_t(e->value);
    ++stats_.hits;
    return true;
}

void SubtreeMemo::store(const Start& start, const Primitive* primitives, const Appearance* looks, std::uint32_t count,
                        std::uint32_t tasks) {
    const std::size_t words = start.count + std::size_t(count) * (kPrimitiveWords + (looks ? kLookWords : 0));
    storedWords_ += words;
    if (storedWords_ > outputs_.ringWords() && !off_) {  // this model outgrows the memo (see the header)
        stats_.outgrown = true;
        turnOff();
    }
    std::uint32_t* rec = nullptr;
    Ring::Entry* e = outputs_.add(start.hash, words, rec);
    if (!e) {
        ++stats_.tooLarge;
        return;
    }
    std::memcpy(rec, start.words, start.count * 4);
    rec += start.count;
    if (count > 0) std::memcpy(rec, primitives, std::size_t(count) * sizeof(Primitive));  // (null when none)
    if (looks && count > 0)
        std::memcpy(rec + std::size_t(count) * kPrimitiveWords, looks, std::size_t(count) * sizeof(Appearance));
    e->value = tasks;
    e->count = count;
    ++stats_.stored;
}

}  // namespace shapevo

// SubtreeMemo: what deriving one subtree of a chromosome made (its primitives, their looks and
// the tasks it took), kept by the subtree's exact content and the scope it started on, so that a
// child, which is mostly its parent, derives again only the subtree its operator changed
// (incremental evaluation; derive.hpp uses it when DeriveScratch::memo is set).
//
// How: identify() gives every gene of a chromosome the number of its subtree's content, children
// first: the same rule, the same parameters bit for bit and children of the same numbers (in slot
// order) get the same number, found in a table of the contents seen before (hash consing); a new
// content gets a number never given before. A subtree's output is then kept by its number and its
// start (the scope's origin, axes and size, its look, the piece key and place, bit for bit).
//
// Promises:
//  - Exact: numbers are compared, never only hashes: two subtrees share a number only if their
//    contents are equal, and an output is found only for the same number and the same start. A
//    gene's task starts on its parent's scope at its first statement with no let values
//    (derive.cpp), so what derive makes of the subtree depends on nothing else.
//  - Bounded: two rings of records with their tables of entries, at most `bytes` in all, in zero
//    pages (base/zero_pages.hpp: memory is mapped as the rings first fill). Storing overwrites
//    the oldest records, and records found in the older half of a ring move to its head (so a
//    subtree every child uses is never forgotten); an entry whose records were overwritten is a
//    miss (a forgotten content gets a new number), never a wrong answer.
//  - Derived data only: a cold memo gives the same geometry as a warm one, only later.
//  - It steps aside for models it cannot hold: each primitive is kept once per subtree around it
//    (once per ancestor gene), so a derivation that stores more than the output ring holds
//    overwrites its own subtrees before any child can find them (a 50,000-gene tree stores ~66 MB
//    against a 24 MB ring: no hit at all, and a child scored 3x slower than without). Such a
//    derivation turns the memo off (on() false, Stats::outgrown) for good.
//  - No allocation once warm.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/zero_pages.hpp"
#include "genome/chromosome.hpp"
#include "geometry/pieces.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

class SubtreeMemo {
public:
    /// Where a subtree starts: its content's number, its piece key, its piece place (grammars
    /// reading piece.index / piece.count), look (with colours) and scope, as words.
    struct Start {
        static constexpr std::size_t kMaxWords = 3 + 1 + 5 + 15 + kMaxCarried;
        std::uint32_t words[kMaxWords];
        std::uint32_t count = 0;
        std::uint64_t hash = 0;
        /// `place` is null for grammars that read no piece.index or piece.count, `look` for
        /// grammars without colours or materials, and `carriedCount` 0 for grammars without
        /// carried attributes (so every start of one grammar has as many words).
        Start(std::uint64_t content, std::uint32_t key, const std::uint32_t* place, const Appearance* look, const Scope& s,
              const float* carried = nullptr, std::uint32_t carriedCount = 0);
    };
    /// A stored subtree's output, valid until the next store().
    struct Found {
        const std::uint32_t* primitives = nullptr;  ///< `count` Primitives, bytewise
        const std::uint32_t* looks = nullptr;       ///< `count` Appearances, bytewise (stored with looks only)
        std::uint32_t count = 0;
        std::uint32_t tasks = 0;  ///< derive's tasks for the subtree, its own first one included
    };
    struct Stats {
        std::uint64_t hits = 0, misses = 0, stored = 0, tooLarge = 0, contents = 0;
        bool outgrown = false;  ///< a derivation stored more than the ring holds: turned off
    };

    explicit SubtreeMemo(std::size_t bytes);

    /// Number every gene's subtree of `c` (contentOf); call before the lookups of one derivation.
    void identify(const Grammar& g, const Chromosome& c);
    /// After identify(c): the number of the content of the subtree at `gene`.
    std::uint64_t contentOf(std::uint32_t gene) const { return contentAt_[gene]; }

    /// The output stored for `start`; false if none.
    bool find(const Start& start, Found& out);
    /// Keep what the subtree started at `start` made: `count` primitives (and their looks, when
    /// `looks` is not null) in `tasks` tasks. A subtree larger than an eighth of the ring is not kept.
    void store(const Start& start, const Primitive* primitives, const Appearance* looks, std::uint32_t count,
               std::uint32_t tasks);

    /// Whether derive uses it (on until turnOff(): its owner may find it does not pay, as on a
    /// spaceship's cheap boxes; results never depend on it, only the time).
    bool on() const { return !off_; }
    void turnOff() { off_ = true; }

    const Stats& stats() const { return stats_; }
    /// Bytes of entries and records written so far (what the system had to map).
    std::size_t bytesUsed() const { return contents_.bytesUsed() + outputs_.bytesUsed(); }

private:
    /// Records of whole words in a ring, found through a table of 4-way buckets by their hash;
    /// storing replaces the least recently used entry of the bucket.
    class Ring {
    public:
        struct Entry {  // all zero: free
            std::uint64_t hash, at, used, value;
            std::uint32_t words, count;
        };
        /// About `bytes` in all, at most `maxTableBytes` of it for the table of entries.
        Ring(std::size_t bytes, std::size_t maxTableBytes);
        /// The live entry of hash `h` whose first `n` words equal `key`, or null. An entry found
        /// in the older half of the ring has its records moved to the head first: what is used
        /// stays (least recently used, not first stored, is overwritten), each record moved at
        /// most once per half ring written.
        Entry* find(std::uint64_t h, const std::uint32_t* key, std::uint32_t n);
        /// Room for `words` words (null if more than an eighth of the ring) and its entry, filled
        /// with `h`; the caller writes both.
        Entry* add(std::uint64_t h, std::size_t words, std::uint32_t*& records);
        const std::uint32_t* records(const Entry& e) const { return &ring_[e.at % ringSize_]; }
        std::size_t ringWords() const { return ringSize_; }
        std::size_t bytesUsed() const {
            return (mask_ + 1) * kWays * sizeof(Entry) + std::min<std::uint64_t>(head_, ringSize_) * 4;
        }

    private:
        static constexpr std::size_t kWays = 4;
        bool live(const Entry& e) const { return e.words > 0 && head_ - e.at <= ringSize_; }
        void moveToHead(Entry& e);
        // Entries and ring in one mapping: large enough for huge pages (base/zero_pages.hpp), so
        // that the table's scattered first touches cost a few page faults, not one per 4 KB.
        ZeroPages<std::uint64_t> memory_;
        Entry* entries_ = nullptr;
        std::uint32_t* ring_ = nullptr;
        std::size_t ringSize_ = 0;
        std::size_t mask_ = 0;
        std::uint64_t head_ = 0, clock_ = 0;
    };

    Ring contents_, outputs_;
    std::uint64_t lastNumber_ = 0;
    bool off_ = false;
    std::uint64_t storedWords_ = 0;  ///< by store() since the last identify()
    std::vector<std::uint64_t> contentAt_;  ///< per word position of the last identify(): its gene's number
    std::vector<std::uint32_t> genes_, key_;  // scratch
    Stats stats_;
};

}  // namespace shapevo

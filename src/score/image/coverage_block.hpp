// CoverageBlock: one block of the bit planes CoverageCounts is made of, shared by reference
// between a model and its children, and the pool blocks come from and go back to, so that
// scoring a child from its parent allocates nothing once warm (score/image/model_store.hpp).
//
// Promises:
//  - A handle shares its block (an atomic count: copies may live and be released on any
//    thread); the last one released gives the block back to its pool, or frees it without one.
//  - shared() is true while another handle holds the block: a handle that is the only one may
//    write (nobody else can copy it meanwhile), the others must copy first (copy-on-write).
//  - The pool counts the bytes of its blocks in use (bytesInUse) and keeps at most `keepBytes`
//    of given-back blocks for reuse, freeing the rest. It must outlive its blocks.
#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <utility>

namespace shapevo {

class CoverageBlockPool;

class CoverageBlock {
public:
    /// Words per block: the 64-pixel words of the picture it covers.
    static constexpr std::size_t kPictureWords = 128;
    /// Most planes a block may have (counts up to 2^32 - 1).
    static constexpr std::uint32_t kMaxPlanes = 32;

    CoverageBlock() = default;
    CoverageBlock(const CoverageBlock& o) noexcept : h_(o.h_) {
        if (h_) h_->refs.fetch_add(1, std::memory_order_relaxed);
    }
    CoverageBlock(CoverageBlock&& o) noexcept : h_(std::exchange(o.h_, nullptr)) {}
    CoverageBlock& operator=(const CoverageBlock& o) noexcept {
        Header* h = o.h_;  // (read before release(): o may be this handle)
        if (h) h->refs.fetch_add(1, std::memory_order_relaxed);
        release();
        h_ = h;
        return *this;
    }
    CoverageBlock& operator=(CoverageBlock&& o) noexcept {
        if (this != &o) {
            release();
            h_ = std::exchange(o.h_, nullptr);
        }
        return *this;
    }
    ~CoverageBlock() { release(); }

    /// A new block of `planes` planes (above-zero plane and planes all zero if `zero`), from
    /// `pool` (null: the heap).
    static CoverageBlock make(CoverageBlockPool* pool, std::uint32_t planes, bool zero);

    explicit operator bool() const { return h_ != nullptr; }
    bool shared() const { return h_->refs.load(std::memory_order_acquire) > 1; }
    std::uint32_t planes() const { return h_->planes; }
    /// Per picture word, 1 + planes() words: the above-zero plane, then the planes.
    std::uint64_t* cells() const { return reinterpret_cast<std::uint64_t*>(h_ + 1); }
    std::uint64_t* cell(std::size_t w) const { return cells() + w * (1 + h_->planes); }
    /// The same key for every handle of one block (memory counts).
    const void* key() const { return h_; }
    std::size_t bytes() const { return bytesOf(h_->planes); }
    static std::size_t bytesOf(std::uint32_t planes) { return sizeof(Header) + kPictureWords * (1 + planes) * sizeof(std::uint64_t); }

private:
    friend class CoverageBlockPool;
    struct Header {
        std::atomic<std::uint32_t> refs;
        std::uint32_t planes;
        CoverageBlockPool* pool;  ///< null: from the heap
        Header* next;             ///< in a pool's free list
    };
    static_assert(sizeof(Header) % sizeof(std::uint64_t) == 0);
    void release() noexcept;
    /// End a block's header and give its memory back to the heap.
    static void freeHeader(Header* h) noexcept;

    Header* h_ = nullptr;
};

class CoverageBlockPool {
public:
    explicit CoverageBlockPool(std::size_t keepBytes = 0) : keepBytes_(keepBytes) {}
    CoverageBlockPool(const CoverageBlockPool&) = delete;
    CoverageBlockPool& operator=(const CoverageBlockPool&) = delete;
    ~CoverageBlockPool();
    /// Bytes of the blocks handed out and not given back.
    std::size_t bytesInUse() const { return std::size_t(inUse_.load(std::memory_order_relaxed)); }
    /// Bytes of given-back blocks kept for reuse.
    std::size_t bytesKept() const;
    void setKeepBytes(std::size_t bytes) { keepBytes_.store(bytes, std::memory_order_relaxed); }

private:
    friend class CoverageBlock;
    using Header = CoverageBlock::Header;
    /// Memory for a block of `planes` planes (a Header to construct in it).
    void* take(std::uint32_t planes);
    void give(Header* h) noexcept;

    std::atomic<std::size_t> keepBytes_;
    std::atomic<std::int64_t> inUse_{0};
    mutable std::mutex mutex_;
    std::array<Header*, CoverageBlock::kMaxPlanes + 1> free_{};  ///< by plane count
    std::size_t kept_ = 0;
};

}  // namespace shapevo

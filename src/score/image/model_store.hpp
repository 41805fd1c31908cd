// ModelStore: where an image scorer's models (score/image/image_model.hpp, what scoring leaves for a
// model's children) come from and go back to, and how much memory they may take.
//
// Promises:
//  - No allocation per model once warm: take() hands out a model given back before (its
//    chromosome and coverage buffers keep their capacity), in a shared_ptr whose control block
//    comes from the store too; the coverage blocks come from its CoverageBlockPool. The last
//    release of a model, on any thread, clears it and gives it back.
//  - Bounded (score.cache_mb, per island, beside the evaluation threads' caches): bytesInUse()
//    counts every model handed out (its own size, its chromosome's capacity, its coverage's
//    handles) and every coverage block in use. reserve(bytes) says whether a model of about
//    `bytes` may be kept: only if it fits four times into what is left of the bound (counting
//    what other threads have reserved meanwhile), so that near the bound the largest models are
//    the first not kept. A model not kept only costs its children speed (they are scored the way
//    they would be without it): results never change.
//  - Given-back models and blocks are kept for reuse up to an eighth of the bound each, beside
//    it; the rest is freed. The store lives as long as any model or control block it handed out.
#pragma once
#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "score/image/coverage_block.hpp"
#include "score/image/image_model.hpp"

namespace shapevo {

class ModelStore : public std::enable_shared_from_this<ModelStore> {
public:
    static std::shared_ptr<ModelStore> make() { return std::shared_ptr<ModelStore>(new ModelStore()); }
    ModelStore(const ModelStore&) = delete;
    ModelStore& operator=(const ModelStore&) = delete;
    ~ModelStore();

    /// The most bytes models may take (0: none is kept).
    void setBound(std::size_t bytes);
    std::size_t bound() const { return bound_.load(std::memory_order_relaxed); }
    /// Room for `bytes` more, counted in bytesInUse() until it goes; while it is held the model
    /// is made and count()ed. Empty (false) when there is no room; a refusal sets full().
    class Reservation {
    public:
        Reservation() = default;
        Reservation(Reservation&& o) noexcept : store_(std::exchange(o.store_, nullptr)), bytes_(o.bytes_) {}
        Reservation& operator=(Reservation&&) = delete;
        ~Reservation() {
            if (store_) store_->reserved_.fetch_sub(bytes_, std::memory_order_relaxed);
        }
        explicit operator bool() const { return store_ != nullptr; }

    private:
        friend class ModelStore;
        Reservation(ModelStore* s, std::size_t bytes) : store_(s), bytes_(bytes) {}
        ModelStore* store_ = nullptr;
        std::size_t bytes_ = 0;
    };
    Reservation reserve(std::size_t bytes);
    /// Some model was not kept for lack of room (a run says so once).
    bool full() const { return full_.load(std::memory_order_relaxed); }
    /// Models and coverage blocks in use, in bytes.
    std::size_t bytesInUse() const {
        return std::size_t(inUse_.load(std::memory_order_relaxed)) + reserved_.load(std::memory_order_relaxed) + blocks_.bytesInUse();
    }

    /// A cleared model to fill, then count(): its coverage blocks will come from blocks().
    std::shared_ptr<ImageModel> take();
    /// Count a filled model's bytes in bytesInUse() (once, before anyone else sees it).
    void count(ImageModel& m);
    /// About the bytes a model of `words` chromosome words will be counted for (for reserve()).
    static std::size_t estimate(std::size_t words);
    /// About the bytes coverage counts of `blocks` blocks will take (for reserve()): the most any
    /// made so far took (noteCoverage), at least one plane in every block.
    std::size_t estimateCoverage(std::size_t blocks) const;
    /// Coverage counts of `bytes` were made (CoverageCounts::bytes()).
    void noteCoverage(std::size_t bytes);
    CoverageBlockPool& blocks() { return blocks_; }

private:
    template <class T>
    friend struct ModelControlAllocator;
    friend struct ModelRecycler;
    ModelStore() = default;
    void give(ImageModel* m) noexcept;
    void* takeControl(std::size_t bytes);
    void giveControl(void* p, std::size_t bytes) noexcept;

    std::atomic<std::size_t> bound_{0};
    std::atomic<bool> full_{false};
    std::atomic<std::int64_t> inUse_{0};
    std::atomic<std::size_t> reserved_{0};
    std::atomic<std::size_t> largestCoverage_{0};
    CoverageBlockPool blocks_;
    std::mutex mutex_;  ///< guards what follows
    std::vector<ImageModel*> free_;
    std::size_t freeBytes_ = 0;
    std::size_t controlBytes_ = 0;  ///< the size of a control block (the first one asked for)
    std::vector<void*> freeControls_;
};

}  // namespace shapevo

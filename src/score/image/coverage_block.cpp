// CoverageBlock and its pool: one free list per plane count, under one mutex (blocks are taken
// by the evaluation threads and given back mostly by the thread that replaces a generation).
#include "score/image/coverage_block.hpp"

#include <cstring>
#include <new>

namespace shapevo {

void CoverageBlock::freeHeader(Header* h) noexcept {
    h->~Header();
    ::operator delete(h);
}

CoverageBlock CoverageBlock::make(CoverageBlockPool* pool, std::uint32_t planes, bool zero) {
    void* memory = pool ? pool->take(planes) : ::operator new(bytesOf(planes));
    Header* h = new (memory) Header{{1}, planes, pool, nullptr};
    CoverageBlock b;
    b.h_ = h;
    if (zero) std::memset(b.cells(), 0, kPictureWords * (1 + planes) * sizeof(std::uint64_t));
    return b;
}

void CoverageBlock::release() noexcept {
    if (!h_) return;
    if (h_->refs.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        if (h_->pool)
            h_->pool->give(h_);
        else
            freeHeader(h_);
    }
    h_ = nullptr;
}

CoverageBlockPool::~CoverageBlockPool() {
    for (Header*& head : free_)
        while (head) CoverageBlock::freeHeader(std::exchange(head, head->next));
}

std::size_t CoverageBlockPool::bytesKept() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return kept_;
}

void* CoverageBlockPool::take(std::uint32_t planes) {
    const std::size_t bytes = CoverageBlock::bytesOf(planes);
    void* memory = nullptr;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (Header* h = free_[planes]) {
            free_[planes] = h->next;
            kept_ -= bytes;
            h->~Header();
            memory = h;
        }
    }
    if (!memory) memory = ::operator new(bytes);
    inUse_.fetch_add(std::int64_t(bytes), std::memory_order_relaxed);
    return memory;
}

void CoverageBlockPool::give(Header* h) noexcept {
    const std::size_t bytes = CoverageBlock::bytesOf(h->planes);
    inUse_.fetch_sub(std::int64_t(bytes), std::memory_order_relaxed);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (kept_ + bytes <= keepBytes_.load(std::memory_order_relaxed)) {
            h->next = free_[h->planes];
            free_[h->planes] = h;
            kept_ += bytes;
            return;
        }
    }
    CoverageBlock::freeHeader(h);
}

}  // namespace shapevo

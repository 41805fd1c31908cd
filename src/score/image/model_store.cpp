// ModelStore: free lists under one mutex (models are taken by the evaluation threads and given
// back mostly by the thread that replaces a generation); control blocks of the one size
// shared_ptr asks for, from the same free lists.
#include "score/image/model_store.hpp"

#include <algorithm>
#include <new>

namespace shapevo {

namespace {
constexpr std::size_t kMostFreeControls = 1 << 14;  ///< control blocks kept for reuse (~50 bytes each)
}  // namespace

/// Gives a model back to its store when its last shared_ptr goes.
struct ModelRecycler {
    ModelStore* store;
    void operator()(ImageModel* m) const noexcept { store->give(m); }
};

/// Allocates shared_ptr control blocks from the store (and keeps the store alive meanwhile).
template <class T>
struct ModelControlAllocator {
    using value_type = T;
    std::shared_ptr<ModelStore> store;
    explicit ModelControlAllocator(std::shared_ptr<ModelStore> s) : store(std::move(s)) {}
    template <class U>
    ModelControlAllocator(const ModelControlAllocator<U>& o) : store(o.store) {}
    T* allocate(std::size_t n) { return static_cast<T*>(store->takeControl(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { store->giveControl(p, n * sizeof(T)); }
    template <class U>
    bool operator==(const ModelControlAllocator<U>& o) const { return store == o.store; }
};

ModelStore::~ModelStore() {
    for (ImageModel* m : free_) delete m;
    for (void* p : freeControls_) ::operator delete(p);
}

void ModelStore::setBound(std::size_t bytes) {
    bound_.store(bytes, std::memory_order_relaxed);
    blocks_.setKeepBytes(bytes / 8);
}

ModelStore::Reservation ModelStore::reserve(std::size_t bytes) {
    const std::size_t bound = this->bound();
    std::size_t reserved = reserved_.load(std::memory_order_relaxed);
    for (;;) {
        const std::size_t used = std::size_t(inUse_.load(std::memory_order_relaxed)) + reserved + blocks_.bytesInUse();
        if (used > bound || bytes > (bound - used) / 4) {
            if (!full_.load(std::memory_order_relaxed)) full_.store(true, std::memory_order_relaxed);
            return {};
        }
        if (reserved_.compare_exchange_weak(reserved, reserved + bytes, std::memory_order_relaxed)) return {this, bytes};
    }
}

std::size_t ModelStore::estimate(std::size_t words) { return sizeof(ImageModel) + words * sizeof(std::uint32_t); }

std::size_t ModelStore::estimateCoverage(std::size_t blocks) const {
    return std::max(largestCoverage_.load(std::memory_order_relaxed), blocks * (sizeof(CoverageBlock) + CoverageBlock::bytesOf(1)));
}

void ModelStore::noteCoverage(std::size_t bytes) {
    std::size_t seen = largestCoverage_.load(std::memory_order_relaxed);
    while (bytes > seen && !largestCoverage_.compare_exchange_weak(seen, bytes, std::memory_order_relaxed)) {
    }
}

std::shared_ptr<ImageModel> ModelStore::take() {
    ImageModel* m = nullptr;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!free_.empty()) {
            m = free_.back();
            free_.pop_back();
            freeBytes_ -= m->countedBytes;
        }
    }
    if (!m) m = new ImageModel();
    m->countedBytes = 0;
    return std::shared_ptr<ImageModel>(m, ModelRecycler{this}, ModelControlAllocator<ImageModel>(shared_from_this()));
}

void ModelStore::count(ImageModel& m) {
    m.countedBytes = sizeof(ImageModel) + m.chromosome.words.capacity() * sizeof(std::uint32_t) + m.handleBytes();
    inUse_.fetch_add(std::int64_t(m.countedBytes), std::memory_order_relaxed);
}

void ModelStore::give(ImageModel* m) noexcept {
    inUse_.fetch_sub(std::int64_t(m->countedBytes), std::memory_order_relaxed);
    m->clear();  // its blocks go back to the pool
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (freeBytes_ + m->countedBytes <= bound() / 8) {
            try {
                free_.push_back(m);
                freeBytes_ += m->countedBytes;
                return;
            } catch (const std::bad_alloc&) {
            }
        }
    }
    delete m;
}

void* ModelStore::takeControl(std::size_t bytes) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (controlBytes_ == 0) controlBytes_ = bytes;
        if (bytes == controlBytes_ && !freeControls_.empty()) {
            void* p = freeControls_.back();
            freeControls_.pop_back();
            return p;
        }
    }
    return ::operator new(bytes);
}

void ModelStore::giveControl(void* p, std::size_t bytes) noexcept {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (bytes == controlBytes_ && freeControls_.size() < kMostFreeControls) {
            try {
                freeControls_.push_back(p);
                return;
            } catch (const std::bad_alloc&) {
            }
        }
    }
    ::operator delete(p);
}

}  // namespace shapevo

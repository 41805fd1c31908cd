// ModelStore (score/image/model_store.hpp): a model given back is handed out again with its buffers'
// capacity (no allocation once warm) and counted only while held; near the bound the larger
// models are refused first and the store says it is full; models may outlive the scorer's
// handle on the store.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "score/image/model_store.hpp"

namespace shapevo {
namespace {

std::shared_ptr<ImageModel> modelOf(ModelStore& store, std::size_t words) {
    std::shared_ptr<ImageModel> m = store.take();
    m->chromosome.words.assign(words, 7u);
    m->chromosome.genes = 1;
    store.count(*m);
    return m;
}

TEST(ModelStore, AModelGivenBackIsHandedOutAgainWithItsCapacity) {
    auto store = ModelStore::make();
    store->setBound(64 << 20);
    std::shared_ptr<ImageModel> m = modelOf(*store, 1000);
    const ImageModel* first = m.get();
    EXPECT_GE(store->bytesInUse(), 4000u);
    m.reset();
    EXPECT_EQ(store->bytesInUse(), 0u);
    std::shared_ptr<ImageModel> again = store->take();
    EXPECT_EQ(again.get(), first);
    EXPECT_TRUE(again->chromosome.words.empty());  // cleared...
    EXPECT_GE(again->chromosome.words.capacity(), 1000u);  // ...keeping its buffer
    EXPECT_EQ(again->coverageIfMade(), nullptr);
}

TEST(ModelStore, NearTheBoundTheLargerModelsAreRefusedFirst) {
    auto store = ModelStore::make();
    store->setBound(4 << 20);
    EXPECT_TRUE(store->reserve(1 << 20));  // a quarter of what is left
    EXPECT_FALSE(store->full());
    std::shared_ptr<ImageModel> big = modelOf(*store, 600'000);  // 2.4 MB: 1.79 MB left
    EXPECT_TRUE(store->reserve(400'000));
    EXPECT_FALSE(store->full());
    EXPECT_FALSE(store->reserve(500'000));
    EXPECT_TRUE(store->full());
    {
        const ModelStore::Reservation held = store->reserve(300'000);  // another thread's, say
        EXPECT_TRUE(held);
        EXPECT_FALSE(store->reserve(400'000));  // what is left is less by what is reserved
    }
    EXPECT_TRUE(store->reserve(400'000));
    big.reset();
    EXPECT_TRUE(store->reserve(500'000));  // room again once it is given back
}

TEST(ModelStore, ModelsAndTheirBlocksMayOutliveEveryOtherHandleOnTheStore) {
    auto store = ModelStore::make();
    store->setBound(1 << 20);
    std::shared_ptr<ImageModel> m = modelOf(*store, 100);
    ImageTarget target;
    target.width = 64;
    target.height = 256;
    target.hit.assign(256, 0);
    target.avoid.assign(256, 0);
    m->coverage([&](CoverageCounts& counts) {
        counts.reset(CoverageLayout(1, 256), &store->blocks());
        CoverageCounts::Delta delta;
        const std::vector<WordMask> words{{3, 1, 0}, {200, 0, 5}};
        counts.add(words, target, delta);
    });
    EXPECT_GT(store->bytesInUse(), 2 * CoverageBlock::bytesOf(1));
    std::weak_ptr<const EvaluatedModel> watch = m;
    store.reset();  // the scorer goes first
    EXPECT_FALSE(watch.expired());
    m.reset();  // gives itself and its blocks back to the store, which goes with the last weak
                // handle (ASan: no leak, no use after free)
    EXPECT_TRUE(watch.expired());
}

}  // namespace
}  // namespace shapevo

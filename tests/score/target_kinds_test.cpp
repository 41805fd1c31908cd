// The table of target kinds (score/target_kinds.hpp): every entry complete and distinct (its name,
// its IoU's summary.json key, its export formats), so that the config, a run's reports and
// `shapevo export` can choose by them without a kind ever being ambiguous.
#include <set>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "score/target_kinds.hpp"

namespace shapevo {
namespace {

TEST(TargetKinds, EveryEntryIsCompleteAndDistinct) {
    ASSERT_FALSE(targetKinds().empty());
    std::set<std::string_view> names, iouKeys, formats;
    for (const TargetKind* k : targetKinds()) {
        ASSERT_NE(k, nullptr);
        EXPECT_FALSE(k->name.empty());
        EXPECT_FALSE(k->summary.empty()) << k->name;
        EXPECT_NE(k->readTarget, nullptr) << k->name;
        EXPECT_FALSE(k->noun.empty()) << k->name;
        EXPECT_FALSE(k->namedBy.empty()) << k->name;
        EXPECT_FALSE(k->iouName.empty()) << k->name;
        EXPECT_TRUE(names.insert(k->name).second) << "two kinds named " << k->name;
        EXPECT_TRUE(iouKeys.insert(k->iouKey).second) << "two kinds write summary.json's " << k->iouKey;
        for (std::string_view f : k->exportFormats) EXPECT_TRUE(formats.insert(f).second) << "two kinds export " << f;
        EXPECT_EQ(findTargetKind(k->name), k);
    }
    EXPECT_EQ(findTargetKind("no such kind"), nullptr);
}

TEST(TargetKinds, SummaryKeysAndExportFormatsAreTheOnesUsersRelyOn) {
    // summary.json's IoU keys and export's formats are public: a new kind adds, never renames.
    const TargetKind* volume = findTargetKind("volume");
    const TargetKind* image = findTargetKind("image");
    ASSERT_NE(volume, nullptr);
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(volume->iouKey, "voxel_iou");
    EXPECT_EQ(image->iouKey, "silhouette_iou");
    EXPECT_EQ(volume->iouName, "voxel IoU");
    EXPECT_EQ(image->iouName, "silhouette IoU");
    std::vector<std::string_view> inTableOrder;
    for (const TargetKind* k : targetKinds()) inTableOrder.insert(inTableOrder.end(), k->exportFormats.begin(), k->exportFormats.end());
    EXPECT_EQ(targetExportFormats(), inTableOrder);
    EXPECT_EQ(targetExportFormats(), (std::vector<std::string_view>{"vdb", "png"}));
}

}  // namespace
}  // namespace shapevo

// ImageScorer: chromosome -> geometry -> silhouette through a camera -> pixel counts against
// one ImageTarget -> fitness (image_fitness.hpp). A pure function of the chromosome; each thread
// brings its own Workspace (derive scratch, geometry, raster).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "score/image/camera.hpp"
#include "score/image/image_fitness.hpp"
#include "score/image/image_model.hpp"
#include "score/image/image_target.hpp"
#include "score/image/model_store.hpp"
#include "score/primitive_cache.hpp"
#include "score/tree_scorer.hpp"
#include "score/image/silhouette_raster.hpp"

namespace shapevo {

class ImageScorer final : public TreeScorer {
public:
    struct Workspace : ScoreWorkspace {
        /// cacheBytes > 0: keep the primitives' rows (incremental scoring, Scorer::setIncremental):
        /// a quarter for the subtree memo, a quarter for whole subtrees' words, half for primitives'.
        explicit Workspace(const Camera& camera, std::size_t cacheBytes = 0) : raster(camera) {
            if (cacheBytes == 0) return;
            derive.memo = std::make_unique<SubtreeMemo>(subtreeMemoBytes(cacheBytes));
            subtrees.emplace(subtreeMemoBytes(cacheBytes));
            cache.emplace(cacheBytes - 2 * subtreeMemoBytes(cacheBytes));
        }
        SilhouetteRaster raster;
        std::optional<PrimitiveCache<WordMask>> cache;
        /// The words whole subtrees set (their primitives' words merged: one OR per word), by the
        /// start that names each subtree's primitives (DeriveScratch::reused).
        std::optional<PrimitiveCache<WordMask, SubtreeKey>> subtrees;
        std::size_t cacheBytesUsed() const override {
            return ScoreWorkspace::cacheBytesUsed() + (cache ? cache->bytesUsed() : 0) +
                   (subtrees ? subtrees->bytesUsed() : 0);
        }
        std::vector<RowSpan> spans;  ///< one primitive's rows, on their way into the cache as...
        std::vector<WordMask> words;  ///< ...the words they set
        std::vector<CacheProbe<WordMask>> probes;  ///< the primitives to look up, with their keys' hashes (after prefetching)
        /// Subtrees replayed whole (primitive index ranges), and those to keep whole once drawn
        /// with the words their primitives set, gathered in `gathered`.
        struct SubtreeRange {
            std::uint32_t first, end;
            std::uint64_t hash = 0, bounds = 0;
            std::size_t from = 0;  ///< its words' start in `gathered`
            SubtreeKey key;
        };
        std::vector<SubtreeRange> replayed, toKeep;
        std::vector<WordMask> gathered;
        std::vector<std::uint64_t> merged;  ///< one word per raster word, zero between merges
        std::vector<SubtreeStart> starts;     ///< fromParent: where the changed subtree starts
        std::vector<std::uint32_t> walkStack;  ///< fromParent: genes of a subtree still to be measured
        std::shared_ptr<ModelStore> models;  ///< the scorer's (its blocks' pool outlives `coverage`)
        CoverageCounts coverage;  ///< fromParent: the child's coverage counts (an overlay on the parent's)
    };

    /// `target` must outlive the scorer and have the camera's size (loadImageTarget checks that
    /// against the camera; a mismatch here is a programming error: std::invalid_argument).
    ImageScorer(const Grammar& g, const Camera& camera, const ImageTarget& target, const FitnessSettings& settings)
        : grammar_(g), camera_(camera), target_(target), settings_(settings) {
        if (target.width != camera.width() || target.height != camera.height())
            throw std::invalid_argument("ImageScorer: the target's size differs from the camera's");
        coverageLayout_ = CoverageLayout(std::uint32_t(target.wordsPerRow()), std::uint32_t(target.height));
    }

    std::unique_ptr<ScoreWorkspace> makeWorkspace() const override {
        auto w = std::make_unique<Workspace>(camera_, cacheBytes());
        w->models = models_;
        return w;
    }
    /// Also bounds what its models may keep for their children: `bytes` (score.cache_mb) per island.
    void setIncremental(std::size_t bytes, bool check = false) override {
        Scorer::setIncremental(bytes, check);
        models_->setBound(bytes);
    }
    std::unique_ptr<ScoreWorkspace> makePlainWorkspace() const override {
        return std::make_unique<Workspace>(camera_, 0);
    }
    double fitness(const Chromosome& c, ScoreWorkspace& w) const override {
        return fitness(c, static_cast<Workspace&>(w), nullptr);
    }
    /// Asks for the parent's chromosome (a generation old, read when the child is scored from it).
    void prepare(const Chromosome& c) const override;
    double fitness(const Chromosome& c, Workspace& w, SilhouetteCounts* countsOut) const {
        w.made.reset();
        SilhouetteCounts counts;
        if (c.lineage.changed() && w.cache) {
            const auto* parent = c.lineage.parent->maker == models_.get() ? static_cast<const ImageModel*>(c.lineage.parent.get()) : nullptr;
            if (parent && fromParent(c, *parent, w, counts)) {
                ++w.fromParent;
                if (countsOut) *countsOut = counts;
                return imageFitness(settings_, counts, target_.hitCount, c.genes);
            }
            ++w.notFromParent;
        }
        if (!deriveCounted(c, w)) {
            if (countsOut) *countsOut = SilhouetteCounts{};
            return kWorstFitness;
        }
        if (throughCache(w.cache, w.geometry.primitives.size())) {
            drawCached(w);
            counts = w.raster.score(target_);
            if (checksIncremental()) checkAgainstFull(w.geometry, w, counts);
        } else {
            w.raster.add(w.geometry);
            counts = w.raster.score(target_);
        }
        // With incremental scoring, what its children start from (scoring from the parent).
        if (w.cache && w.status == DeriveStatus::Complete) w.made = keep(c, w.geometry.primitives.size(), w.derive.tasks, counts);
        if (countsOut) *countsOut = counts;
        return imageFitness(settings_, counts, target_.hitCount, c.genes);
    }
    /// The chromosome's silhouette, one byte per pixel (rows from the top): 0 = empty, 1 = model.
    void modelMask(const Chromosome& c, Workspace& w, std::vector<std::uint8_t>& mask) const;

    const Camera& camera() const { return camera_; }
    const ImageTarget& target() const { return target_; }
    /// Where its models come from, and the memory they take (ModelStore::bytesInUse).
    const ModelStore& models() const { return *models_; }
    bool modelsFull() const override { return models_->full(); }
    std::size_t modelBytesInUse() const override { return models_->bytesInUse(); }
    const Grammar& grammar() const override { return grammar_; }

private:
    /// Draw w.geometry, replaying the rows of primitives found in w.cache and keeping the others'.
    void drawCached(Workspace& w) const;
    /// Draw `geometry` the full way (no cache); throw IncrementalMismatch unless it gives `counts`.
    void checkAgainstFull(const Geometry& geometry, Workspace& w, const SilhouetteCounts& counts) const;

    // Scoring from the parent (image_from_parent.cpp).
    /// Score `c`, whose lineage names one changed subtree of `parent`, from the parent's
    /// coverage counts: take out the old subtree's primitives, put in the new one's. Sets
    /// `counts`, w.status and w.made; false (nothing set) when the model must be scored the full
    /// way: a subtree at the root, a lineage that does not fit the chromosomes, a derivation that
    /// would not be Complete.
    bool fromParent(const Chromosome& c, const ImageModel& parent, Workspace& w, SilhouetteCounts& counts) const;
    /// apply(words) with the words each primitive of w.geometry sets (from the primitive cache,
    /// or drawn and kept there; lookups prefetched first). Leaves drawing in w.raster, which the
    /// caller clears.
    template <class Apply>
    void eachPrimitivesWords(Workspace& w, Apply&& apply) const;
    /// What a Complete model leaves for its children (its coverage counts: `overlay`, on the
    /// counts of `parent`, swapped in, or made when first asked for), or null if the models'
    /// bound leaves no room for it.
    std::shared_ptr<const EvaluatedModel> keep(const Chromosome& c, std::size_t primitives, std::size_t tasks,
                                               const SilhouetteCounts& counts, CoverageCounts* overlay = nullptr,
                                               const std::shared_ptr<const EvaluatedModel>& parent = nullptr) const;
    /// The coverage counts of `m`, made by deriving and drawing it whole.
    void makeCoverage(const ImageModel& m, Workspace& w, CoverageCounts& out) const;

    const Grammar& grammar_;
    Camera camera_;
    const ImageTarget& target_;
    FitnessSettings settings_;
    CoverageLayout coverageLayout_;  ///< the target's picture, in the tiles of its coverage counts
    std::shared_ptr<ModelStore> models_ = ModelStore::make();
};

/// The silhouette of `geometry` through `camera`, one byte per pixel (rows from the top):
/// 0 = empty, 1 = model; `mask` is resized to width * height.
void silhouetteMask(const Geometry& geometry, const Camera& camera, std::vector<std::uint8_t>& mask);

}  // namespace shapevo

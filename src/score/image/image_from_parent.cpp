// ImageScorer from the parent: a child whose operator changed one subtree (Lineage) is scored
// from its parent's coverage counts (score/image/image_model.hpp). Exact because a subtree's
// derivation depends only on its content and its start (geometry/subtree_memo.hpp), the starts
// of the changed subtree are the parent's (its ancestors did not change: the operators name the
// gene whose own derivation changed, geometry/derive.hpp findSubtreeStarts), and a derivation is
// Complete exactly when its totals of primitives and tasks are within the limits.
#include <algorithm>
#include <optional>
#include <vector>

#include "score/image/image_scorer.hpp"

namespace shapevo {

namespace {
/// Genes and words of the subtree at `root` of `c` (`stack`: scratch).
void measureSubtree(const Grammar& g, const Chromosome& c, std::uint32_t root, std::vector<std::uint32_t>& stack,
                    std::uint32_t& geneCount, std::uint32_t& words) {
    geneCount = words = 0;
    stack.assign(1, root);
    while (!stack.empty()) {
        const std::uint32_t pos = stack.back();
        stack.pop_back();
        const Rule& r = g.rules[c.rule(pos)];
        ++geneCount;
        words += r.geneWords();
        for (std::uint32_t e = 0; e < r.childOffsets; ++e)
            if (c.child(pos, e) > 0) stack.push_back(pos + std::uint32_t(c.child(pos, e)));
    }
}
}  // namespace

void ImageScorer::prepare(const Chromosome& c) const {
    if (!c.lineage.changed() || c.lineage.parent->maker != models_.get()) return;
    const auto& parent = static_cast<const ImageModel&>(*c.lineage.parent);
    const char* const first = reinterpret_cast<const char*>(parent.chromosome.words.data());
    const std::size_t bytes = parent.chromosome.words.size() * sizeof(std::uint32_t);
    for (std::size_t at = 0; at < bytes; at += 64) __builtin_prefetch(first + at);
    parent.prefetchCoverageHandles();
}

template <class Apply>
void ImageScorer::eachPrimitivesWords(Workspace& w, Apply&& apply) const {
    drawThroughCache(
        *w.cache, w.geometry.primitives, w.probes, w.words, [](const Primitive&, std::size_t) { return false; },
        [&](const PrimitiveCache<WordMask>::Found& found, std::size_t) { apply(found.records); },
        [&](const Primitive& p, std::vector<WordMask>& words) -> std::uint64_t {
            w.spans.clear();
            w.raster.addRecorded(p, w.geometry.meshes, w.spans);
            w.raster.wordMasks(w.spans, words);
            return SilhouetteRaster::boundsOf(w.spans);
        },
        [&](std::span<const WordMask> words, std::uint64_t, std::size_t) { apply(words); });
}

std::shared_ptr<const EvaluatedModel> ImageScorer::keep(const Chromosome& c, std::size_t primitives, std::size_t tasks,
                                                        const SilhouetteCounts& counts, CoverageCounts* overlay,
                                                        const std::shared_ptr<const EvaluatedModel>& parent) const {
    // (its coverage counts, if still to be made, are reserved when a child asks for them)
    const ModelStore::Reservation room = models_->reserve(ModelStore::estimate(c.size()));
    if (!room) return nullptr;
    std::shared_ptr<ImageModel> m = models_->take();
    m->maker = models_.get();  // (outlives every model it made, unlike the scorer)
    m->chromosome.words.assign(c.words.begin(), c.words.end());
    m->chromosome.genes = c.genes;
    m->primitives = primitives;
    m->tasks = tasks;
    m->counts = counts;
    if (overlay) m->setOverlay(*overlay, parent);
    models_->count(*m);
    return m;
}

void ImageScorer::makeCoverage(const ImageModel& m, Workspace& w, CoverageCounts& out) const {
    derive(grammar_, m.chromosome, w.geometry, w.derive, maxPrimitives());
    out.reset(coverageLayout_, &models_->blocks());
    CoverageCounts::Delta delta;
    eachPrimitivesWords(w, [&](std::span<const WordMask> words) { out.add(words, target_, delta); });
    w.raster.clear();
    if (std::uint64_t(delta.covered) != m.counts.covered || std::uint64_t(delta.hit) != m.counts.hit ||
        std::uint64_t(delta.avoided) != m.counts.avoided)
        throw IncrementalMismatch("ImageScorer: a model's coverage counts differ from its pixel counts");
}

bool ImageScorer::fromParent(const Chromosome& c, const ImageModel& parent, Workspace& w, SilhouetteCounts& counts) const {
    const Lineage& l = c.lineage;
    const Chromosome& before = parent.chromosome;
    const std::uint32_t none = Lineage::kNone;
    if (l.childGene == 0 || l.parentGene == 0) return false;  // the whole model changed
    if ((l.childGene != none && l.childGene >= c.size()) || (l.parentGene != none && l.parentGene >= before.size()))
        return false;
    // The lineage must account for the sizes: the parent less its old subtree plus the new one.
    std::uint32_t oldGenes = 0, oldWords = 0, newGenes = 0, newWords = 0;
    if (l.parentGene != none) measureSubtree(grammar_, before, l.parentGene, w.walkStack, oldGenes, oldWords);
    if (l.childGene != none) measureSubtree(grammar_, c, l.childGene, w.walkStack, newGenes, newWords);
    if (std::uint64_t(before.genes) + newGenes != std::uint64_t(c.genes) + oldGenes ||
        std::uint64_t(before.size()) + newWords != std::uint64_t(c.size()) + oldWords)
        return false;
    // Where the subtree starts: found in the child, or (a subtree removed) in the parent.
    const DeriveStatus found = l.childGene != none ? findSubtreeStarts(grammar_, c, l.childGene, w.derive, w.starts, maxPrimitives())
                                                   : findSubtreeStarts(grammar_, before, l.parentGene, w.derive, w.starts, maxPrimitives());
    if (found != DeriveStatus::Complete) return false;
    // The child's counts: an overlay on the parent's (made now if no child asked before and there
    // is room for them), which copies only the blocks it writes; then out with the old subtree
    // and in with the new one, each start in turn.
    CoverageCounts& coverage = w.coverage;
    {
        std::optional<ModelStore::Reservation> room;
        if (!parent.coverageAtHand()) {
            room.emplace(models_->reserve(models_->estimateCoverage(coverageLayout_.blocks())));
            if (!*room) return false;
        }
        coverage.overlay(parent.coverage([&](CoverageCounts& out) {
            makeCoverage(parent, w, out);
            models_->noteCoverage(out.bytes());
        }));
    }
    CoverageCounts::Delta delta;
    std::int64_t primitives = std::int64_t(parent.primitives), tasks = std::int64_t(parent.tasks);
    bool complete = true;
    for (const SubtreeStart& start : w.starts) {
        if (l.parentGene != none) {
            if (deriveSubtree(grammar_, before, l.parentGene, start, w.geometry, w.derive, maxPrimitives()) != DeriveStatus::Complete) {
                complete = false;  // (cannot happen: it was part of a Complete derivation)
                break;
            }
            primitives -= std::int64_t(w.geometry.primitives.size());
            tasks -= std::int64_t(w.derive.tasks);
            eachPrimitivesWords(w, [&](std::span<const WordMask> words) { coverage.remove(words, target_, delta); });
        }
        if (l.childGene != none) {
            if (deriveSubtree(grammar_, c, l.childGene, start, w.geometry, w.derive, maxPrimitives()) != DeriveStatus::Complete) {
                complete = false;  // a non-finite number, or past the limits on its own
                break;
            }
            primitives += std::int64_t(w.geometry.primitives.size());
            tasks += std::int64_t(w.derive.tasks);
            eachPrimitivesWords(w, [&](std::span<const WordMask> words) { coverage.add(words, target_, delta); });
        }
    }
    w.raster.clear();
    if (!complete || primitives > std::int64_t(maxPrimitives()) || tasks > std::int64_t(maxDeriveTasks(maxPrimitives()))) {
        coverage.clear();
        return false;
    }
    counts = SilhouetteCounts{};
    counts.covered = std::uint64_t(std::int64_t(parent.counts.covered) + delta.covered);
    counts.hit = std::uint64_t(std::int64_t(parent.counts.hit) + delta.hit);
    counts.avoided = std::uint64_t(std::int64_t(parent.counts.avoided) + delta.avoided);
    w.status = DeriveStatus::Complete;
    if (checksIncremental()) {
        derive(grammar_, c, w.checkGeometry, w.checkDerive, maxPrimitives());  // no memo
        checkAgainstFull(w.checkGeometry, w, counts);
    }
    w.made = keep(c, std::size_t(primitives), std::size_t(tasks), counts, &coverage, c.lineage.parent);
    coverage.clear();  // (the blocks of the model kept, or of none)
    return true;
}

}  // namespace shapevo

// ImageScorer: incremental drawing and its check, and the model masks for overlays (the rest of
// the hot path lives in the header).
#include "score/image/image_scorer.hpp"

#include <algorithm>
#include <string>

namespace shapevo {

namespace {
/// Subtrees of fewer primitives are looked up primitive by primitive only.
constexpr std::uint32_t kWholeSubtreeMin = 3;

/// The rectangle of two SilhouetteRaster::boundsOf numbers (0: none).
std::uint64_t unionOfBounds(std::uint64_t a, std::uint64_t b) {
    if (a == 0 || b == 0) return a | b;
    auto field = [](std::uint64_t v, int k) { return std::uint64_t(v >> (16 * k) & 0xffff); };
    return std::min(field(a, 0), field(b, 0)) | std::max(field(a, 1), field(b, 1)) << 16 |
           std::min(field(a, 2), field(b, 2)) << 32 | std::max(field(a, 3), field(b, 3)) << 48;
}

/// Merge the masks of equal indices among the `n` words at `words`, in place (first places kept);
/// returns how many remain. `scratch` has a zero word per index and is left all zero.
std::size_t mergeWords(WordMask* words, std::size_t n, std::vector<std::uint64_t>& scratch) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t& at = scratch[words[i].index];
        if (at == 0) words[out++].index = words[i].index;  // first seen: its place in the output
        at |= words[i].mask();
    }
    for (std::size_t i = 0; i < out; ++i) {
        std::uint64_t& at = scratch[words[i].index];
        words[i].low = std::uint32_t(at);
        words[i].high = std::uint32_t(at >> 32);
        at = 0;
    }
    return out;
}
}  // namespace

void ImageScorer::drawCached(Workspace& w) const {
    // Whole subtrees the derivation copied from its memo: one replay each if their words are kept;
    // otherwise their primitives go through the cache as any other and their words are gathered.
    w.replayed.clear();
    w.toKeep.clear();
    w.merged.resize(w.raster.bits().size());  // all zero between calls
    PrimitiveCache<WordMask, SubtreeKey>::Found whole;
    for (const DeriveScratch::ReusedSubtree& r : w.derive.reused) {
        if (r.count < kWholeSubtreeMin) continue;
        // The start's hash is the key's (both quickHash of the same words): not computed twice.
        const Workspace::SubtreeRange range{r.first, r.first + r.count, r.start.hash, 0, 0, SubtreeKey(r.start)};
        if (w.subtrees->find(range.key, range.hash, whole)) {
            w.raster.replay(whole.records, whole.extra);
            w.replayed.push_back(range);
        } else {
            w.toKeep.push_back(range);
        }
    }
    w.gathered.clear();
    std::size_t skip = 0, keep = 0;
    auto gather = [&](std::span<const WordMask> words, std::uint64_t bounds, std::size_t i) {
        while (keep < w.toKeep.size() && w.toKeep[keep].end <= i) ++keep;
        if (keep == w.toKeep.size() || i < w.toKeep[keep].first) return;
        Workspace::SubtreeRange& range = w.toKeep[keep];
        if (i == range.first) range.from = w.gathered.size();
        w.gathered.insert(w.gathered.end(), words.begin(), words.end());
        range.bounds = unionOfBounds(range.bounds, bounds);
    };
    drawThroughCache(
        *w.cache, w.geometry.primitives, w.probes, w.words,
        [&](const Primitive&, std::size_t i) {  // skip the subtrees replayed whole
            while (skip < w.replayed.size() && w.replayed[skip].end <= i) ++skip;
            return skip < w.replayed.size() && i >= w.replayed[skip].first;
        },
        [&](const PrimitiveCache<WordMask>::Found& found, std::size_t i) {
            w.raster.replay(found.records, found.extra);
            gather(found.records, found.extra, i);
        },
        [&](const Primitive& p, std::vector<WordMask>& words) -> std::uint64_t {
            w.spans.clear();
            w.raster.addRecorded(p, w.geometry.meshes, w.spans);
            w.raster.wordMasks(w.spans, words);
            return SilhouetteRaster::boundsOf(w.spans);  // kept beside the words: replay needs no per-word bookkeeping
        },
        [&](std::span<const WordMask> words, std::uint64_t bounds, std::size_t i) { gather(words, bounds, i); });
    for (std::size_t k = 0; k < w.toKeep.size(); ++k) {
        const Workspace::SubtreeRange& range = w.toKeep[k];
        const std::size_t end = k + 1 < w.toKeep.size() ? w.toKeep[k + 1].from : w.gathered.size();
        const std::size_t n = mergeWords(w.gathered.data() + range.from, end - range.from, w.merged);
        w.subtrees->store(range.key, range.hash, std::span<const WordMask>(w.gathered.data() + range.from, n), range.bounds);
    }
    if (w.cache->full()) noteCacheFull();
}

void ImageScorer::checkAgainstFull(const Geometry& geometry, Workspace& w, const SilhouetteCounts& counts) const {
    w.raster.add(geometry);
    const SilhouetteCounts full = w.raster.score(target_);
    if (full.covered != counts.covered || full.hit != counts.hit || full.avoided != counts.avoided)
        throw IncrementalMismatch("incremental image scoring differs from the full one: covered/hit/avoided " +
                                  std::to_string(counts.covered) + "/" + std::to_string(counts.hit) + "/" +
                                  std::to_string(counts.avoided) + " against " + std::to_string(full.covered) + "/" +
                                  std::to_string(full.hit) + "/" + std::to_string(full.avoided) + " (" +
                                  std::to_string(geometry.primitives.size()) + " primitives)");
}

void ImageScorer::modelMask(const Chromosome& c, Workspace& w, std::vector<std::uint8_t>& mask) const {
    derive(grammar_, c, w.geometry, w.derive, maxPrimitives());  // a non-finite primitive is left out
    w.raster.clear();
    w.raster.add(w.geometry);
    w.raster.fillMask(mask);
    w.raster.clear();
}

void silhouetteMask(const Geometry& geometry, const Camera& camera, std::vector<std::uint8_t>& mask) {
    SilhouetteRaster raster(camera);
    raster.add(geometry);
    raster.fillMask(mask);
}

}  // namespace shapevo

// DrawingScorer: derive, draw, rasterize, count (drawing_scorer.hpp).
#include "score/image/drawing_scorer.hpp"

#include <bit>
#include <cmath>

#include "base/input_error.hpp"

namespace shapevo {

namespace {

/// OR of `in` shifted by -k..k bits along a row of `words` words (bit i = pixel i).
void spreadRow(const std::uint64_t* in, std::uint64_t* out, std::size_t words, int k) {
    for (std::size_t i = 0; i < words; ++i) out[i] = in[i];
    // Doubling: after a step of s, each set bit covers [i - reach, i + reach]; reach grows to k.
    int reach = 0;
    while (reach < k) {
        const int s = std::min(reach + 1, k - reach);
        for (int dir = 0; dir < 2; ++dir) {
            // out |= out shifted by s (left then right), word by word from a copy-free order
            if (dir == 0) {
                for (std::size_t i = words; i-- > 0;) {
                    std::uint64_t v = out[i] << s;
                    if (i > 0) v |= out[i - 1] >> (64 - s);
                    out[i] |= v;
                }
            } else {
                for (std::size_t i = 0; i < words; ++i) {
                    std::uint64_t v = out[i] >> s;
                    if (i + 1 < words) v |= out[i + 1] << (64 - s);
                    out[i] |= v;
                }
            }
        }
        reach += s;
    }
}

}  // namespace

DrawingScorer::DrawingScorer(const GraphFamily& family, const ImageTarget& target, const graph::RasterFrame& frame,
                             const FitnessSettings& settings, int tolerancePixels)
    : family_(family), target_(target), frame_(frame), settings_(settings), tolerance_(tolerancePixels) {
    for (int dy = -tolerance_; dy <= tolerance_; ++dy)
        reach_.push_back(int(std::floor(std::sqrt(double(tolerance_) * tolerance_ - double(dy) * dy))));
    // The hit pixels grown by the disc, once (by brute force over the disc: a target is small).
    const int W = target.width, H = target.height;
    const std::size_t wpr = std::size_t(target.wordsPerRow());
    nearHit_.assign(target.hit.size(), 0);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (!target.isHit(x, y)) continue;
            for (int dy = -tolerance_; dy <= tolerance_; ++dy) {
                const int yy = y + dy;
                if (yy < 0 || yy >= H) continue;
                const int r = reach_[std::size_t(dy + tolerance_)];
                for (int xx = std::max(0, x - r); xx <= std::min(W - 1, x + r); ++xx)
                    nearHit_[std::size_t(yy) * wpr + std::size_t(xx >> 6)] |= std::uint64_t(1) << (xx & 63);
            }
        }
}

graph::Drawing DrawingScorer::drawing(const Chromosome& c) const {
    return family_.drawing(c);
}

void DrawingScorer::grow(Workspace& w) const {
    const std::vector<std::uint64_t>& bits = w.raster.bits();
    const std::size_t wpr = std::size_t(target_.wordsPerRow());
    w.grown.assign(bits.size(), 0);
    w.row.resize(wpr);
    const int H = target_.height;
    for (int y = 0; y < H; ++y) {
        const std::uint64_t* in = bits.data() + std::size_t(y) * wpr;
        bool any = false;
        for (std::size_t i = 0; i < wpr && !any; ++i) any = in[i] != 0;
        if (!any) continue;
        for (int dy = -tolerance_; dy <= tolerance_; ++dy) {
            const int yy = y + dy;
            if (yy < 0 || yy >= H) continue;
            spreadRow(in, w.row.data(), wpr, reach_[std::size_t(dy + tolerance_)]);
            std::uint64_t* out = w.grown.data() + std::size_t(yy) * wpr;
            for (std::size_t i = 0; i < wpr; ++i) out[i] |= w.row[i];
        }
    }
    // bits past the width stay 0 in the counts: the target's rows have none there
}

double DrawingScorer::score(const Chromosome& c, Workspace& w, SilhouetteCounts* counts) const {
    w.made.reset();
    auto record = std::make_shared<GraphDerivationRecord>();
    try {
        const graph::DeriveResult r = family_.derive(c, &record->record);
        w.steps = r.steps;
        const graph::Drawing drawing = family_.drawing(r.graph);
        w.shapes = drawing.shapes.size();
        w.raster.rasterize(drawing, frame_);
    } catch (const InputError&) {
        countAgain(DeriveStatus::NonFinite);
        w.status = DeriveStatus::NonFinite;
        if (counts) *counts = {};
        w.made = std::move(record);
        return kWorstFitness;
    }
    w.status = DeriveStatus::Complete;
    w.made = std::move(record);
    const std::vector<std::uint64_t>& bits = w.raster.bits();
    SilhouetteCounts exact, tolerant;
    for (std::size_t i = 0; i < bits.size(); ++i) {
        exact.covered += std::uint64_t(std::popcount(bits[i]));
        exact.hit += std::uint64_t(std::popcount(bits[i] & target_.hit[i]));
        exact.avoided += std::uint64_t(std::popcount(bits[i] & target_.avoid[i]));
    }
    if (counts) *counts = exact;
    if (tolerance_ == 0) return imageFitness(settings_, exact, target_.hitCount, std::uint32_t(w.steps));
    grow(w);
    tolerant.covered = exact.covered;
    for (std::size_t i = 0; i < bits.size(); ++i) {
        tolerant.hit += std::uint64_t(std::popcount(w.grown[i] & target_.hit[i]));
        tolerant.avoided += std::uint64_t(std::popcount(bits[i] & target_.avoid[i] & ~nearHit_[i]));
    }
    return imageFitness(settings_, tolerant, target_.hitCount, std::uint32_t(std::min<std::int64_t>(w.steps, UINT32_MAX)));
}

}  // namespace shapevo

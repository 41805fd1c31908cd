// SilhouetteRaster: exact row bounds of convex pieces, word masks, counting over written words.
#include "score/image/silhouette_raster.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <stdexcept>

namespace shapevo {

namespace {
/// The 64-pixel words pixels lo..hi of one row cover, left to right: f(word, mask) for each
/// (markRow ORs them in; wordMasks keeps them for a replay).
template <class F>
inline void forEachWordOf(int lo, int hi, F&& f) {
    const int w0 = lo >> 6, w1 = hi >> 6;
    const std::uint64_t head = ~0ULL << (lo & 63), tail = ~0ULL >> (63 - (hi & 63));
    if (w0 == w1) {
        f(w0, head & tail);
        return;
    }
    f(w0, head);
    for (int w = w0 + 1; w < w1; ++w) f(w, ~0ULL);
    f(w1, tail);
}

/// q = floor(num / d), r = num - q d in [0, d), for d > 0 and |num| < 2^53: the estimate from the
/// double reciprocal is within one of q (relative error about 2^-52), the remainder corrects it.
inline void floorDivide(std::int64_t num, std::int64_t d, double inverse, std::int64_t& q, std::int64_t& r) {
    q = std::int64_t(std::floor(double(num) * inverse));
    r = num - q * d;
    if (r < 0) {
        --q;
        r += d;
    } else if (r >= d) {
        ++q;
        r -= d;
    }
}

/// Rows j with 256 j + 128 in [lo, hi] (pixel-centre rows of a fixed-point y range).
inline std::int64_t firstRow(std::int64_t lo) { return -((kSubpixels / 2 - lo) >> 8); }  // ceil((lo - 128) / 256)
inline std::int64_t lastRow(std::int64_t hi) { return (hi - kSubpixels / 2) >> 8; }     // floor((hi - 128) / 256)

}  // namespace

SilhouetteRaster::SilhouetteRaster(const Camera& camera)
    : width_(camera.width()), height_(camera.height()), words_((camera.width() + 63) / 64), camera_(camera),
      outline_(camera_), left_(std::size_t(height_)), right_(std::size_t(height_)),
      bits_(std::size_t(words_) * std::size_t(height_), 0) {
    forget();
}

bool SilhouetteRaster::allSet(int x0, int x1, int y0, int y1) const {
    const int w0 = x0 >> 6, w1 = x1 >> 6;
    const std::uint64_t first = ~0ULL << (x0 & 63), last = ~0ULL >> (63 - (x1 & 63));
    for (int y = y0; y <= y1; ++y) {
        const std::uint64_t* words = &bits_[std::size_t(y) * std::size_t(words_)];
        if (w0 == w1) {
            if ((words[w0] & first & last) != (first & last)) return false;
            continue;
        }
        if ((words[w0] & first) != first || (words[w1] & last) != last) return false;
        for (int w = w0 + 1; w < w1; ++w)
            if (words[w] != ~0ULL) return false;
    }
    return true;
}

void SilhouetteRaster::add(const Primitive& p, const std::vector<MeshShape>* meshes) {
    if (!outline_.prepare(p, meshes)) return;
    int x0, x1, y0, y1;
    if (outline_.coverBound(x0, x1, y0, y1) && (x0 > x1 || y0 > y1 || allSet(x0, x1, y0, y1)))
        return;  // no pixel centre within reach, or every one already covered: nothing would change
    pieces_.clear();
    outline_.addPrepared(pieces_);
    for (const OutlinePiece& piece : pieces_.pieces) fillConvex(hull_.of(pieces_.points.data(), piece));
}

void SilhouetteRaster::addRecorded(const Primitive& p, const std::vector<MeshShape>* meshes, std::vector<RowSpan>& spans) {
    if (!outline_.prepare(p, meshes)) return;
    int x0, x1, y0, y1;
    if (outline_.coverBound(x0, x1, y0, y1) && (x0 > x1 || y0 > y1)) return;  // no pixel centre within reach
    pieces_.clear();
    outline_.addPrepared(pieces_);
    const std::size_t first = spans.size();
    recording_ = &spans;
    for (const OutlinePiece& piece : pieces_.pieces) fillConvex(hull_.of(pieces_.points.data(), piece));
    recording_ = nullptr;
    // The pieces overlap: keep each row's union as few intervals (a replay then marks each pixel once).
    const auto begin = spans.begin() + std::ptrdiff_t(first);
    std::sort(begin, spans.end(), [](const RowSpan& a, const RowSpan& b) { return a.y != b.y ? a.y < b.y : a.lo < b.lo; });
    auto out = begin;
    for (auto in = begin; in != spans.end(); ++in) {
        if (out != begin && (out - 1)->y == in->y && in->lo <= (out - 1)->hi + 1)
            (out - 1)->hi = std::max((out - 1)->hi, in->hi);
        else
            *out++ = *in;
    }
    spans.erase(out, spans.end());
}

std::uint64_t SilhouetteRaster::boundsOf(std::span<const RowSpan> spans) {
    if (spans.empty()) return 0;
    int y0 = spans[0].y, y1 = y0, w0 = spans[0].lo >> 6, w1 = spans[0].hi >> 6;
    for (const RowSpan& r : spans) {
        y0 = std::min(y0, int(r.y)), y1 = std::max(y1, int(r.y));
        w0 = std::min(w0, int(r.lo >> 6)), w1 = std::max(w1, int(r.hi >> 6));
    }
    return std::uint64_t(y0) | std::uint64_t(y1) << 16 | std::uint64_t(w0) << 32 | std::uint64_t(w1) << 48;
}

void SilhouetteRaster::wordMasks(std::span<const RowSpan> spans, std::vector<WordMask>& words) const {
    const std::size_t first = words.size();
    for (const RowSpan& r : spans) {
        const std::uint32_t row = std::uint32_t(r.y) * std::uint32_t(words_);
        forEachWordOf(r.lo, r.hi, [&](int w, std::uint64_t mask) {
            const std::uint32_t index = row + std::uint32_t(w);
            if (words.size() > first && words.back().index == index) {  // spans of one row meeting in a word
                words.back().low |= std::uint32_t(mask), words.back().high |= std::uint32_t(mask >> 32);
                return;
            }
            words.push_back({index, std::uint32_t(mask), std::uint32_t(mask >> 32)});
        });
    }
}

void SilhouetteRaster::replay(std::span<const WordMask> words, std::uint64_t bounds) {
    if (words.empty()) return;
    std::uint64_t* bits = bits_.data();
    for (const WordMask& m : words) bits[m.index] |= m.mask();
    yMin_ = std::min(yMin_, int(bounds & 0xffff)), yMax_ = std::max(yMax_, int(bounds >> 16 & 0xffff));
    wordMin_ = std::min(wordMin_, int(bounds >> 32 & 0xffff)), wordMax_ = std::max(wordMax_, int(bounds >> 48));
}

inline void SilhouetteRaster::markRow(int y, int lo, int hi) {
    std::uint64_t* words = &bits_[std::size_t(y) * std::size_t(words_)];
    forEachWordOf(lo, hi, [&](int w, std::uint64_t mask) { words[w] |= mask; });
}

void SilhouetteRaster::fillConvex(std::span<const FixedPoint> hull) {
    const std::size_t n = hull.size();
    if (n < 3) return;  // no area
    std::int32_t xmin = hull[0].x, xmax = hull[0].x, ymin = hull[0].y, ymax = hull[0].y;
    for (const FixedPoint& v : hull) {
        xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x);
        ymin = std::min(ymin, v.y), ymax = std::max(ymax, v.y);
    }
    const std::int64_t top = std::max<std::int64_t>(firstRow(ymin), 0);
    const std::int64_t bottom = std::min<std::int64_t>(lastRow(ymax), height_ - 1);
    const std::int64_t leftmost = std::max<std::int64_t>(firstRow(xmin), 0);  // the same rounding for columns
    const std::int64_t rightmost = std::min<std::int64_t>(lastRow(xmax), width_ - 1);
    if (top > bottom || leftmost > rightmost) return;  // no pixel centre in the bounding box
    // Edge a -> b keeps the pixel centres p with E(p) = dx (p.y - a.y) - dy (p.x - a.x) >= 0.
    // With p.x = 256 i + 128: E = C - 256 dy i, C = dx (p.y - a.y) - dy (128 - a.x), so
    // dy < 0 gives i >= ceil(-C / (256 |dy|)) (a left edge), dy > 0 gives i <= floor(C / (256 dy)).
    // On a row, the left and the right edge that span it bound the convex hull exactly.
    // Per edge, the first row's bound and the per-row step are integer quotients with remainders
    // (floorDivide: exact); further rows step quotient and remainder in integers. Numerators stay
    // below 2^53 in magnitude: coordinates are within +-2^23 fixed units.
    for (std::size_t e = 0; e < n; ++e) {
        const FixedPoint a = hull[e], b = hull[e + 1 == n ? 0 : e + 1];
        const std::int64_t dy = std::int64_t(b.y) - a.y;
        if (dy == 0) continue;
        const std::int64_t j0 = std::max(firstRow(std::min<std::int64_t>(a.y, b.y)), top);
        const std::int64_t j1 = std::min(lastRow(std::max<std::int64_t>(a.y, b.y)), bottom);
        if (j0 > j1) continue;
        const std::int64_t dx = std::int64_t(b.x) - a.x;
        const std::int64_t py = kSubpixels * j0 + kSubpixels / 2;
        const std::int64_t c = dx * (py - a.y) - dy * (kSubpixels / 2 - a.x);
        const int rows = int(j1 - j0 + 1);
        // left: i >= ceil(num / d); right: i <= floor(num / d); num grows by `step` per row
        const bool isLeft = dy < 0;
        const std::int64_t d = kSubpixels * (isLeft ? -dy : dy), num = isLeft ? -c : c;
        const std::int64_t step = isLeft ? -kSubpixels * dx : kSubpixels * dx;
        std::int32_t* out = (isLeft ? left_.data() : right_.data()) + j0;
        const double inverse = 1.0 / double(d);
        std::int64_t q, r, sq, sr;
        floorDivide(num, d, inverse, q, r);
        if (isLeft) out[0] = std::int32_t(q + (r != 0));
        else out[0] = std::int32_t(q);
        if (rows == 1) continue;
        // further rows: step quotient and remainder exactly (the remainder stays in [0, d))
        floorDivide(step, d, inverse, sq, sr);
        const std::int64_t ceilBias = isLeft ? 1 : 0;
        for (int k = 1; k < rows; ++k) {
            q += sq;
            r += sr;
            const bool carry = r >= d;
            q += carry;
            r -= carry ? d : 0;
            out[k] = std::int32_t(q + (r != 0 ? ceilBias : 0));
        }
    }
    rows_ += std::uint64_t(bottom - top + 1);
    bool drawn = false;
    for (std::int64_t j = top; j <= bottom; ++j) {
        const int lo = std::max(left_[std::size_t(j)], int(leftmost)), hi = std::min(right_[std::size_t(j)], int(rightmost));
        if (lo <= hi) {
            markRow(int(j), lo, hi), drawn = true;
            if (recording_) [[unlikely]]
                recording_->push_back({std::int32_t(j), lo, hi});
        }
    }
    if (drawn) {  // the rectangle counting and clearing must sweep
        yMin_ = std::min(yMin_, int(top)), yMax_ = std::max(yMax_, int(bottom));
        wordMin_ = std::min(wordMin_, int(leftmost >> 6)), wordMax_ = std::max(wordMax_, int(rightmost >> 6));
    }
}

SilhouetteCounts SilhouetteRaster::score(const ImageTarget& target) {
    if (target.width != width_ || target.height != height_)
        throw std::invalid_argument("SilhouetteRaster::score: target size differs from the camera's");
    SilhouetteCounts c;
    c.rows = rows_;
    const std::size_t W = std::size_t(words_);
    for (int y = yMin_; y <= yMax_; ++y) {
        std::uint64_t covered = 0, hit = 0, avoided = 0;
        for (std::size_t i = std::size_t(y) * W + std::size_t(wordMin_), end = std::size_t(y) * W + std::size_t(wordMax_) + 1; i < end; ++i) {
            const std::uint64_t m = bits_[i];
            covered += std::uint64_t(std::popcount(m));
            hit += std::uint64_t(std::popcount(m & target.hit[i]));
            avoided += std::uint64_t(std::popcount(m & target.avoid[i]));
            bits_[i] = 0;
        }
        c.covered += covered;
        c.hit += hit;
        c.avoided += avoided;
    }
    forget();
    return c;
}

void SilhouetteRaster::forget() {
    yMin_ = wordMin_ = INT_MAX;
    yMax_ = wordMax_ = -1;
    rows_ = 0;
}

void SilhouetteRaster::fillMask(std::vector<std::uint8_t>& mask) const {
    mask.assign(std::size_t(width_) * std::size_t(height_), 0);
    for (int y = yMin_; y <= yMax_; ++y)
        for (int x = 0; x < width_; ++x)
            mask[std::size_t(y) * std::size_t(width_) + std::size_t(x)] =
                std::uint8_t((bits_[std::size_t(y) * std::size_t(words_) + std::size_t(x >> 6)] >> (x & 63)) & 1);
}

void SilhouetteRaster::clear() {
    const std::size_t W = std::size_t(words_);
    for (int y = yMin_; y <= yMax_; ++y)
        std::fill(bits_.begin() + std::ptrdiff_t(std::size_t(y) * W + std::size_t(wordMin_)),
                  bits_.begin() + std::ptrdiff_t(std::size_t(y) * W + std::size_t(wordMax_) + 1), 0);
    forget();
}

}  // namespace shapevo

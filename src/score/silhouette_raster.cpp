// SilhouetteRaster: exact row bounds of convex pieces, word masks, counting over written words.
#include "score/silhouette_raster.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <stdexcept>

namespace shapevo {

namespace {

/// floor(num / d) for d > 0 and |num| < 2^53, with the remainder in [0, d). The double quotient
/// is within one of the true one; the integer check makes it exact.
inline void floorDivide(std::int64_t num, std::int64_t d, std::int64_t& q, std::int64_t& r) {
    q = std::int64_t(std::floor(double(num) / double(d)));
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
      bits_(std::size_t(words_) * std::size_t(height_), 0), wordLo_(std::size_t(height_), std::int16_t(words_)),
      wordHi_(std::size_t(height_), -1), yMin_(INT_MAX), yMax_(-1) {}

void SilhouetteRaster::add(const Primitive& p, const std::vector<MeshShape>* meshes) {
    pieces_.clear();
    outline_.add(p, meshes, pieces_);
    for (const OutlinePiece& piece : pieces_.pieces) fillConvex(hull_.of(pieces_.points.data(), piece));
}

void SilhouetteRaster::fillConvex(std::span<const FixedPoint> hull) {
    const std::size_t n = hull.size();
    if (n < 3) return;  // no area
    std::int64_t ymin = hull[0].y, ymax = hull[0].y;
    for (const FixedPoint& v : hull) {
        ymin = std::min<std::int64_t>(ymin, v.y);
        ymax = std::max<std::int64_t>(ymax, v.y);
    }
    const std::int64_t top = std::max<std::int64_t>(firstRow(ymin), 0);
    const std::int64_t bottom = std::min<std::int64_t>(lastRow(ymax), height_ - 1);
    if (top > bottom) return;
    // Edge a -> b keeps the pixel centres p with E(p) = dx (p.y - a.y) - dy (p.x - a.x) >= 0.
    // With p.x = 256 i + 128: E = C - 256 dy i, C = dx (p.y - a.y) - dy (128 - a.x), so
    // dy < 0 gives i >= ceil(-C / (256 |dy|)) (a left edge), dy > 0 gives i <= floor(C / (256 dy)).
    // On a row, the left and the right edge that span it bound the convex hull exactly.
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
        const bool isLeft = dy < 0;
        const std::int64_t d = kSubpixels * (isLeft ? -dy : dy);
        const std::int64_t num = isLeft ? -c : c, step = isLeft ? -kSubpixels * dx : kSubpixels * dx;
        std::int64_t q, r, sq, sr;
        floorDivide(num, d, q, r);
        floorDivide(step, d, sq, sr);
        std::int32_t* out = (isLeft ? left_.data() : right_.data()) + j0;
        const std::int64_t rows = j1 - j0 + 1;
        if (isLeft) {
            for (std::int64_t k = 0; k < rows; ++k) {
                out[k] = std::int32_t(q + (r != 0));
                q += sq;
                r += sr;
                if (r >= d) {
                    r -= d;
                    ++q;
                }
            }
        } else {
            for (std::int64_t k = 0; k < rows; ++k) {
                out[k] = std::int32_t(q);
                q += sq;
                r += sr;
                if (r >= d) {
                    r -= d;
                    ++q;
                }
            }
        }
    }
    rows_ += std::uint64_t(bottom - top + 1);
    for (std::int64_t j = top; j <= bottom; ++j) {
        const int lo = std::max(left_[std::size_t(j)], 0), hi = std::min(right_[std::size_t(j)], width_ - 1);
        if (lo <= hi) markRow(int(j), lo, hi);
    }
}

void SilhouetteRaster::markRow(int y, int lo, int hi) {
    yMin_ = std::min(yMin_, y);
    yMax_ = std::max(yMax_, y);
    const int w0 = lo >> 6, w1 = hi >> 6;
    const std::size_t row = std::size_t(y);
    wordLo_[row] = std::min<std::int16_t>(wordLo_[row], std::int16_t(w0));
    wordHi_[row] = std::max<std::int16_t>(wordHi_[row], std::int16_t(w1));
    std::uint64_t* words = &bits_[row * std::size_t(words_)];
    const std::uint64_t first = ~0ULL << (lo & 63), last = ~0ULL >> (63 - (hi & 63));
    if (w0 == w1) {
        words[w0] |= first & last;
        return;
    }
    words[w0] |= first;
    for (int w = w0 + 1; w < w1; ++w) words[w] = ~0ULL;
    words[w1] |= last;
}

SilhouetteCounts SilhouetteRaster::score(const ImageTarget& target) {
    if (target.width != width_ || target.height != height_)
        throw std::invalid_argument("SilhouetteRaster::score: target size differs from the camera's");
    SilhouetteCounts c;
    c.rows = rows_;
    const std::size_t W = std::size_t(words_);
    for (int y = yMin_; y <= yMax_; ++y) {
        const std::size_t row = std::size_t(y);
        std::uint64_t covered = 0, hit = 0, avoided = 0;
        for (std::size_t i = row * W + std::size_t(wordLo_[row]), end = row * W + std::size_t(wordHi_[row]) + 1; i < end; ++i) {
            const std::uint64_t m = bits_[i];
            covered += std::uint64_t(std::popcount(m));
            hit += std::uint64_t(std::popcount(m & target.hit[i]));
            avoided += std::uint64_t(std::popcount(m & target.avoid[i]));
            bits_[i] = 0;
        }
        c.covered += covered;
        c.hit += hit;
        c.avoided += avoided;
        wordLo_[row] = std::int16_t(words_);
        wordHi_[row] = -1;
    }
    yMin_ = INT_MAX;
    yMax_ = -1;
    rows_ = 0;
    return c;
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
    for (int y = yMin_; y <= yMax_; ++y) {
        const std::size_t row = std::size_t(y);
        if (wordLo_[row] <= wordHi_[row])
            std::fill(bits_.begin() + std::ptrdiff_t(row * W + std::size_t(wordLo_[row])),
                      bits_.begin() + std::ptrdiff_t(row * W + std::size_t(wordHi_[row]) + 1), 0);
        wordLo_[row] = std::int16_t(words_);
        wordHi_[row] = -1;
    }
    yMin_ = INT_MAX;
    yMax_ = -1;
    rows_ = 0;
}

}  // namespace shapevo

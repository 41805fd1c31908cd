// SilhouetteRaster: draws a model's silhouette into bit rows (one bit per pixel) and counts it
// against an image target. Each primitive becomes convex pieces (silhouette_outline.hpp); each
// piece's exact hull (fixed_hull.hpp) is filled row by row: on pixel row j the covered pixels are
// the integers i between the bounds of the hull's left and right edges at y = 256 j + 128,
// computed with exact integer steps (a quotient and remainder per edge, no rounding), then OR-ed
// in as word masks. So a pixel is set exactly when its centre lies in the closed hull, the same
// answer a point-in-polygon test gives pixel by pixel.
//
// A primitive is skipped before any of that when the projected corners of its box reach no pixel
// centre, or only pixels already drawn (the union would not change).
// addRecorded/wordMasks/replay serve incremental scoring (score/primitive_cache.hpp): a
// primitive's row intervals, kept as the words they set, draw the same pixels again without its
// outline, one OR per word.
// Bookkeeping: the rectangle of rows and words written since the last count, so counting and
// clearing touch only that rectangle.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "shape/primitive.hpp"
#include "score/image/camera.hpp"
#include "score/image/fixed_hull.hpp"
#include "score/image/image_target.hpp"
#include "score/image/silhouette_outline.hpp"

namespace shapevo {

/// One row interval a primitive drew: pixels lo..hi of row y (what addRecorded records).
struct RowSpan {
    std::int32_t y, lo, hi;
};

/// One word of bits() a primitive drew into: the bits of `mask()` in word `index` (what
/// PrimitiveCache keeps for it, so that a replay is one OR per word). 12 bytes, as a RowSpan.
struct WordMask {
    std::uint32_t index, low, high;
    std::uint64_t mask() const { return std::uint64_t(low) | std::uint64_t(high) << 32; }
};

struct SilhouetteCounts {
    std::uint64_t covered = 0;  ///< pixels the model covers
    std::uint64_t hit = 0;      ///< covered pixels that are hit pixels of the target
    std::uint64_t avoided = 0;  ///< covered pixels that are avoid pixels of the target
    std::uint64_t rows = 0;     ///< pixel rows convex pieces were drawn into (a work measure)
    bool operator==(const SilhouetteCounts&) const = default;
};

class SilhouetteRaster {
public:
    explicit SilhouetteRaster(const Camera& camera);
    SilhouetteRaster(const SilhouetteRaster&) = delete;  // holds a reference into itself (the outline builder's camera)
    SilhouetteRaster& operator=(const SilhouetteRaster&) = delete;

    /// Draw one primitive (`meshes`: the grammar's meshes, for Mesh primitives; may be null).
    void add(const Primitive& p, const std::vector<MeshShape>* meshes);
    void add(const Geometry& g) {
        for (const Primitive& p : g.primitives) add(p, g.meshes);
    }
    /// Draw one primitive as add() does, but never skip it for covering only pixels already
    /// drawn, and append every row interval it draws to `spans` (merged per row; as wordMasks()
    /// they replay() to the same pixels).
    void addRecorded(const Primitive& p, const std::vector<MeshShape>* meshes, std::vector<RowSpan>& spans);
    /// The words of bits() that `spans` (from addRecorded) set, in the order of the spans, one
    /// entry per word (spans sharing a word share its entry), appended to `words`.
    void wordMasks(std::span<const RowSpan> spans, std::vector<WordMask>& words) const;
    /// Draw the words wordMasks() gave for a primitive's spans: the same pixels as drawing the
    /// primitive. `bounds` = boundsOf(those spans), kept beside them in the cache, so that no
    /// word pays for the bookkeeping of the rectangle written. Adds nothing to the work measure
    /// (SilhouetteCounts::rows): a replay draws no piece.
    void replay(std::span<const WordMask> words, std::uint64_t bounds);
    /// The rows and 64-pixel words `spans` touch, packed in one number (16 bits each: pictures
    /// are at most 16,384 pixels a side); 0 for no spans.
    static std::uint64_t boundsOf(std::span<const RowSpan> spans);
    /// Draw one convex polygon of positive area given as its hull (counter-clockwise, no repeated
    /// points, every turn left or straight; fixed point).
    void fillConvex(std::span<const FixedPoint> hull);

    /// Count what was drawn against `target` (same size as the camera's picture) and clear.
    SilhouetteCounts score(const ImageTarget& target);
    /// The drawing as one byte per pixel, rows from the top: 0 = empty, 1 = model. `mask` is
    /// resized to width * height. Does not clear.
    void fillMask(std::vector<std::uint8_t>& mask) const;
    void clear();

    int width() const { return width_; }
    int height() const { return height_; }
    int wordsPerRow() const { return words_; }
    /// Bit rows of the current drawing (row y starts at word y * wordsPerRow(); bit i = pixel x).
    const std::vector<std::uint64_t>& bits() const { return bits_; }

private:
    void markRow(int y, int lo, int hi);
    bool allSet(int x0, int x1, int y0, int y1) const;  ///< every pixel of the rectangle drawn?
    void forget();  ///< mark everything clear (after the words were zeroed)

    int width_, height_, words_;
    const Camera camera_;
    OutlineBuilder outline_;
    Outline pieces_;
    FixedHull hull_;
    std::vector<std::int32_t> left_, right_;  ///< per row: covered pixel bounds of the piece being drawn
    std::vector<std::uint64_t> bits_;
    int yMin_, yMax_, wordMin_, wordMax_;  ///< the rectangle of rows and words written (empty: min > max)
    std::uint64_t rows_ = 0;
    std::vector<RowSpan>* recording_ = nullptr;  ///< during addRecorded: where fillConvex appends its rows
};

}  // namespace shapevo

// FixedHull: ring merge -> insertion sort -> monotone chain, all on integers.
#include "score/image/fixed_hull.hpp"

#include <algorithm>

namespace shapevo {

namespace {

bool less(FixedPoint a, FixedPoint b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

/// A ring in cyclic order -> x order: from its least point, merge the forward and the backward
/// walk (each x-monotone if the ring is convex; if not, the insertion sort repairs it).
void sortRing(const FixedPoint* ring, int n, FixedPoint* out) {
    int least = 0;
    for (int i = 1; i < n; ++i)
        if (less(ring[i], ring[least])) least = i;
    out[0] = ring[least];
    int f = least + 1 == n ? 0 : least + 1, b = least == 0 ? n - 1 : least - 1;
    for (int k = 1; k < n; ++k) {
        if (less(ring[b], ring[f])) {
            out[k] = ring[b];
            b = b == 0 ? n - 1 : b - 1;
        } else {
            out[k] = ring[f];
            f = f + 1 == n ? 0 : f + 1;
        }
    }
}

void merge(const FixedPoint* a, int na, const FixedPoint* b, int nb, FixedPoint* out) {
    int i = 0, j = 0, k = 0;
    while (i < na && j < nb) out[k++] = less(b[j], a[i]) ? b[j++] : a[i++];
    while (i < na) out[k++] = a[i++];
    while (j < nb) out[k++] = b[j++];
}

void insertionSort(FixedPoint* a, int n) {
    for (int i = 1; i < n; ++i) {
        const FixedPoint v = a[i];
        int j = i;
        while (j > 0 && less(v, a[j - 1])) {
            a[j] = a[j - 1];
            --j;
        }
        a[j] = v;
    }
}

/// If the cycle p[0..n) is a convex polygon winding once (repeated points and points along an
/// edge allowed), write it counter-clockwise without repeats to `out` and return its size; 0 if
/// it is not (`out` then holds scratch), -1 if it has no area (all points on one line).
int convexCycle(const FixedPoint* p, int n, FixedPoint* out) {
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (m == 0 || !(p[i] == out[m - 1])) out[m++] = p[i];
    while (m > 1 && out[m - 1] == out[0]) --m;
    if (m < 3) return -1;
    int left = 0, right = 0, ySwaps = 0, firstDy = 0, lastDy = 0;
    for (int i = 0; i < m; ++i) {
        const FixedPoint a = out[i == 0 ? m - 1 : i - 1], b = out[i], c = out[i + 1 == m ? 0 : i + 1];
        const std::int64_t o = orientation(a, b, c);
        if (o > 0) ++left;
        else if (o < 0) ++right;
        else if ((std::int64_t(b.x) - a.x) * (std::int64_t(c.x) - b.x) + (std::int64_t(b.y) - a.y) * (std::int64_t(c.y) - b.y) < 0)
            return 0;  // turns back along a line
        const int dy = (c.y > b.y) - (c.y < b.y);
        if (dy != 0) {
            if (lastDy == 0) firstDy = dy;
            ySwaps += lastDy != 0 && dy != lastDy;
            lastDy = dy;
        }
    }
    ySwaps += lastDy != 0 && firstDy != lastDy;  // close the cycle
    if (left == 0 && right == 0) return -1;
    if ((left != 0 && right != 0) || ySwaps != 2) return 0;  // a dent, or winding more than once
    if (right != 0) std::reverse(out, out + m);
    return m;
}

}  // namespace

std::span<const FixedPoint> FixedHull::of(const FixedPoint* points, const OutlinePiece& piece) {
    const int n = int(piece.count);
    const FixedPoint* p = points + piece.first;
    if (sorted_.size() < std::size_t(n)) {
        sorted_.resize(std::size_t(n));
        merged_.resize(std::size_t(n));
        hull_.resize(2 * std::size_t(n) + 1);
    }
    if (piece.rings == 1 && piece.ringSize == piece.count) {  // maybe already a convex polygon in order
        const int m = convexCycle(p, n, hull_.data());
        if (m > 0) return {hull_.data(), std::size_t(m)};
        if (m < 0) return {};
    }
    FixedPoint *s = sorted_.data(), *spare = merged_.data(), *ring = hull_.data();  // hull_ is free until the chain
    const int ringSize = piece.ringSize, rings = ringSize > 0 ? std::min<int>(piece.rings, n / ringSize) : 0;
    int done = 0;
    for (int r = 0; r < rings; ++r, done += ringSize) {
        if (r == 0) {
            sortRing(p, ringSize, s);
            continue;
        }
        sortRing(p + done, ringSize, ring);
        merge(s, done, ring, ringSize, spare);
        std::swap(s, spare);
    }
    std::copy(p + done, p + n, s + done);  // loose points (or everything, without rings)
    insertionSort(s, n);

    FixedPoint* h = hull_.data();
    int k = 0;
    for (int i = 0; i < n; ++i) {
        while (k >= 2 && orientation(h[k - 2], h[k - 1], s[i]) <= 0) --k;
        h[k++] = s[i];
    }
    for (int i = n - 2, t = k + 1; i >= 0; --i) {
        while (k >= t && orientation(h[k - 2], h[k - 1], s[i]) <= 0) --k;
        h[k++] = s[i];
    }
    return {h, std::size_t(k > 1 ? k - 1 : k)};
}

}  // namespace shapevo

// Pieces: split and repeat layouts, comp faces and lots (see geometry/pieces.hpp).
#include "geometry/pieces.hpp"

#include <algorithm>
#include <cmath>

#include "grammar/expression.hpp"

namespace shapevo {

namespace {

/// Whole repeats of `size` in `length`, forgiving the rounding of a length that is a multiple.
float wholeRepeats(float length, float size) {
    const float n = std::floor(length / size * (1.0f + 1e-5f));
    return std::isfinite(n) ? std::clamp(n, 0.0f, float(kMaxPieces)) : 0.0f;
}

/// A piece along `axis` from t (measured from the scope's low end) of length len.
void emitAlong(const Scope& s, int axis, float t, float len, std::uint32_t piece, std::vector<PieceScope>& out) {
    if (!(len > 0.0f) || out.size() >= kMaxPieces) return;  // no zero-size (or NaN) pieces
    PieceScope p{s, piece};
    p.scope.origin = s.origin + s.axes[axis] * (t + len * 0.5f - s.size[axis] * 0.5f);
    p.scope.size[axis] = len;
    out.push_back(p);
}

void split(const Grammar& g, const PieceList& list, const Scope& s, const float* lengths, std::vector<PieceScope>& out) {
    const int a = list.axis;
    const float L = s.size[a];
    if (!(L > 0.0f)) return;
    const Piece* pieces = &g.pieces[list.first];
    float fixed0 = 0, float0 = 0, groupFixed = 0, groupFloat = 0;
    std::uint32_t groupBegin = list.count, groupEnd = list.count;
    for (std::uint32_t k = 0; k < list.count; ++k) {
        const bool floating = pieces[k].size == PieceSize::Floating;
        const float v = std::max(lengths[k], 0.0f);
        if (pieces[k].repeated) {
            if (groupBegin == list.count) groupBegin = k;
            groupEnd = k + 1;
            (floating ? groupFloat : groupFixed) += v;
        } else {
            (floating ? float0 : fixed0) += v;
        }
    }
    float n = 0;
    if (groupBegin < groupEnd) {
        const float avail = L - fixed0 - float0;
        const float group = groupFixed + groupFloat;
        if (group > 0.0f && avail > 0.0f) n = wholeRepeats(avail, group);
        if (groupFloat > 0.0f && n < 1.0f && avail > 0.0f) n = 1.0f;
    }
    const float floats = float0 + n * groupFloat;
    const float rest = L - fixed0 - n * groupFixed;
    const float stretch = floats > 0.0f ? std::max(rest, 0.0f) / floats : 0.0f;
    float t = 0;
    auto place = [&](std::uint32_t k) {
        float len = std::max(lengths[k], 0.0f);
        if (pieces[k].size == PieceSize::Floating) len *= stretch;
        len = std::min(len, L - t);  // pieces beyond the scope are cut off
        emitAlong(s, a, t, len, k, out);
        if (len > 0.0f) t += len;
    };
    for (std::uint32_t k = 0; k < groupBegin && k < list.count; ++k) place(k);
    for (float r = 0; r < n; ++r)
        for (std::uint32_t k = groupBegin; k < groupEnd; ++k) place(k);
    for (std::uint32_t k = groupEnd; k < list.count; ++k) place(k);
}

/// The flat frame lots are made in: `s` itself when it is flat, else its ground plane.
Scope groundOf(const Scope& s) {
    if (s.size.z == 0.0f) return s;
    Scope f = s;
    f.axes = glm::mat3(s.axes[0], -s.axes[2], s.axes[1]);
    f.size = glm::vec3(s.size.x, s.size.z, 0.0f);
    return f;
}

/// A flat lot of `w` x `d` centred at (cx, cy) in flat frame f.
PieceScope lotAt(const Scope& f, float cx, float cy, float w, float d, std::uint32_t piece) {
    PieceScope p{f, piece};
    p.scope.origin = f.origin + f.axes[0] * cx + f.axes[1] * cy;
    p.scope.size = glm::vec3(w, d, 0.0f);
    return p;
}

void face(const Scope& s, FaceName which, std::uint32_t piece, std::vector<PieceScope>& out) {
    const glm::vec3 X = s.axes[0], Y = s.axes[1], Z = s.axes[2], h = s.size * 0.5f;
    PieceScope p{s, piece};
    Scope& f = p.scope;
    switch (which) {
    case FaceName::Top: f.origin += Y * h.y; f.axes = glm::mat3(X, -Z, Y); f.size = {s.size.x, s.size.z, 0}; break;
    case FaceName::Bottom: f.origin -= Y * h.y; f.axes = glm::mat3(X, Z, -Y); f.size = {s.size.x, s.size.z, 0}; break;
    case FaceName::Front: f.origin += Z * h.z; f.axes = glm::mat3(X, Y, Z); f.size = {s.size.x, s.size.y, 0}; break;
    case FaceName::Back: f.origin -= Z * h.z; f.axes = glm::mat3(-X, Y, -Z); f.size = {s.size.x, s.size.y, 0}; break;
    case FaceName::Right: f.origin += X * h.x; f.axes = glm::mat3(-Z, Y, X); f.size = {s.size.z, s.size.y, 0}; break;
    case FaceName::Left: f.origin -= X * h.x; f.axes = glm::mat3(Z, Y, -X); f.size = {s.size.z, s.size.y, 0}; break;
    }
    out.push_back(p);
}

}  // namespace

Scope extrudeScope(const Scope& s, float height) {
    Scope e = s;
    e.axes = glm::mat3(s.axes[0], s.axes[2], -s.axes[1]);
    e.size = glm::vec3(s.size.x, height, s.size.y);
    e.origin = s.origin + s.axes[2] * (height * 0.5f);
    return e;
}

void makePieces(const Grammar& g, const PieceList& list, const Scope& s, const float* params,
                const glm::vec3& parentSize, float* evalStack, std::vector<PieceScope>& out) {
    out.clear();
    auto eval = [&](const ExprRef& e) { return evaluate(g, e, params, &s.size.x, &parentSize.x, evalStack); };
    switch (list.kind) {
    case PiecesKind::Split: {
        float lengths[kMaxSplitPieces];  // the parser allows no more
        const std::uint32_t n = std::min<std::uint32_t>(list.count, std::uint32_t(kMaxSplitPieces));
        for (std::uint32_t k = 0; k < n; ++k) {
            const Piece& p = g.pieces[list.first + k];
            const float v = eval(p.value);
            lengths[k] = p.size == PieceSize::Relative ? v * s.size[list.axis] : v;
        }
        split(g, list, s, lengths, out);
        return;
    }
    case PiecesKind::RepeatCount:
    case PiecesKind::RepeatSize: {
        const float L = s.size[list.axis];
        if (!(L > 0.0f)) return;
        const float v = eval(list.arg[0]);
        float n = 0, len = 0;
        if (list.kind == PiecesKind::RepeatCount) {
            n = std::isfinite(v) ? std::clamp(std::floor(v), 0.0f, float(kMaxPieces)) : 0.0f;
            len = L / n;
        } else if (v > 0.0f) {
            n = wholeRepeats(L, v);
            if (list.floating) n = std::max(n, 1.0f);
            len = list.floating ? L / n : v;
        }
        for (std::uint32_t k = 0; float(k) < n; ++k) emitAlong(s, list.axis, float(k) * len, len, k % list.count, out);
        return;
    }
    case PiecesKind::Copy:
        out.push_back({s, 0});
        return;
    case PiecesKind::CopyCount: {  // N times the scope itself, successors in turn (N as repeat count's)
        const float v = eval(list.arg[0]);
        const float n = std::isfinite(v) ? std::clamp(std::floor(v), 0.0f, float(kMaxPieces)) : 0.0f;
        for (std::uint32_t k = 0; float(k) < n; ++k) out.push_back({s, k % list.count});
        return;
    }
    case PiecesKind::Comp:
        for (std::uint32_t k = 0; k < list.count; ++k) face(s, FaceName(g.pieces[list.first + k].face), k, out);
        return;
    case PiecesKind::LotRect: {
        const float x1 = eval(list.arg[0]), y1 = eval(list.arg[1]), x2 = eval(list.arg[2]), y2 = eval(list.arg[3]);
        const PieceScope p = lotAt(groundOf(s), (x1 + x2) * 0.5f, (y1 + y2) * 0.5f, std::fabs(x2 - x1), std::fabs(y2 - y1), 0);
        if (p.scope.size.x > 0.0f && p.scope.size.y > 0.0f) out.push_back(p);
        return;
    }
    case PiecesKind::LotCircle: {
        const float r = eval(list.arg[2]);
        if (r > 0.0f) out.push_back(lotAt(groundOf(s), eval(list.arg[0]), eval(list.arg[1]), 2 * r, 2 * r, 0));
        return;
    }
    case PiecesKind::Center: {
        const float w = eval(list.arg[0]), d = eval(list.arg[1]);
        if (w > 0.0f && d > 0.0f) out.push_back(lotAt(groundOf(s), 0, 0, w, d, 0));
        return;
    }
    case PiecesKind::Corners: {
        const Scope f = groundOf(s);
        const float side = std::min(eval(list.arg[0]) * f.size.x, eval(list.arg[1]) * f.size.y);
        if (!(side > 0.0f)) return;
        // Centred on the corners, or (inside) with one corner on the parent's.
        const float inset = list.floating ? side * 0.5f : 0.0f;
        const float hx = f.size.x * 0.5f - inset, hy = f.size.y * 0.5f - inset;
        const float cx[4] = {-hx, hx, hx, -hx}, cy[4] = {-hy, -hy, hy, hy};  // anticlockwise from (-, -)
        std::uint32_t made = 0;
        for (int c = 0; c < 4; ++c) {
            const float on = eval(list.arg[2 + c]);
            if (!(on > 0.0f || on < 0.0f)) continue;
            out.push_back(lotAt(f, cx[c], cy[c], side, side, made++ % list.count));
        }
        return;
    }
    case PiecesKind::Edges: {
        // Edge e runs anticlockwise from corner e; its lots have x along it and y pointing inwards.
        const Scope f = groundOf(s);
        const float rx = eval(list.arg[0]), ry = eval(list.arg[1]);
        const float hx = f.size.x * 0.5f, hy = f.size.y * 0.5f;
        const glm::vec3 X = f.axes[0], Y = f.axes[1], Z = f.axes[2];
        const glm::mat3 frames[4] = {glm::mat3(X, Y, Z), glm::mat3(Y, -X, Z), glm::mat3(-X, -Y, Z), glm::mat3(-Y, X, Z)};
        for (int e = 0; e < 4; ++e) {
            const float v = eval(list.arg[2 + e]);
            const float n = std::isfinite(v) ? std::clamp(std::floor(v), 0.0f, float(kMaxPieces)) : 0.0f;
            const float along = (e % 2 == 0 ? f.size.x : f.size.y), across = (e % 2 == 0 ? f.size.y : f.size.x);
            const float w = rx * along / std::max(n, 1.0f), d = ry * across;
            if (!(w > 0.0f && d > 0.0f)) continue;
            const std::uint32_t piece = std::uint32_t(e) % list.count;
            for (std::uint32_t k = 0; float(k) < n && out.size() < kMaxPieces; ++k) {
                const float t = (float(k) + 0.5f) / n * along - along * 0.5f;  // along the edge from its middle
                float cx = 0, cy = 0;
                switch (e) {
                case 0: cx = t, cy = -hy + d * 0.5f; break;
                case 1: cx = hx - d * 0.5f, cy = t; break;
                case 2: cx = -t, cy = hy - d * 0.5f; break;
                default: cx = -hx + d * 0.5f, cy = -t; break;
                }
                PieceScope p = lotAt(f, cx, cy, w, d, piece);
                p.scope.axes = frames[e];
                out.push_back(p);
            }
        }
        return;
    }
    }
}

}  // namespace shapevo

// derive: an explicit stack over (gene, statement, scope); `child` pushes the expressed children
// with the current scope, `mirror` pushes the rest of the rule again with one axis flipped.
#include "geometry/derive.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geometry/gather.hpp"
#include "geometry/texture_look.hpp"
#include "grammar/expression.hpp"
#include "mesh/mesh_material.hpp"
#include "shape/kinds.hpp"

namespace shapevo {

namespace {
glm::mat3 axisRotation(int axis, float degrees) {
    const float r = degrees * float(M_PI / 180.0), c = std::cos(r), s = std::sin(r);
    switch (axis) {
    case 0: return glm::mat3(1, 0, 0, 0, c, s, 0, -s, c);
    case 1: return glm::mat3(c, 0, -s, 0, 1, 0, s, 0, c);
    default: return glm::mat3(c, s, 0, -s, c, 0, 0, 0, 1);
    }
}
#if defined(__SSE2__)
// glm's mat3 * mat3 and mat3 * vec3 column by column in SSE lanes: every lane does the very same
// float operations in the same order as glm (column j = (a0 * b[j].x + a1 * b[j].y) + a2 * b[j].z),
// so the bits are the same, with a third of the instructions.
static_assert(sizeof(glm::mat3) == 9 * sizeof(float), "glm::mat3 must be 9 packed floats");
/// The three columns of `a` in lanes 0..2 (lane 3 is junk that no result uses).
struct Columns {
    __m128 c0, c1, c2;
    explicit Columns(const glm::mat3& a) {
        const float* f = &a[0][0];  // glm stores the 9 floats contiguously, column by column
        c0 = _mm_loadu_ps(f);
        c1 = _mm_loadu_ps(f + 3);
        const __m128 tail = _mm_loadu_ps(f + 5);  // a12 a20 a21 a22: stays inside the matrix
        c2 = _mm_shuffle_ps(tail, tail, _MM_SHUFFLE(0, 3, 2, 1));
    }
    __m128 times(const glm::vec3& b) const {
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(c0, _mm_set1_ps(b.x)), _mm_mul_ps(c1, _mm_set1_ps(b.y))),
                          _mm_mul_ps(c2, _mm_set1_ps(b.z)));
    }
};
glm::mat3 multiply(const glm::mat3& a, const glm::mat3& b) {
    const Columns ca(a);
    float f[12];
    _mm_storeu_ps(f, ca.times(b[0]));
    _mm_storeu_ps(f + 3, ca.times(b[1]));
    _mm_storeu_ps(f + 6, ca.times(b[2]));  // each store overwrites the junk lane of the one before
    glm::mat3 r;
    std::memcpy(&r[0][0], f, 9 * sizeof(float));
    return r;
}
glm::vec3 multiply(const glm::mat3& a, const glm::vec3& v) {
    float f[4];
    _mm_storeu_ps(f, Columns(a).times(v));
    return {f[0], f[1], f[2]};
}
/// glm::abs(v) * 0.5f lane by lane: glm's abs is `x >= 0 ? x : -x` (so -0 stays -0 and NaN flips sign).
glm::vec3 halfAbs(const glm::vec3& v) {
    const __m128 x = _mm_setr_ps(v.x, v.y, v.z, 0.0f);
    const __m128 keep = _mm_cmpge_ps(x, _mm_setzero_ps());
    const __m128 negated = _mm_xor_ps(x, _mm_set1_ps(-0.0f));
    const __m128 a = _mm_or_ps(_mm_and_ps(keep, x), _mm_andnot_ps(keep, negated));
    float f[4];
    _mm_storeu_ps(f, _mm_mul_ps(a, _mm_set1_ps(0.5f)));
    return {f[0], f[1], f[2]};
}
#else
glm::mat3 multiply(const glm::mat3& a, const glm::mat3& b) { return a * b; }
glm::vec3 multiply(const glm::mat3& a, const glm::vec3& v) { return a * v; }
glm::vec3 halfAbs(const glm::vec3& v) { return glm::abs(v) * 0.5f; }
#endif

}  // namespace

namespace {
/// Centre and half extents finite and within kMaxCoordinate (NaN fails every comparison). The
/// axes need no test: they are products of rotations by finite angles (Rotate refuses others)
/// and sign flips, so every entry stays within [-1, 1] up to rounding.
bool bounded(const Primitive& p) {
    // Six independent comparisons, combined without branches (NaN fails every comparison).
    const bool centre = (std::fabs(p.centre.x) <= kMaxCoordinate) & (std::fabs(p.centre.y) <= kMaxCoordinate) &
                        (std::fabs(p.centre.z) <= kMaxCoordinate);
    const bool half = (std::fabs(p.half.x) <= kMaxCoordinate) & (std::fabs(p.half.y) <= kMaxCoordinate) &
                      (std::fabs(p.half.z) <= kMaxCoordinate);
    return centre & half;
}
}  // namespace

namespace {
// The building statements, out of line: derive's loop stays small enough for the compiler to
// keep the common statements (and their expressions) inlined and in registers.

/// The appearance a Color / Material statement makes of `current`; returns its index in `looks`.
[[gnu::noinline]] std::uint32_t newLook(const Grammar& g, const Statement& st, std::vector<Appearance>& looks,
                                         std::uint32_t current, const float* params, const glm::vec3& size,
                                         const glm::vec3& parentSize, float* evalStack) {
    Appearance look = looks[current];
    look.texture = 0;  // a colour or a material ends a texture
    if (st.kind == StatementKind::Color) {
        for (int k = 0; k < 3; ++k) {
            look.color[k] = clampUnit(evaluate(g, st.expr[k], params, &size.x, &parentSize.x, evalStack));  // NaN -> 0
        }
    } else {
        look.material = st.slot;
    }
    looks.push_back(look);
    return std::uint32_t(looks.size() - 1);
}

/// The marks of the pieces just made (scratch.pieceMarks), for grammars that mark pieces: with
/// `per piece` parameters the k-th piece of a kind (counted from the first) gets its key; with
/// piece.index / piece.count each piece its place among them (nil ones too), except in `[ ]`.
[[gnu::noinline]] void markPieces(const Grammar& g, const PieceList& list, const PieceMark& mark, DeriveScratch& scratch) {
    const std::size_t n = scratch.pieces.size();
    scratch.pieceMarks.assign(n, mark);
    std::vector<std::uint32_t>& seen = scratch.repetitions;
    if (g.usesPieceKeys) {
        seen.assign(list.count, 0);
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint16_t kind = g.pieces[list.first + scratch.pieces[k].piece].first;
            scratch.pieceMarks[k].key = pieceKey(mark.key, kind, seen[kind]++);
        }
    }
    if (g.usesPiecePlaces && list.kind != PiecesKind::Copy)
        for (std::size_t k = 0; k < n; ++k) scratch.pieceMarks[k].place = piecePlace(std::uint32_t(k), std::uint32_t(n));
}

/// The pieces of a Pieces statement, each a task running its successor on its own scope.
[[gnu::noinline]] void pushPieces(const Grammar& g, const Statement& st, std::uint32_t gene, const Scope& s,
                                  const float* params, const glm::vec3& parentSize, float* evalStack,
                                  std::uint32_t frame, PieceMark mark, DeriveScratch& scratch) {
    makePieces(g, g.pieceLists[st.slot], s, params, parentSize, evalStack, scratch.pieces);
    const PieceList& list = g.pieceLists[st.slot];
    if (g.marksPieces) [[unlikely]]
        markPieces(g, list, mark, scratch);
    // Last piece first, scope and task alike: the first piece runs first, and every task below
    // the one popped refers to scopes below its own (see derive's resize of `scopes`).
    for (std::size_t k = scratch.pieces.size(); k-- > 0;) {
        const Piece& piece = g.pieces[list.first + scratch.pieces[k].piece];
        if (piece.begin == piece.end) continue;  // nil
        scratch.scopes.push_back(scratch.pieces[k].scope);
        const auto at = std::uint32_t(scratch.scopes.size() - 1);
        scratch.stack.push_back({gene, piece.begin, piece.end, at, at, frame, g.marksPieces ? scratch.pieceMarks[k] : mark});
    }
}
/// With the memo: keep every open subtree whose last task is done (the stack is back to the
/// size it had once the subtree's first task was popped).
[[gnu::noinline]] void keepFinishedSubtrees(const Grammar& g, const Geometry& out,
                                            DeriveScratch& scratch, std::size_t stackSize, std::size_t tasks) {
    while (!scratch.open.empty() && stackSize <= scratch.open.back().height) {
        const DeriveScratch::OpenSubtree& o = scratch.open.back();
        const Appearance* looks = g.hasAppearance ? out.appearance.data() + o.first : nullptr;
        scratch.memo->store(o.start, out.primitives.data() + o.first, looks,
                            std::uint32_t(out.primitives.size() - o.first), std::uint32_t(tasks - o.tasks));
        scratch.open.pop_back();
    }
}

/// With the memo, at the first task of a gene's subtree (already counted in `tasks`): append
/// what the memo kept for it and return true, if it kept it and it fits in what is left of the
/// limits (so the full derivation would not have stopped inside it either); otherwise open the
/// subtree, to be kept once derived, and return false.
[[gnu::noinline]] bool reuseSubtree(const Grammar& g, const DeriveScratch::Task& task, Geometry& out,
                                    DeriveScratch& scratch, SubtreeMemo& memo, std::size_t& tasks, std::size_t maxTasks,
                                    std::size_t maxPrimitives) {
    const Scope& s = scratch.scopes[task.scope];
    const SubtreeMemo::Start start(memo.contentOf(task.gene), g.usesPieceKeys ? task.mark.key : 0,
                                   g.usesPiecePlaces ? &task.mark.place : nullptr,
                                   g.hasAppearance ? &scratch.looks[s.look] : nullptr, s,
                                   scratch.carried.data() + task.mark.carried, std::uint32_t(g.carriedNames.size()));
    SubtreeMemo::Found found;
    const std::size_t first = out.primitives.size();
    if (memo.find(start, found) && first + found.count <= maxPrimitives &&
        tasks - 1 + found.tasks <= maxTasks) {
        out.primitives.resize(first + found.count);
        if (found.count > 0)  // (data() may be null when there are none)
            std::memcpy(static_cast<void*>(out.primitives.data() + first), found.primitives,
                        std::size_t(found.count) * sizeof(Primitive));
        if (g.hasAppearance && found.count > 0) {
            out.appearance.resize(first + found.count);
            std::memcpy(static_cast<void*>(out.appearance.data() + first), found.looks,
                        std::size_t(found.count) * sizeof(Appearance));
        }
        tasks += found.tasks - 1;
        scratch.reused.push_back({std::uint32_t(first), found.count, start});
        return true;
    }
    scratch.open.push_back({scratch.stack.size(), first, tasks - 1, start});
    return false;
}
}  // namespace

namespace {
/// Derive's state before its first task: `out` cleared, one task for `gene` on `start` (its
/// scope and look), the stacks empty below it.
void begin(const Grammar& g, Geometry& out, DeriveScratch& scratch, std::uint32_t gene, const SubtreeStart& start,
           const float* carried) {
    out.clear();
    scratch.reused.clear();
    scratch.open.clear();
    out.meshes = &g.meshes;
    out.materialNames = &g.materialNames;
    out.textures = &g.textures;
    scratch.stack.clear();
    scratch.scopes.clear();
    scratch.frames.clear();
    scratch.collections.clear();
    scratch.carried.assign(carried, carried + g.carriedNames.size());
    Scope s = start.scope;
    if (g.hasAppearance) {
        scratch.looks.clear();
        scratch.looks.push_back(start.look);
        s.look = 0;
    }
    // Live scopes are about as many as pending tasks: sized with the stack, they stop growing when it does.
    if (scratch.scopes.capacity() < scratch.stack.capacity()) scratch.scopes.reserve(scratch.stack.capacity());
    scratch.params.resize(kParamBlockFloats);
    scratch.scopes.push_back(s);
    scratch.stack.push_back({gene, 0, UINT32_MAX, 0, 0, DeriveScratch::kNoFrame, {start.key, start.place, 0}});
}

/// Whether `task` is the first task of its gene's subtree, on its parent's scope (what the memo
/// keeps and what a subtree start names).
bool startsSubtree(const DeriveScratch::Task& task) {
    return task.statement == 0 && task.end == UINT32_MAX && task.frame == DeriveScratch::kNoFrame &&
           task.scope == task.parent;
}

/// What derive's loop does beside deriving: Focus::Path skips every task that is neither the
/// focus gene's first nor an ancestor's, records the focus gene's starts instead of deriving it,
/// and makes no primitive.
enum class Focus { None, Path };

// Derive's loop in parts: run() pops the tasks, runTask() runs one task's statements, and the
// longer statements have their own functions. The parts are [[gnu::always_inline]] so that the
// compiled loop is one function, as fast as when it was written as one (callgrind, 2026-12:
// 0.7-1.1 % fewer instructions); the cold paths (non-finite numbers, storing let values) stay
// out of line. This translation unit (a unity build) is at GCC's inline-unit-growth limit, so
// inlining more into the loop can push std::vector::push_back or extrudeScope out of it:
// measure with callgrind (bench_derive, bench_incremental) after changing these parts.

/// What a derivation's tasks all read: the model, the output and the limits, and with
/// Focus::Path the focus gene and its ancestors. Passed to the loop's parts, which are all
/// inlined into it (so this never lives in memory).
struct Derivation {
    const Grammar& g;
    const Chromosome& c;
    Geometry& out;
    DeriveScratch& scratch;
    std::size_t maxPrimitives;
    std::uint32_t focus;
    std::span<const std::uint32_t> ancestors;
};

/// Whether `gene` is one of the path's ancestors (Focus::Path).
[[gnu::always_inline]] inline bool onPath(const Derivation& d, std::uint32_t gene) {
    return std::find(d.ancestors.begin(), d.ancestors.end(), gene) != d.ancestors.end();
}

/// Stop with NonFinite: `rule` made a non-finite angle or primitive.
[[gnu::cold, gnu::noinline]] DeriveStatus nonFinite(DeriveScratch& scratch, std::uint16_t rule) {
    scratch.badRule = rule;
    return DeriveStatus::NonFinite;
}
/// Stop with NonFinite on the primitive just appended to `out`, which goes.
[[gnu::cold, gnu::noinline]] DeriveStatus rejectPrimitive(Geometry& out, DeriveScratch& scratch, std::uint16_t rule) {
    out.primitives.pop_back();
    return nonFinite(scratch, rule);
}

/// `params` for `task`: its gene's parameters, the let values it goes on with (a mirror's or a
/// piece's continuation) and its piece mark.
[[gnu::always_inline]] inline void loadParams(const Derivation& d, const Rule& r, const DeriveScratch::Task& task,
                                              float* params) {
    loadGeneAndFrame(r, d.c, task.gene, d.scratch.frames, task.frame, params);
    if (d.g.marksPieces) [[unlikely]]
        loadPieceMark(d.g, task.mark, params);
    if (!d.g.carriedNames.empty()) [[unlikely]]
        loadCarried(d.g, d.scratch.carried, task.mark.carried, params);
}

/// The let values a task has now, for tasks it pushes that go on in this gene.
[[gnu::always_inline]] inline std::uint32_t snapshot(const Rule& r, std::vector<float>& frames, const float* params) {
    if (r.frameFloats == 0) return DeriveScratch::kNoFrame;
    return storeFrame(frames, params + kFrameBase, r.frameFloats);
}

/// The three expressions of a Scale / Size / Translate statement.
template <class Eval>
[[gnu::always_inline]] inline glm::vec3 vector3(const Eval& eval, const Statement& st) {
    return glm::vec3(eval(st.expr[0]), eval(st.expr[1]), eval(st.expr[2]));
}

/// A Mirror statement at statement `i`: the rest of the rule again, on `s` with one axis flipped.
[[gnu::always_inline]] inline void pushMirror(const Derivation& d, const Rule& r, const Statement& st,
                                              const DeriveScratch::Task& task, std::uint32_t i, const Scope& s,
                                              const float* params) {
    Scope mirrored = s;
    mirrored.axes[st.axis] = -mirrored.axes[st.axis];
    std::vector<Scope>& scopes = d.scratch.scopes;
    scopes.push_back(mirrored);
    // the parent scope stays where it is: at or below task.scope
    const std::uint32_t frame = snapshot(r, d.scratch.frames, params);
    d.scratch.stack.push_back({task.gene, i + 1, task.end, std::uint32_t(scopes.size() - 1), task.parent, frame, task.mark});
}

/// A Set statement at statement `i`: a new block of carried values (the task's, with attribute
/// `st.slot` = `value`), and the rest of the task as a task of its own that carries it, on `s`
/// with the let values it has now (it runs next, before anything the task pushed).
[[gnu::noinline]] void setCarried(const Derivation& d, const Rule& r, const Statement& st, const DeriveScratch::Task& task,
                                  std::uint32_t i, const Scope& s, const float* params, float value) {
    std::vector<float>& carried = d.scratch.carried;
    const std::size_t n = d.g.carriedNames.size(), at = carried.size();
    carried.resize(at + n);
    std::copy_n(carried.begin() + task.mark.carried, n, carried.begin() + std::ptrdiff_t(at));
    carried[at + st.slot] = value;
    PieceMark mark = task.mark;
    mark.carried = std::uint32_t(at);
    d.scratch.scopes.push_back(s);
    const std::uint32_t frame = snapshot(r, d.scratch.frames, params);
    d.scratch.stack.push_back({task.gene, i + 1, task.end, std::uint32_t(d.scratch.scopes.size() - 1), task.parent, frame, mark});
}

/// What a primitive kind's emit reads (K::emit, setParams): its expressions and its slot.
struct PrimitiveArguments {
    const Grammar& g;
    const Statement& st;
    const float *params, *size, *parentSize;
    float* evalStack;
    float expression(int i) const { return evaluate(g, st.expr[i], params, size, parentSize, evalStack); }
    std::uint16_t slot() const { return st.slot; }
};

/// A Primitive statement: the kind's primitive on `s`, in the look in force. Complete, or why
/// derivation stops here.
[[gnu::always_inline]] inline DeriveStatus emitPrimitive(const Derivation& d, const Statement& st,
                                                         const DeriveScratch::Task& task, const Scope& s,
                                                         const float* params, const glm::vec3& parentSize,
                                                         float* evalStack) {
    Geometry& out = d.out;
    // A cap, so that mirrors inside recursion (2^depth copies) cannot run away.
    if (out.primitives.size() >= d.maxPrimitives) return DeriveStatus::Truncated;
    Primitive& p = out.primitives.emplace_back();
    p.kind = st.primitive;
    p.params = {};
    p.centre = s.origin;
    p.axes = s.axes;
    p.half = halfAbs(s.size);
    // The kind's own parameters (a cone's taper, a roof's fractions, a mesh's index).
    const PrimitiveArguments args{d.g, st, params, &s.size.x, &parentSize.x, evalStack};
    visitKind(st.primitive, [&](auto kind) { decltype(kind)::type::emit(p, args); });
    if (!bounded(p)) [[unlikely]]
        return rejectPrimitive(out, d.scratch, d.c.rule(task.gene));
    if (d.g.hasAppearance) out.appearance.push_back(d.scratch.looks[s.look]);
    return DeriveStatus::Complete;
}

/// A Child statement: a task for each expressed child of the slot, last first, on `s` (stored
/// once for consecutive child statements: `stored`, UINT32_MAX when `s` is not stored yet).
template <Focus F>
[[gnu::always_inline]] inline void pushChildren(const Derivation& d, const Rule& r, const Statement& st,
                                                const DeriveScratch::Task& task, const std::int32_t* childOffsets,
                                                const Scope& s, std::uint32_t& stored) {
    std::vector<Scope>& scopes = d.scratch.scopes;
    const Slot& slot = r.slots[st.slot];
    for (std::uint32_t k = slot.maxCount; k-- > 0;) {
        const std::int32_t off = childOffsets[slot.firstChild + k];
        if constexpr (F == Focus::Path) {  // only the path's genes are run: the others are not pushed
            const std::uint32_t child = task.gene + std::uint32_t(off);
            if (off > 0 && child != d.focus && !onPath(d, child)) continue;
        }
        if (off > 0) {
            if (stored == UINT32_MAX) {
                scopes.push_back(s);
                stored = std::uint32_t(scopes.size() - 1);
            }
            d.scratch.stack.push_back({task.gene + std::uint32_t(off), 0, UINT32_MAX, stored, stored,
                                       DeriveScratch::kNoFrame, task.mark});
        }
    }
}

/// Run one task's statements (from task.statement to task.end, on its scope): Complete, or why
/// derivation stops here.
template <Focus F>
[[gnu::always_inline]] inline DeriveStatus runTask(const Derivation& d, const DeriveScratch::Task& task, float* params,
                                                   float* evalStack) {
    const Grammar& g = d.g;
    const Chromosome& c = d.c;
    DeriveScratch& scratch = d.scratch;
    const Rule& r = g.rules[c.rule(task.gene)];
    loadParams(d, r, task, params);
    Scope s = scratch.scopes[task.scope], beforeTerminal;
    const glm::vec3 parentSize = scratch.scopes[task.parent].size;
    // Index of the stored scope equal to `s`, if the last one stored still is (children of
    // consecutive child statements share it); UINT32_MAX when `s` changed since.
    std::uint32_t stored = UINT32_MAX;
    auto eval = [&](const ExprRef& e) __attribute__((always_inline)) { return evaluate(g, e, params, &s.size.x, &parentSize.x, evalStack); };
    // Local copies of pointers the pushes below might otherwise make the compiler reload.
    const Statement* const statementList = r.statements.data();
    const std::uint32_t statements = std::min(task.end, std::uint32_t(r.statements.size()));
    const std::int32_t* const childOffsets = reinterpret_cast<const std::int32_t*>(c.words.data() + task.gene + 2);
    for (std::uint32_t i = task.statement; i < statements; ++i) {
        const Statement& st = statementList[i];
        switch (st.kind) {
        case StatementKind::Scale:
            s.size *= vector3(eval, st);
            stored = UINT32_MAX;
            break;
        case StatementKind::Size:
            s.size = vector3(eval, st);
            stored = UINT32_MAX;
            break;
        case StatementKind::Translate:
            s.origin += multiply(s.axes, vector3(eval, st));
            stored = UINT32_MAX;
            break;
        case StatementKind::Rotate: {
            const float degrees = eval(st.expr[0]);
            if (!std::isfinite(degrees)) [[unlikely]]
                return nonFinite(scratch, c.rule(task.gene));
            s.axes = multiply(s.axes, axisRotation(st.axis, degrees));
            stored = UINT32_MAX;
            break;
        }
        case StatementKind::Mirror:
            pushMirror(d, r, st, task, i, s, params);
            stored = UINT32_MAX;  // children pushed later need a scope above the mirrored one
            break;
        case StatementKind::Primitive:
            if constexpr (F == Focus::Path) break;  // the path's own primitives are not asked for
            if (const DeriveStatus why = emitPrimitive(d, st, task, s, params, parentSize, evalStack);
                why != DeriveStatus::Complete) [[unlikely]]
                return why;
            break;
        case StatementKind::TerminalBegin:
            if (c.hasChildren(task.gene, r)) {
                i = st.end;  // the loop's ++i steps past the TerminalEnd
            } else {
                beforeTerminal = s;
            }
            break;
        case StatementKind::TerminalEnd:
            s = beforeTerminal;
            stored = UINT32_MAX;
            break;
        case StatementKind::Child:
            pushChildren<F>(d, r, st, task, childOffsets, s, stored);
            break;
        case StatementKind::If: {
            const float condition = eval(st.expr[0]);
            if (!(condition > 0.0f || condition < 0.0f)) i = st.end - 1;  // 0 and NaN are false
            break;
        }
        case StatementKind::Jump:
            i = st.end - 1;
            break;
        case StatementKind::Let:
            for (int k = 0; k < st.axis; ++k) params[st.slot + k] = eval(st.expr[k]);
            break;
        case StatementKind::Extrude:
            s = extrudeScope(s, eval(st.expr[0]));
            stored = UINT32_MAX;
            break;
        case StatementKind::Color:
        case StatementKind::Material:
            s.look = newLook(g, st, scratch.looks, s.look, params, s.size, parentSize, evalStack);
            stored = UINT32_MAX;
            break;
        case StatementKind::Texture:
            s.look = textureLook(g, st, scratch.looks, s, params, parentSize, evalStack, d.out.textureFrames);
            stored = UINT32_MAX;
            break;
        case StatementKind::ScopeFrame:
            writeScopeFrame(s, params);
            break;
        case StatementKind::Open:
            openCollections(g, st, task, s, snapshot(r, scratch.frames, params), scratch);
            break;
        case StatementKind::Send:
            if (!sendScope(scratch.collections, st, s, task.mark.carried)) [[unlikely]]
                return DeriveStatus::Truncated;
            break;
        case StatementKind::Gather:
            if (Collection* open = scratch.collections.ofGather(st.slot)) open->frame = snapshot(r, scratch.frames, params);
            i = st.end - 1;
            break;
        case StatementKind::Set:
            setCarried(d, r, st, task, i, s, params, eval(st.expr[0]));
            return DeriveStatus::Complete;  // the rest of the task goes on in the task setCarried pushed
        case StatementKind::Pieces:
            pushPieces(g, st, task.gene, s, params, parentSize, evalStack, snapshot(r, scratch.frames, params),
                       task.mark, scratch);
            stored = UINT32_MAX;
            i = st.end - 1;
            break;
        }
    }
    return DeriveStatus::Complete;
}

/// Run the tasks on the stack (begin()). `memo` may be null; Path takes none.
template <Focus F>
DeriveStatus run(const Grammar& g, const Chromosome& c, Geometry& out, DeriveScratch& scratch, std::size_t maxPrimitives,
                 SubtreeMemo* const memo, std::uint32_t focus, std::span<const std::uint32_t> ancestors,
                 std::vector<SubtreeStart>* starts) {
    const Derivation d{g, c, out, scratch, maxPrimitives, focus, ancestors};
    auto& stack = scratch.stack;
    auto& scopes = scratch.scopes;
    float* params = scratch.params.data();
    float evalStack[kMaxExpressionStack];
    std::size_t& tasks = scratch.tasks;
    tasks = 0;
    const std::size_t maxTasks = maxDeriveTasks(maxPrimitives);
    for (;;) {
        if (memo) [[unlikely]]
            keepFinishedSubtrees(g, out, scratch, stack.size(), tasks);
        if (stack.empty()) break;
        if (++tasks > maxTasks) return DeriveStatus::Truncated;
        const DeriveScratch::Task task = stack.back();
        stack.pop_back();
        // Every task still on the stack refers to scopes at or below this task's own one.
        scopes.resize(task.scope + 1);
        if constexpr (F == Focus::Path) {
            if (task.gene == focus && startsSubtree(task)) {
                const Scope& s = scopes[task.scope];
                starts->push_back({s, g.hasAppearance ? scratch.looks[s.look] : Appearance{}, task.mark.key, task.mark.place});
                std::copy_n(scratch.carried.begin() + task.mark.carried, g.carriedNames.size(), starts->back().carried);
                continue;
            }
            if (!onPath(d, task.gene)) continue;
        }
        // A gene's subtree, from its first statement on its parent's scope: derived before? (Not
        // the root's: the whole model recurs only as a duplicate, which search methods never
        // score twice, and keeping it would copy every primitive of every model.)
        if (g.hasLists && task.end == DeriveScratch::kGatherMarker) [[unlikely]] {
            runGatherMarker(g, c, task, params, evalStack, scratch);
            continue;
        }
        if (memo && task.gene != 0 && startsSubtree(task))
            if (reuseSubtree(g, task, out, scratch, *memo, tasks, maxTasks, maxPrimitives)) continue;
        if (const DeriveStatus why = runTask<F>(d, task, params, evalStack); why != DeriveStatus::Complete) [[unlikely]]
            return why;
    }
    return DeriveStatus::Complete;
}
}  // namespace

DeriveStatus derive(const Grammar& g, const Chromosome& c, Geometry& out, DeriveScratch& scratch, std::size_t maxPrimitives) {
    begin(g, out, scratch, 0, SubtreeStart{}, g.carriedDefaults.data());
    if (c.empty()) {
        scratch.tasks = 0;
        return DeriveStatus::Complete;
    }
    SubtreeMemo* const memo = g.textures.empty() && scratch.memo && scratch.memo->on() ? scratch.memo.get() : nullptr;
    if (memo) memo->identify(g, c);
    return run<Focus::None>(g, c, out, scratch, maxPrimitives, memo, 0, {}, nullptr);
}

DeriveStatus deriveSubtree(const Grammar& g, const Chromosome& c, std::uint32_t gene, const SubtreeStart& start,
                           Geometry& out, DeriveScratch& scratch, std::size_t maxPrimitives) {
    begin(g, out, scratch, gene, start, start.carried);
    return run<Focus::None>(g, c, out, scratch, maxPrimitives, nullptr, 0, {}, nullptr);
}

DeriveStatus findSubtreeStarts(const Grammar& g, const Chromosome& c, std::uint32_t gene, DeriveScratch& scratch,
                               std::vector<SubtreeStart>& starts, std::size_t maxPrimitives) {
    starts.clear();
    auto& path = scratch.path;
    path.clear();
    for (std::uint32_t at = gene; at != 0;) {
        at = std::uint32_t(std::int64_t(at) + c.parentOffset(at));
        path.push_back(at);
    }
    Geometry& none = scratch.pathGeometry;
    begin(g, none, scratch, 0, SubtreeStart{}, g.carriedDefaults.data());
    return run<Focus::Path>(g, c, none, scratch, maxPrimitives, nullptr, gene, path, &starts);
}

}  // namespace shapevo

// derive: run the grammar's statements along a chromosome's derivation tree and collect the
// primitives. Pure and deterministic: the same chromosome always gives the same geometry.
#pragma once
#include <cstring>
#include <memory>
#include <vector>

#include "genome/chromosome.hpp"
#include "geometry/collections.hpp"
#include "geometry/pieces.hpp"
#include "geometry/subtree_memo.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// piece.index and piece.count packed in one word: index | count << 16 (both at most kMaxPieces).
inline constexpr std::uint32_t piecePlace(std::uint32_t index, std::uint32_t count) { return index | count << 16; }
/// The place outside any piece: piece.index 0, piece.count 1.
inline constexpr std::uint32_t kNoPiecePlace = piecePlace(0, 1);

/// Which piece a task runs in: its piece key (grammar/expression.hpp, pieceKey: which piece of
/// its kind, for `per piece`) and its place (piecePlace: piece.index, piece.count). Children
/// inherit their parent's; only grammars with Grammar::marksPieces give pieces their own.
struct PieceMark {
    std::uint32_t key = 0;
    std::uint32_t place = kNoPiecePlace;
    std::uint32_t carried = 0;  ///< its carried attributes' values: DeriveScratch::carried[carried, + count)
};

/// `mark`'s piece key (its bits) and, with piece.index / piece.count, its place into the
/// parameter block, where OpCode::Fresh and piece.index / piece.count read them.
[[gnu::always_inline]] inline void loadPieceMark(const Grammar& g, const PieceMark& mark, float* params) {
    std::memcpy(params + kPieceKeySlot, &mark.key, sizeof mark.key);
    if (g.usesPiecePlaces) {
        params[kPieceIndexSlot] = float(mark.place & 0xFFFFu);
        params[kPieceCountSlot] = float(mark.place >> 16);
    }
}

/// The carried attribute values at `block` of `carried` into the parameter block, where the
/// attributes' names read them (only grammars that declare some).
[[gnu::always_inline]] inline void loadCarried(const Grammar& g, const std::vector<float>& carried, std::uint32_t block,
                                               float* params) {
    std::memcpy(params + kCarriedSlot, carried.data() + block, g.carriedNames.size() * sizeof(float));
}

/// The gene's stored parameters (`gene`: its word in `c`, of rule `r`) and, unless `frame` is
/// kNoFrame (UINT32_MAX), the let values stored at `frames[frame]` into the parameter block.
[[gnu::always_inline]] inline void loadGeneAndFrame(const Rule& r, const Chromosome& c, std::uint32_t gene,
                                                    const std::vector<float>& frames, std::uint32_t frame, float* params) {
    if (r.paramFloats > 0)
        std::memcpy(params, &c.words[Chromosome::paramWord(gene, r)], r.paramFloats * sizeof(float));
    if (frame != UINT32_MAX) [[unlikely]]
        std::memcpy(params + kFrameBase, frames.data() + frame, r.frameFloats * sizeof(float));
}

/// A scope's world origin and axes into the parameter block, where scope.origin and scope.axis
/// read them. Out of line: only grammars that read them get here.
[[gnu::noinline]] inline void writeScopeFrame(const Scope& s, float* params) {
    std::memcpy(params + kScopeOriginSlot, &s.origin[0], 3 * sizeof(float));
    std::memcpy(params + kScopeAxisSlot, &s.axes[0][0], 9 * sizeof(float));  // column a: axis a
}

/// Appends `count` let values to `frames`; returns where they start. Out of line: only rules
/// with lets get here, and the insert inlined would crowd derive's loop.
[[gnu::noinline]] inline std::uint32_t storeFrame(std::vector<float>& frames, const float* values, std::uint32_t count) {
    const auto at = std::uint32_t(frames.size());
    frames.insert(frames.end(), values, values + count);
    return at;
}

/// Where a gene's subtree starts being derived: its parent's scope, the look in force there, the
/// piece key and place (what a SubtreeMemo::Start holds besides the content). What derive makes
/// of the subtree depends on nothing else (subtree_memo.hpp).
struct SubtreeStart {
    Scope scope;  ///< `look` unused: the look is `look`
    Appearance look;
    std::uint32_t key = 0;
    std::uint32_t place = kNoPiecePlace;  ///< piecePlace(piece.index, piece.count)
    float carried[kMaxCarried] = {};      ///< the carried attributes' values (Grammar::carriedNames)
};

/// Reusable work space for derive (no allocation once warm).
struct DeriveScratch {
    struct Task {
        std::uint32_t gene;
        std::uint32_t statement;  ///< first statement to run
        std::uint32_t end;        ///< one past the last (a piece's successor ends early)
        std::uint32_t scope;      ///< index in `scopes`: current scope when the task starts
        std::uint32_t parent;     ///< index in `scopes`: scope the gene received from its parent
        std::uint32_t frame;      ///< its let values in `frames` (kNoFrame: none)
        PieceMark mark;           ///< which piece it runs in (piece key, piece.index and piece.count)
    };
    static constexpr std::uint32_t kNoFrame = UINT32_MAX;
    /// Task::end of a gather's marker (Task::statement: the gather's index in Grammar::gathers):
    /// pushed below every task of its invocation, it pops when they are all done.
    static constexpr std::uint32_t kGatherMarker = UINT32_MAX - 1;
    std::vector<Task> stack;
    /// Scopes the pending tasks start from, stored once per pushed batch of children (a stack:
    /// entries above the popped task's own scope are no longer referenced).
    std::vector<Scope> scopes;
    std::vector<float> params;
    /// Let values of tasks that continue a gene (mirrors, pieces), appended and never popped
    /// during one derivation (only rules with lets or inline arguments write any).
    std::vector<float> frames;
    /// Carried attribute values, one block of Grammar::carriedNames.size() per value set, appended
    /// by `set` and never popped during one derivation (only grammars that declare some).
    std::vector<float> carried;
    std::vector<PieceScope> pieces;    ///< work space of split / comp / lot statements
    std::vector<std::uint32_t> repetitions;  ///< per kind of piece of a list: how many came before (`per piece`)
    std::vector<PieceMark> pieceMarks;       ///< the marks of the pieces being pushed (Grammar::marksPieces)
    std::vector<Appearance> looks;     ///< appearances of this derivation (Scope::look)
    Collections collections;           ///< open lists (send / gather; only grammars with Grammar::hasLists)
    std::uint32_t badRule = 0;  ///< after DeriveStatus::NonFinite: the rule whose primitive it was
    /// Set: incremental derivation. Every gene's subtree is looked up before it is derived and
    /// kept after (geometry/subtree_memo.hpp); the geometry is the same bit for bit. Not with
    /// textures (their frames are numbered per derivation).
    std::unique_ptr<SubtreeMemo> memo;
    /// Subtrees being derived while the memo is on, to be kept when their last task is done.
    struct OpenSubtree {
        std::size_t height;      ///< the stack's size once its first task was popped: done when back to it
        std::size_t first;       ///< its first primitive
        std::size_t tasks;       ///< derive's task count before its first task
        SubtreeMemo::Start start;
    };
    std::vector<OpenSubtree> open;
    /// After a derivation with the memo: the subtrees it copied from the memo, in the order of
    /// their primitives (disjoint ranges of Geometry::primitives); their starts name them exactly.
    struct ReusedSubtree {
        std::uint32_t first, count;
        SubtreeMemo::Start start;
    };
    std::vector<ReusedSubtree> reused;
    /// After a derivation: the tasks it ran (the memo's reused subtrees counting theirs), which
    /// the limit of 4 * maxPrimitives + 1024 tasks is checked against.
    std::size_t tasks = 0;
    std::vector<std::uint32_t> path;  ///< findSubtreeStarts: the gene's ancestors
    Geometry pathGeometry;            ///< findSubtreeStarts: stays empty
};

/// Every number of a primitive (centre, half extents; its axes follow from finite rotation
/// angles) must be finite and at most this in absolute value: a model beyond a million units is
/// a runaway expression (a division by zero, `scale 1e30`), never a model.
inline constexpr float kMaxCoordinate = 1e6f;
/// The default of genome.max_primitives: derivation stops after this many primitives.
inline constexpr std::size_t kDefaultMaxPrimitives = GenomeLimits{}.maxPrimitives;

/// The most tasks a derivation with `maxPrimitives` runs before it stops (Truncated): mirrors
/// without primitives multiply too.
inline std::size_t maxDeriveTasks(std::size_t maxPrimitives) { return 4 * maxPrimitives + 1024; }

enum class DeriveStatus : unsigned char {
    Complete,   ///< the whole derivation
    Truncated,  ///< stopped at `maxPrimitives` primitives (or 4x as many scopes): `out` holds the first ones
    NonFinite,  ///< a primitive had a non-finite or absurd number (kMaxCoordinate), or a rotation a
                ///< non-finite angle; that primitive is not in `out`, derivation stopped there and
                ///< scratch.badRule names its rule
};

/// Derive `c` into `out` (cleared first). A mirror inside a recursion doubles the work at every
/// level, so derivation stops after `maxPrimitives` primitives (or 4x as many scopes) and says
/// Truncated; a primitive with a non-finite or absurd number stops it with NonFinite. Either way
/// `out` holds only finite, bounded primitives.
DeriveStatus derive(const Grammar& g, const Chromosome& c, Geometry& out, DeriveScratch& scratch,
                    std::size_t maxPrimitives = kDefaultMaxPrimitives);

/// Derive only the subtree of the gene at word `gene` of `c`, from `start`: exactly the
/// primitives (in order) and tasks (scratch.tasks) a derivation of `c` makes of that subtree at
/// that start. The memo is not used. The same limits apply to the subtree alone.
DeriveStatus deriveSubtree(const Grammar& g, const Chromosome& c, std::uint32_t gene, const SubtreeStart& start,
                           Geometry& out, DeriveScratch& scratch, std::size_t maxPrimitives = kDefaultMaxPrimitives);

/// Every start of the subtree of the gene at word `gene` (not the root) in a derivation of `c`,
/// in derivation order: one per time its parent's derivation reaches it (more than one under a
/// mirror or in repeated pieces). Runs only the statements of its ancestors and makes no
/// primitive, so it costs the path from the root, not the model. Its status is Complete unless
/// the ancestors' own tasks pass the task limit (a model whose full derivation is Complete
/// always gives Complete); what the full derivation's status is, it does not say.
DeriveStatus findSubtreeStarts(const Grammar& g, const Chromosome& c, std::uint32_t gene, DeriveScratch& scratch,
                               std::vector<SubtreeStart>& starts, std::size_t maxPrimitives = kDefaultMaxPrimitives);

}  // namespace shapevo

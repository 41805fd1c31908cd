// Grammar: the generator graph compiled from a .grammar file.
// Rules (nodes) carry parameters with priors, a linear list of shape statements, and child
// slots (edges). Expressions are compiled once into a flat instruction array; deriving a genome
// never re-reads text. See grammars/README.md for the language.
#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mesh/mesh_shape.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// One instruction of the tiny stack machine that evaluates compiled expressions.
enum class OpCode : std::uint8_t {
    Const, Param, ScopeSize, ParentSize,  // push: value / gene parameter float / scope or parent size component
    Add, Sub, Mul, Div, Neg,
    Min, Max, Abs, Sin, Cos, Sqrt, Floor,
    Lt, Le, Gt, Ge, Eq, Ne, And, Or, Not,  // comparisons and logic: 1 for true, 0 for false
    NormalCdf, NormalQuantile,             // the standard normal's CDF and its inverse (run-time normal priors)
    Atan2,                                 // atan2(y, x) in radians
    Fresh,  // u in [0, 1] -> u itself in the first piece of its kind, else a value in [0, 1) hashed from u and the piece key (`per piece`)
    Square,  // x * x (length, dot and distance of 3-vectors are compiled into Square, Mul, Add, Sub and Sqrt)
};
struct Instr {
    OpCode op;
    std::uint8_t component = 0;  ///< for ScopeSize / ParentSize
    std::uint16_t index = 0;     ///< for Param: float index inside the gene's parameter block
    float value = 0.0f;          ///< for Const
};
/// Where one leaf of a small expression (see ExprRef) reads its value.
enum class LeafSource : std::uint8_t { Const, Param, ScopeSize, ParentSize };
/// A compiled scalar expression: instructions [begin, end) of Grammar::code. The compiler also
/// recognises the common small shapes over leaves (numbers, parameter floats, size components):
/// `a`, `a op b`, `(a op b) op c` and `a op (b op c)`, and stores them here as well, so that
/// evaluate() can skip the stack machine; the result is the same to the last bit.
struct ExprRef {
    enum class Shape : std::uint8_t { Program, Leaf, Binary, LeftNested, RightNested };
    std::uint32_t begin = 0, end = 0;
    Shape shape = Shape::Program;                 ///< Program: only the instructions say what to do
    OpCode op[2] = {OpCode::Add, OpCode::Add};    ///< op[0] inner (or only) operation, op[1] outer
    LeafSource source[3] = {};                    ///< leaves a, b, c in source order
    std::uint16_t index[3] = {};                  ///< Param: float index; sizes: component; Const: leaf number
    float value[3] = {};                          ///< Const leaves' values (by leaf number)
};

enum class PriorKind : std::uint8_t { Uniform, Normal, Int, Choice };
/// The prior of one scalar component of a parameter.
struct Prior {
    PriorKind kind = PriorKind::Uniform;
    float lo = 0, hi = 0;              ///< support: uniform/normal/int bounds
    float mu = 0, sigma = 0;           ///< normal only
    std::uint32_t choiceBegin = 0;     ///< choice only: values in Grammar::choiceValues
    std::uint32_t choiceCount = 0;
};
struct Param {
    std::string name;
    std::uint16_t first = 0;   ///< index of its first float in the gene's parameter block
    std::uint8_t dims = 1;     ///< 1 (scalar) or 3 (vector)
    Prior prior[3];
};

/// A child slot: which rules may be derived there, how likely each sibling is expressed, how many.
struct Slot {
    std::vector<std::uint16_t> rules;   ///< allowed rules (stochastic alternatives)
    std::vector<float> weights;         ///< relative weight of each alternative
    float probability = 1.0f;           ///< chance that each sibling position is expressed
    std::uint16_t maxCount = 1;         ///< sibling positions (one child offset each)
    std::uint16_t firstChild = 0;       ///< index of its first child offset in the gene
    std::uint32_t edge = 0;             ///< generator-graph edge id, unique over the grammar
    /// `optional`: the genome may leave it out even at probability 1 (grow adds it, cut removes
    /// it, a fresh gene does not bring it), so a cycle through it may end; uncontrolled
    /// derivations still express each position with `probability`.
    bool optional = false;
    bool mandatory() const { return probability >= 1.0f && !optional; }
    /// Relative chance that cut picks an expressed position of this slot.
    float cutWeight() const { return optional ? 1.0f : 1.0f - probability; }
};

enum class StatementKind : std::uint8_t {
    Scale, Size, Translate, Rotate, Mirror, Child,
    Primitive,                           // emit a primitive of kind `primitive` (its arguments: shape/kinds/)
    TerminalBegin, TerminalEnd,          // `terminal { ... }`: runs only on genes without expressed children
    If,        // expr[0] is the condition: if it is 0 (or NaN), go on at `end`
    Jump,      // go on at `end` (closes an if's branch that has an else)
    Let,       // frame floats [slot, slot + axis) = expr[0..axis) (a `let` or an inline call's argument)
    Pieces,    // split, repeat, comp, lots: Grammar::pieceLists[slot]; the pieces' bodies follow; `end` is after them
    Extrude,   // a flat scope becomes a volume of height expr[0] (geometry/derive.hpp: flat scopes)
    Color,     // the colour of what follows: expr[0..2]
    Material,  // the named material of what follows: slot (index into Grammar::materialNames)
    Texture,   // the textured material of what follows: slot (index into Grammar::textures), stretch expr[0..1]
    ScopeFrame,  // the current scope's origin and axes into the parameter block (kScopeOriginSlot...): put
                 // right before each statement whose expressions read scope.origin or scope.axis
    Open,    // first statement of a rule body that gathers: opens Grammar::gathers [slot, slot + end), one
             // collection each, gathered once everything this invocation started is done
    Send,    // a copy of the current scope goes into the innermost open collection of list `slot` (Grammar::listNames)
    Gather,  // gather Grammar::gathers[slot] { ... }: the place its frame is taken; its routes' bodies follow; `end` is after them
    Set,     // set NAME = expr[0]: carried attribute `slot` (Grammar::carriedNames) of the current shape and all it derives
};
struct Statement {
    StatementKind kind;
    std::uint8_t axis = 0;       ///< Rotate, Mirror; Let: number of floats (1 or 3)
    PrimitiveKind primitive = PrimitiveKind::Box;  ///< Primitive: its kind
    std::uint16_t slot = 0;      ///< Child: slot index; Primitive: its kind's tag (Mesh: index into Grammar::meshes; Roof: its form)
    std::uint32_t end = 0;       ///< TerminalBegin: index of its TerminalEnd; If, Jump, Pieces: where to go on
    ExprRef expr[3];             ///< vector statements use 3, Rotate and a cone Primitive expr[0], `roof top` expr[0..1]
};

/// How one piece of a split takes its share of the scope along the split axis.
enum class PieceSize : std::uint8_t {
    Absolute,  ///< `EXPR`: that many units
    Relative,  ///< `'EXPR`: that fraction of the scope's size along the axis
    Floating,  ///< `~EXPR`: about that many units, stretched with the other floating pieces to fill
};
/// One piece of a Pieces statement: its size (splits) and the statements its successor runs
/// ([begin, end) of the rule's statements; empty for `nil`).
struct Piece {
    PieceSize size = PieceSize::Absolute;
    bool repeated = false;      ///< split: inside the `{ ... }*` repeat group
    std::uint8_t face = 0;      ///< comp: the face (FaceName)
    ExprRef value;              ///< split: the size expression
    std::uint32_t begin = 0, end = 0;
    /// Index in its list of the first piece with the same successor statements (a successor
    /// named twice, comp's `side`, a repeat's round robin): pieces of one kind count their
    /// repetitions for `per piece` parameters.
    std::uint16_t first = 0;
};
/// The faces `comp` takes a volume apart into (see geometry/derive.hpp for their frames).
enum class FaceName : std::uint8_t { Top, Bottom, Front, Back, Left, Right };
inline constexpr int kFaces = 6;
/// What a Pieces statement makes of the current scope.
enum class PiecesKind : std::uint8_t {
    Split,        ///< split AXIS { SIZE: A | ... }: pieces along one axis
    RepeatCount,  ///< repeat AXIS count N A | B ...: N equal pieces, successors in turn
    RepeatSize,   ///< repeat AXIS [~]SIZE A | B ...: as many pieces of SIZE as fit (floating: stretched to fill)
    Comp,         ///< comp { FACE: A | ... }: a volume's faces as flat scopes
    LotRect,      ///< lot rect (x1, y1, x2, y2) A: a flat lot in the scope's ground plane
    LotCircle,    ///< lot circle (cx, cy, r) A: the flat square lot around a circle
    Center,       ///< center (w, d) A: a lot of w x d units in the middle of a flat scope
    Corners,      ///< corners (rx, ry) [on (a, b, c, d)] [inside] A | ...: square lots on a flat scope's corners
    Edges,        ///< edges (rx, ry) (n1, n2, n3, n4) A | ...: lots along a flat scope's edges, x along the edge
    Copy,         ///< [ STATEMENTS ]: one piece, the scope itself (CGA's push / pop); keeps piece.index / piece.count
    CopyCount,    ///< copy N A | B ...: N pieces, each the scope itself, successors in turn (PCGR's copy)
};
/// Most pieces one split may list (a repeat group makes any number of them).
inline constexpr std::size_t kMaxSplitPieces = 256;
struct PieceList {
    PiecesKind kind = PiecesKind::Split;
    std::uint8_t axis = 0;       ///< Split, Repeat*
    bool floating = false;       ///< RepeatSize with `~`; Corners with `inside`
    ExprRef arg[6];              ///< the kind's numbers (see PiecesKind), in source order
    std::uint32_t first = 0, count = 0;  ///< its pieces in Grammar::pieces
};

struct SourceLocation {
    int line = 0, column = 0;
};

/// One step of a gather block (PCGR's collective nodes, grammars/README.md "Lists"): operations
/// reorder the collected entities or compute a value over them; the last step is a route, which
/// sends each entity to a successor (statements [begin, end) of the rule; empty: nil).
enum class ListOpKind : std::uint8_t {
    OrderBy,    ///< order by E [asc|desc]: expr[0] per entity; detail 1 = descending; `keys` OrderBy ops in a row form one sort
    Reverse,    ///< reverse
    Shuffle,    ///< shuffle U: a permutation drawn from expr[0] (a value in [0, 1]) and the invocation's piece key
    Aggregate,  ///< let NAME = min|max|avg|sum(E): detail = AggregateKind, dims 1 or 3, into frame floats [slot, slot + dims)
    GroupBy,    ///< group by E, ...: expr[0] per entity; `keys` GroupBy ops in a row form one grouping
    Cluster,    ///< cluster K by E: expr[0] K, expr[1..1 + dims) the point per entity (dims 1 or 3)
    Unify,      ///< unify [within T]: expr[0] the tolerance
    Merge,      ///< merge: each group (or the whole list) becomes one entity
    Ungroup,    ///< ungroup
    RayCast,    ///< let NAME = raycast(±AXIS, LIST): per entity; detail = axis (0-2) + 4 if negative; `other` the target list
    Facing,     ///< let NAME = facing(LIST, DEGREES [, unoccluded]): per entity 1 or 0; expr[0] degrees; detail 1 = unoccluded
    KeepFirst,  ///< route: keep first N [from K] : A | rest : B (expr[0] N, expr[1] K)
    Each,       ///< route: each : A
    Where,      ///< route: where (E) : A | else : B (expr[0] per entity)
};
enum class AggregateKind : std::uint8_t { Min, Max, Avg, Sum, GroupIndex };  ///< GroupIndex: `let NAME = group.index`
struct ListOp {
    ListOpKind kind = ListOpKind::Reverse;
    std::uint8_t detail = 0;     ///< OrderBy: 1 descending; Aggregate: AggregateKind
    std::uint8_t dims = 1;       ///< Aggregate: floats of its value; Cluster: of its point
    std::uint8_t keys = 1;       ///< OrderBy, GroupBy (the first of a run): how many such ops make its keys
    std::uint16_t slot = 0;      ///< Aggregate, RayCast, Facing: its frame index
    std::uint32_t other = 0;     ///< RayCast, Facing: the gather whose list is the target (kOwnList: this gather's own)
    ExprRef expr[4];
    std::uint32_t begin[2] = {}, end[2] = {};  ///< routes: successor 0 (first / each / where) and 1 (rest / else)
};
/// How many of a ListOp's expressions it uses: expr[0, listOpExpressions(op)).
inline int listOpExpressions(const ListOp& op) {
    switch (op.kind) {
    case ListOpKind::Aggregate: return op.detail == std::uint8_t(AggregateKind::GroupIndex) ? 0 : op.dims;
    case ListOpKind::Cluster: return 1 + op.dims;
    case ListOpKind::KeepFirst: return 2;
    case ListOpKind::Facing: return 1;
    case ListOpKind::Reverse:
    case ListOpKind::RayCast:
    case ListOpKind::Each:
    case ListOpKind::Merge:
    case ListOpKind::Ungroup: return 0;
    default: return 1;
    }
}
/// A gather block: the list it gathers and its steps Grammar::listOps [firstOp, firstOp + ops)
/// (the last one a route).
struct Gather {
    std::uint16_t list = 0;      ///< index in Grammar::listNames
    std::uint32_t firstOp = 0, ops = 0;
    SourceLocation where;
};
/// Most entities one collection holds: beyond it the derivation stops as Truncated.
inline constexpr std::uint32_t kMaxListEntities = 65535;
/// ListOp::other of a ray cast or facing step that looks at its own gather's list.
inline constexpr std::uint32_t kOwnList = UINT32_MAX;
/// Most assignment rounds of `cluster` (k-means) before it stops where it is.
inline constexpr std::uint32_t kMaxClusterRounds = 100;

/// Parameter-block index where a rule's frame values (`let`, inline calls' arguments) start: they
/// follow the (at most 256) stored parameter floats in derive's work space, never in genes.
inline constexpr std::uint16_t kFrameBase = 256;
/// Parameter-block index where derive keeps the running task's piece key (its bits, for
/// OpCode::Fresh): after the frame values.
inline constexpr std::uint16_t kPieceKeySlot = 2 * kFrameBase;
/// Parameter-block indices of the running task's piece.index and piece.count (floats; derive
/// writes them only when Grammar::usesPiecePlaces).
inline constexpr std::uint16_t kPieceIndexSlot = kPieceKeySlot + 1;
inline constexpr std::uint16_t kPieceCountSlot = kPieceKeySlot + 2;
/// Parameter-block indices of the current scope's world origin and axes x, y, z (3 floats each),
/// written by a ScopeFrame statement (which the compiler puts only where they are read).
inline constexpr std::uint16_t kScopeOriginSlot = kPieceKeySlot + 3;
inline constexpr std::uint16_t kScopeAxisSlot = kScopeOriginSlot + 3;  ///< axis a at kScopeAxisSlot + 3 * a
/// Floats of derive's parameter block: the last slot above, plus one.
/// Most carried attributes a grammar declares (`carry NAME = VALUE`).
inline constexpr std::size_t kMaxCarried = 8;
/// Parameter-block index of the running task's carried attribute values (derive writes them only
/// when the grammar declares some).
inline constexpr std::uint16_t kCarriedSlot = kScopeAxisSlot + 9;
inline constexpr std::size_t kParamBlockFloats = std::size_t(kCarriedSlot) + kMaxCarried;

struct Rule {
    std::string name;
    SourceLocation where;
    std::vector<Param> params;
    std::vector<Slot> slots;
    std::vector<Statement> statements;
    std::uint16_t paramFloats = 0;   ///< floats in the parameter block
    std::uint16_t childOffsets = 0;  ///< sum of slot maxCount
    std::uint16_t frameFloats = 0;   ///< floats of `let` values and inline calls' arguments (after kFrameBase)
    /// Gene size in 32-bit words: header (rule id, parent offset) + child offsets + parameters.
    std::uint32_t geneWords() const { return 2u + childOffsets + paramFloats; }
};

/// An inline rule call (a rule named as a statement or as a successor of a split, comp or lot),
/// kept for the picture of the generator graph (`shapevo graph`); derive never reads it.
struct InlineCall {
    std::uint16_t rule = 0;   ///< the rule whose gene runs the call (nested calls: the outermost rule)
    std::string callee;       ///< the called rule's name (one with arguments may have no Rule of its own)
    SourceLocation where;     ///< the first such call in that rule
};

struct Grammar {
    std::string path;        ///< file it was read from
    std::string source;      ///< its full text (stored in outputs and checkpoints)
    std::vector<std::string> includes;  ///< other files its text reads (a rule file's includes), relative to its folder
    std::vector<Rule> rules;
    std::uint16_t start = 0;
    std::vector<Instr> code;
    std::vector<float> choiceValues;
    std::vector<MeshShape> meshes;   ///< shapes of `mesh "file"` statements, read when the grammar is loaded
    std::vector<PieceList> pieceLists;   ///< one per Pieces statement
    std::vector<Piece> pieces;
    std::vector<std::string> materialNames{""};  ///< index 0: no named material
    bool hasAppearance = false;      ///< a `color` or `material` statement exists (derive fills Geometry::appearance)
    bool usesPieceKeys = false;      ///< a `per piece` parameter exists (derive keeps piece keys for OpCode::Fresh)
    bool usesPiecePlaces = false;    ///< an expression reads piece.index or piece.count (derive keeps them per task)
    bool marksPieces = false;        ///< usesPieceKeys || usesPiecePlaces (set once parsed: derive tests one flag)
    std::vector<Texture> textures;   ///< images of `texture` statements (which set hasAppearance too), read when the grammar is loaded
    std::map<std::string, double> attrs;  ///< every attr's final value (after overrides)
    std::uint32_t edgeCount = 0;
    std::vector<InlineCall> inlineCalls;  ///< each (rule, callee) pair once, by rule id, in the order met
    std::vector<std::string> listNames;   ///< lists named by send / gather
    std::vector<Gather> gathers;          ///< every gather block (Open and Gather statements index it)
    std::vector<ListOp> listOps;
    bool hasLists = false;                ///< a gather exists (derive checks its markers)
    /// Carried attributes (`carry NAME = VALUE`): every shape carries one value of each, which its
    /// descendants inherit and `set` changes; expressions read it by name.
    std::vector<std::string> carriedNames;
    std::vector<float> carriedDefaults;   ///< the value a derivation's first shape carries
    bool carries() const { return !carriedNames.empty(); }
    int maxStack = 0;        ///< deepest expression evaluation stack
    /// Largest number of genes a freshly grown gene of each rule brings with it (mandatory children).
    std::vector<std::uint32_t> mandatoryGenes;
    std::vector<std::uint32_t> mandatoryWords;

    int findRule(const std::string& name) const;
};

}  // namespace shapevo

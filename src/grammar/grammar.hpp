// Grammar: the generator graph compiled from a .grammar file.
// Rules (nodes) carry parameters with priors, a linear list of shape statements, and child
// slots (edges). Expressions are compiled once into a flat instruction array; deriving a genome
// never re-reads text. See grammars/README.md for the language.
#pragma once
#include <cstdint>
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
    bool mandatory() const { return probability >= 1.0f; }
};

enum class StatementKind : std::uint8_t {
    Scale, Size, Translate, Rotate, Mirror, Child,
    Primitive,                           // emit a primitive of kind `primitive` (its arguments: shape/kinds/)
    TerminalBegin, TerminalEnd,          // `terminal { ... }`: runs only on genes without expressed children
};
struct Statement {
    StatementKind kind;
    std::uint8_t axis = 0;       ///< Rotate, Mirror
    PrimitiveKind primitive = PrimitiveKind::Box;  ///< Primitive: its kind
    std::uint16_t slot = 0;      ///< Child: slot index; Primitive: its kind's tag (Mesh: index into Grammar::meshes; Roof: its form)
    std::uint32_t end = 0;       ///< TerminalBegin: index of its TerminalEnd
    ExprRef expr[3];             ///< vector statements use 3, Rotate and a cone Primitive expr[0], `roof top` expr[0..1]
};

struct SourceLocation {
    int line = 0, column = 0;
};

struct Rule {
    std::string name;
    SourceLocation where;
    std::vector<Param> params;
    std::vector<Slot> slots;
    std::vector<Statement> statements;
    std::uint16_t paramFloats = 0;   ///< floats in the parameter block
    std::uint16_t childOffsets = 0;  ///< sum of slot maxCount
    /// Gene size in 32-bit words: header (rule id, parent offset) + child offsets + parameters.
    std::uint32_t geneWords() const { return 2u + childOffsets + paramFloats; }
};

struct Grammar {
    std::string path;        ///< file it was read from
    std::string source;      ///< its full text (stored in outputs and checkpoints)
    std::vector<Rule> rules;
    std::uint16_t start = 0;
    std::vector<Instr> code;
    std::vector<float> choiceValues;
    std::vector<MeshShape> meshes;   ///< shapes of `mesh "file"` statements, read when the grammar is loaded
    std::uint32_t edgeCount = 0;
    int maxStack = 0;        ///< deepest expression evaluation stack
    /// Largest number of genes a freshly grown gene of each rule brings with it (mandatory children).
    std::vector<std::uint32_t> mandatoryGenes;
    std::vector<std::uint32_t> mandatoryWords;

    int findRule(const std::string& name) const;
};

}  // namespace shapevo

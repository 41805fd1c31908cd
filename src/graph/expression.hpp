// The expression language of 2D graph grammars: the small subset of Python the original's files
// use (graph-grammar README, section 3), compiled when the file is read — never eval'd, no
// interpreter. Every name is resolved at compile time against the names its place may see (a
// typo is an error then, not when a step first reaches it); the whitelisted functions are the only
// calls; nesting depth and text size are bounded. Evaluation allocates only for strings and
// tuples it builds, and draws every random number from a DrawSource.
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "graph/draw_source.hpp"
#include "graph/value.hpp"

namespace shapevo::graph {

/// Limits on what one expression may be (each a clear compile error when exceeded).
inline constexpr std::size_t kMaxExpressionBytes = 64 * 1024;
inline constexpr int kMaxExpressionDepth = 64;

/// The names an expression's place lets it see, each bound to one slot of the frame it is
/// evaluated in (graph-grammar README, section 2.5 says which names each place has).
struct NameSlots {
    std::vector<std::string> names;  // slot i holds names[i]
    /// The slot of `name`, or -1.
    int find(std::string_view name) const {
        for (std::size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return int(i);
        return -1;
    }
    int add(std::string name) {
        names.push_back(std::move(name));
        return int(names.size()) - 1;
    }
};

/// A compile error: what went wrong and the byte offset in the expression's text.
class ExpressionError : public std::runtime_error {
public:
    ExpressionError(const std::string& what, std::size_t offset) : std::runtime_error(what), offset_(offset) {}
    std::size_t offset() const { return offset_; }

private:
    std::size_t offset_;
};

/// An evaluation error (division by zero, a wrong type, int('x'), ...). A missing attribute key
/// is MissingKeyError, which a match condition treats as "no match".
class EvaluationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};
class MissingKeyError : public EvaluationError {
public:
    using EvaluationError::EvaluationError;
};

/// What an expression is evaluated with: one value per slot of the NameSlots it was compiled
/// against, the grammar's attribute names (for X.attr['key']) and the source of random draws.
struct EvaluationFrame {
    const Value* slots = nullptr;
    std::size_t slotCount = 0;
    const AttrNames* names = nullptr;
    DrawSource* draws = nullptr;
};

class CompiledExpression {
public:
    CompiledExpression();
    ~CompiledExpression();
    CompiledExpression(CompiledExpression&&) noexcept;
    CompiledExpression& operator=(CompiledExpression&&) noexcept;

    /// Evaluates it. Throws EvaluationError (or MissingKeyError).
    Value evaluate(const EvaluationFrame& frame) const;
    /// True if it is one constant (no name, no random draw): its value never changes.
    bool isConstant() const;
    /// True if it calls random.* (a decision a genome may own).
    bool drawsRandomly() const;
    /// The slots it reads (each once, ascending).
    const std::vector<int>& slotsRead() const;

    struct Program;  // the compiled form (expression.cpp)
    explicit CompiledExpression(std::unique_ptr<Program> program);

private:
    std::unique_ptr<Program> program_;
};

/// Compiles `text` against `slots`. Attribute keys quoted in X.attr['key'] / attrs['key'] are
/// interned into `names`. Throws ExpressionError with the offset of the fault.
CompiledExpression compileExpression(std::string_view text, const NameSlots& slots, AttrNames& names);

}  // namespace shapevo::graph

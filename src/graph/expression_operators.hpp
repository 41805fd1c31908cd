// The operators of the expression language (internal to the expression files), with Python's
// semantics: true and floor division, the sign of %, int overflow as an EvaluationError, str and
// tuple concatenation and bounded repetition, vector arithmetic, comparisons across types.
#pragma once
#include "graph/expression_program.hpp"

namespace shapevo::graph {

/// `a op b` into `out` (which neither operand aliases).
void binaryOperation(BinaryOp op, const Value& a, const Value& b, Value& out);
/// Unary minus / plus into `out`.
void negateValue(const Value& a, Value& out);
void plusValue(const Value& a, Value& out);
/// Python's `a op b` for ==, !=, <, <=, >, >=; ordering between unrelated types is an
/// EvaluationError ("'<' not supported between instances of 'str' and 'int'").
bool compareValues(CompareOp op, const Value& a, const Value& b);
/// Throws EvaluationError if a tuple's contents (strings' bytes, nested tuples) exceed kMaxBuiltBytes.
void checkTupleSize(const std::vector<Value>& items);
/// Throws EvaluationError if a string built by an expression exceeds kMaxBuiltBytes.
void checkStringSize(std::size_t bytes);

}  // namespace shapevo::graph

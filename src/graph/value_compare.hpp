// Helpers behind Value's Python semantics that the expression evaluator shares (value.cpp):
// exact comparison of numbers across bool/int/float, and appending str() text to a buffer.
#pragma once
#include <string>

#include "graph/value.hpp"

namespace shapevo::graph {

/// True for bool, int and float (Python's numbers).
bool isNumber(const Value& v);
/// Compares two numbers exactly as Python does (an int with a float by their mathematical
/// values): -1, 0, 1, or 2 when unordered (a nan).
int compareNumbers(const Value& a, const Value& b);
/// Appends Python's str(v) to `out`.
void appendValueText(std::string& out, const Value& v);
/// Appends Python's repr() of a finite or non-finite float ('1.0', '1e+16', 'nan', '-0.0').
void appendFloatRepr(std::string& out, double d);

}  // namespace shapevo::graph

// Python's numeric conversions for the expression language (internal to the expression files):
// int() (truncates floats; parses ' -3 ', '1_000'; int('3.5') is an error), float() (parses
// '3.5', 'inf', '1e3') and round() (half to even, with or without ndigits).
#pragma once
#include <cstdint>

#include "graph/value.hpp"

namespace shapevo::graph {

std::int64_t pythonInt(const Value& v);
double pythonFloat(const Value& v);
/// round(x) (an int) or round(x, ndigits) (the type of x) into `out`.
void pythonRound(const Value& x, const Value* ndigits, Value& out);

}  // namespace shapevo::graph

// The whitelist of callable functions (internal to the expression files): their names, how many
// arguments each takes (checked at compile time), and what each computes (Python's results).
#pragma once
#include <string_view>

#include "graph/expression_program.hpp"

namespace shapevo::graph {

struct FunctionInfo {
    std::string_view name;  // as written: "int", "random.uniform", "np.arctan2", "norm", ...
    Function id;
    int minArgs, maxArgs;   // maxArgs -1: any number (min, max)
};

/// The entry of `name`, or nullptr. Vec is resolved by the parser (its forms differ by keywords).
const FunctionInfo* findFunction(std::string_view name);

/// Calls `f` on `count` (<= 3) arguments, writing its result to `out` (which no argument aliases).
/// min and max of two or more arguments are the evaluator's (minOrMax).
void callFunction(Function f, const Value* const* args, int count, const EvaluationFrame& frame, Value& out);

}  // namespace shapevo::graph

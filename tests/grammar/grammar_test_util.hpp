// Helpers shared by the grammar tests: load a shipped grammar, find rules and params by name.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "grammar/grammar.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo::test {

inline std::string shippedGrammarPath(const std::string& name) {
    return std::string(SHAPEVO_SOURCE_DIR) + "/grammars/" + name;
}

inline const Rule& ruleNamed(const Grammar& g, const std::string& name) {
    const int r = g.findRule(name);
    if (r < 0) throw std::runtime_error("test grammar has no rule " + name);
    return g.rules[std::size_t(r)];
}

inline const Param& paramNamed(const Rule& r, const std::string& name) {
    for (const Param& p : r.params)
        if (p.name == name) return p;
    throw std::runtime_error("rule " + r.name + " has no param " + name);
}

}  // namespace shapevo::test

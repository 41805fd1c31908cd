// Tables of malformed grammars (tests/grammar/malformed_*_test.cpp): each case a grammar text,
// the place its error must name (bad.grammar:LINE:COL) and a distinctive part of the message.
// One parameterized test, GrammarMalformed.IsRejectedWithLocationAndMessage (defined in
// malformed_grammar_test.cpp), checks every table instantiated with it.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

namespace shapevo::malformed_grammar {

struct Malformed {
    const char* name;      ///< test name suffix: what is wrong
    std::string text;      ///< the grammar
    std::string where;     ///< expected "bad.grammar:LINE:COL"
    std::string fragment;  ///< a distinctive part of the expected message
};

inline std::ostream& operator<<(std::ostream& os, const Malformed& m) { return os << m.name; }

/// A one-rule grammar "start A / rule A {" whose body starts on line 3, column 3.
inline std::string body(const std::string& lines) { return "start A\nrule A {\n" + lines + "\n}\n"; }

class GrammarMalformed : public ::testing::TestWithParam<Malformed> {};

inline std::string caseName(const ::testing::TestParamInfo<Malformed>& info) { return std::string(info.param.name); }

/// At least twenty cases, no two with the same name.
inline void expectTwentyDistinctCases(const std::vector<Malformed>& cases) {
    EXPECT_GE(cases.size(), 20u);
    std::vector<std::string> names;
    for (const Malformed& m : cases) names.push_back(m.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << "case names must be unique";
}

}  // namespace shapevo::malformed_grammar

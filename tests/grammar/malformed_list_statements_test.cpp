// Every malformed send / gather statement (grammars/README.md "Lists") is rejected with an
// InputError at file:line:column of the offending token, saying what is wrong: a send that no
// gather of its gene takes, a gather out of place or without a route, unknown steps, routes,
// grouping steps and aggregates written wrong. The test itself is GrammarMalformed's (malformed_grammar_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "malformed_grammar_cases.hpp"

namespace shapevo {
namespace malformed_list_statements_test {

using malformed_grammar::GrammarMalformed;

using malformed_grammar::body;
using malformed_grammar::Malformed;

const std::vector<Malformed>& listCases() {
    static const std::vector<Malformed> all = {
        {"SendWithoutGather", body("  send items"), "bad.grammar:3:8", "'send items' has no 'gather items' to go to"},
        {"SendToTheGatherOfAnotherGene", "start A\nrule A {\n  gather l {\n    each : { box }\n  }\n  child B\n}\nrule B {\n  send l\n}\n",
         "bad.grammar:9:8", "never to another gene"},
        {"SendFromARouteToItsOwnGather", body("  gather l {\n    each : { send l }\n  }"), "bad.grammar:4:19",
         "'send l' has no 'gather l' to go to"},
        {"SendFromARouteToAnEarlierGather", body("  gather a {\n    each : nil\n  }\n  gather b {\n    each : { send a }\n  }"),
         "bad.grammar:7:19", "'send a' has no 'gather a' to go to"},
        {"SendWithoutListName", body("  send 3"), "bad.grammar:3:8", "expected a list name after 'send'"},
        {"GatherInsideABlock", body("  if (1 > 0) {\n    gather l {\n      each : nil\n    }\n  }"), "bad.grammar:4:5",
         "'gather' goes at the top level of a rule's body"},
        {"GatherInsideASuccessor", body("  split x { 1: { gather l { each : nil } } }"), "bad.grammar:3:18",
         "'gather' goes at the top level of a rule's body"},
        {"GatherWithoutListName", body("  gather { each : nil }"), "bad.grammar:3:10", "expected a list name after 'gather'"},
        {"GatherWithoutBrace", body("  gather l each : nil"), "bad.grammar:3:12", "expected '{' after 'gather l'"},
        {"GatherWithoutRoute", body("  gather l {\n    reverse\n  }"), "bad.grammar:3:12", "'gather l' has no route"},
        {"StepAfterTheRoute", body("  gather l {\n    each : nil\n    reverse\n  }"), "bad.grammar:5:5",
         "expected '}' to close 'gather l': its route is its last step"},
        {"UnknownStep", body("  gather l {\n    sort by scope.size.x\n    each : nil\n  }"), "bad.grammar:4:5",
         "expected a list operation (order by, reverse, shuffle"},
        {"OrderWithoutBy", body("  gather l {\n    order scope.size.x\n    each : nil\n  }"), "bad.grammar:4:11",
         "expected 'by' after 'order'"},
        {"KeepWithoutFirst", body("  gather l {\n    keep 2 : nil\n  }"), "bad.grammar:4:10", "expected 'first' after 'keep'"},
        {"RouteWithoutColon", body("  gather l {\n    each { box }\n  }"), "bad.grammar:4:10", "after the route 'each'"},
        {"KeepFirstWithElse", body("  gather l {\n    keep first 1 : nil | else : nil\n  }"), "bad.grammar:4:26",
         "expected 'rest' after '|'"},
        {"WhereWithRest", body("  gather l {\n    where (1 > 0) : nil | rest : nil\n  }"), "bad.grammar:4:27",
         "expected 'else' after '|'"},
        {"WhereWithAVectorCondition", body("  gather l {\n    where (scope.size) : nil\n  }"), "bad.grammar:4:12",
         "a condition must be a scalar"},
        {"EachWithASecondSuccessor", body("  gather l {\n    each : nil | rest : nil\n  }"), "bad.grammar:4:16",
         "its route is its last step"},
        {"UnknownAggregate", body("  gather l {\n    let m = median(scope.size.x)\n    each : nil\n  }"), "bad.grammar:4:13",
         "expected an aggregate min, max, avg or sum"},
        {"AggregateWithAReservedName", body("  gather l {\n    let pi = sum(1)\n    each : nil\n  }"), "bad.grammar:4:9",
         "'pi' is a reserved name"},
        {"AggregateWithoutParentheses", body("  gather l {\n    let m = sum scope.size.x\n    each : nil\n  }"),
         "bad.grammar:4:17", "expected '(' after 'sum'"},
        {"GroupWithoutBy", body("  gather l {\n    group scope.size.x\n    each : nil\n  }"), "bad.grammar:4:11",
         "expected 'by' after 'group'"},
        {"ClusterWithoutBy", body("  gather l {\n    cluster 3 scope.origin\n    each : nil\n  }"), "bad.grammar:4:15",
         "expected 'by' after 'cluster K'"},
        {"GroupSomethingOtherThanIndex", body("  gather l {\n    let g = group.count\n    each : nil\n  }"), "bad.grammar:4:19",
         "expected 'index' after 'group.'"},
        {"GroupIndexWithoutDot", body("  gather l {\n    let g = group index\n    each : nil\n  }"), "bad.grammar:4:19",
         "expected '.' after 'group'"},
        {"RaycastAlongNoAxis", body("  gather l {\n    let d = raycast(+w, l)\n    each : nil\n  }"), "bad.grammar:4:22",
         "expected an axis of the entity's scope (x, y or z, with + or -)"},
        {"RaycastAtAnEarlierList", body("  gather a {\n    each : nil\n  }\n  gather l {\n    let d = raycast(+x, a)\n    each : nil\n  }"),
         "bad.grammar:7:25", "looks at list a, which no gather of this rule after this one gathers"},
        {"FacingWithAnUnknownOption", body("  gather l {\n    let f = facing(l, 30, hidden)\n    each : nil\n  }"), "bad.grammar:4:27",
         "expected 'unoccluded' after facing's angle"},
        {"RouteToAnUndefinedRule", body("  gather l {\n    each : Nope\n  }"), "bad.grammar:4:12", "rule 'Nope' is not defined"},
    };
    return all;
}

INSTANTIATE_TEST_SUITE_P(ListCases, GrammarMalformed, ::testing::ValuesIn(listCases()), malformed_grammar::caseName);

TEST(ListStatementMalformedCases, AtLeastTwentyDistinctCases) { malformed_grammar::expectTwentyDistinctCases(listCases()); }

}  // namespace malformed_list_statements_test
}  // namespace shapevo

// The generator graph of a compiled Grammar (.grammar and .rule files alike) as a GraphDiagram
// (grammar/pcg/graph_diagram.hpp), what `shapevo graph` draws for them:
// - one node per rule in rule-id order (plain rules in file order, then rule instances such as
//   "Branch(0, 120)" in order of first use), each with one single input port "in" and one single
//   output port per child slot ("slot K", K from 1); the start rule is marked; after them one node
//   per rule called only inline that has no Rule of its own (a rule with arguments);
// - one Child edge per slot and alternative, from the slot's port to the derived rule's "in",
//   labelled "slot K · edge E" (E: the generator-graph edge id, Slot::edge) with the slot's
//   probability, sibling positions, `optional` and alternative weight where they are not 1;
// - one Inline edge per (rule, inline callee) pair (Grammar::inlineCalls), from the rule itself
//   to the callee's "in", labelled "inline";
// - after those, one node per gather ("gather LIST", its steps as its second line) with one
//   collective input port "list", an Inline edge from the rule that gathers to the node itself
//   ("at the end of each run"), and from every rule that sends to LIST one Inline edge into the
//   port ("send LIST");
// - cyclic edges, topological numbers and loop nodes from numberDiagram() (PCGR §3.4 / §3.5).
#pragma once
#include "grammar/grammar.hpp"
#include "grammar/pcg/graph_diagram.hpp"

namespace shapevo {

pcg::GraphDiagram grammarDiagram(const Grammar& grammar);

}  // namespace shapevo

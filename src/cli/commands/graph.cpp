// `shapevo graph FILE.grammar|.rule|.pcg -o OUT.dot|.svg|.png`: what the file's front end draws
// (grammar/front_ends.hpp, grammarFileDiagram: for .grammar and .rule the generator graph of
// grammar/grammar_diagram.hpp — rules as nodes, child slots and inline calls as edges; for .pcg
// the graph itself, its nodes and ports) in PCGR's notation (report/diagram_writer.hpp): cyclic
// edges dashed, topological numbers and loop stars. The summary line counts the diagram's nodes
// by what they are ("rules" or "nodes").
// The output name is checked before anything is read; nothing is written on bad input.
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "grammar/front_ends.hpp"
#include "report/diagram_writer.hpp"
#include "run/command_options.hpp"
#include "run/model_export.hpp"

namespace shapevo {

namespace {

struct GraphOptions {
    std::string path;
    std::string out;
    std::vector<std::string> attrs;
};
GraphOptions graphOptions;

}  // namespace

void GraphCommand::addOptions(CLI::App& command) {
    GraphOptions& o = graphOptions;
    command.add_option("file", o.path, "grammar file to draw: " + grammarExtensions() + " (docs/grammars.md)")->required();
    command.add_option("-o,--output", o.out,
                       "picture to write: .dot (Graphviz text), .svg or .png (laid out by Graphviz's library; no `dot` "
                       "program needed); must not exist")
        ->required();
    command.add_option("--attr", o.attrs, "replace an attr of the file, NAME=VALUE (repeatable)");
}

void GraphCommand::run(const CommandContext&) {
    const GraphOptions& o = graphOptions;
    const std::string format = requireOutputFormat(o.out, kDiagramFormats, "-o");
    refuseExisting(o.out);
    const pcg::GraphDiagram diagram = grammarFileDiagram(o.path, parseAttrOptions(o.attrs));
    writeDiagram(diagram, format, o.out);
    const pcg::DiagramCounts c = countDiagram(diagram);
    std::cout << "wrote " << o.out << " (" << c.nodes << " " << diagram.nodeNoun << ", " << c.edges << " edges, " << c.cyclicEdges << " cyclic, "
              << c.loopNodes << " on a loop; " << o.path << ")\n";
}

}  // namespace shapevo

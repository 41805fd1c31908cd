// `shapevo sample GRAMMAR -o FILE`: random derivations of a grammar, no evolution (run/sample_models.hpp;
// a 2D graph grammar, .yml: run/sample_graphs.hpp).
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "run/sample_graphs.hpp"
#include "run/sample_models.hpp"

namespace shapevo {

namespace {

SampleRequest sampleOptions;
CLI::Option* minGenesOption = nullptr;
CLI::Option* maxGenesOption = nullptr;

}  // namespace

void SampleCommand::addOptions(CLI::App& command) {
    SampleRequest& o = sampleOptions;
    const std::string redraws = std::to_string(kSampleAttempts);
    command.add_option("grammar", o.grammarPath, "grammar file: .grammar (grammars/README.md), a CastleMaker .rule file "
                                                  "(grammars/castlemaker/README.md), a procedural content graph .pcg "
                                                  "(grammars/pcg/README.md) or a 2D graph grammar, .yml or .yaml "
                                                  "(docs/graph-grammars.md)")
        ->required();
    command.add_option("--seed", o.seed, "random seed, 0 to 2^64-1; with --count N, file k uses seed + k - 1 (mod 2^64)")
        ->capture_default_str();
    minGenesOption = command.add_option("--min-genes", o.minGenes, "tree grammars: a derivation with fewer genes is dropped and drawn again (at most " + redraws +
                                                      " draws per file, then exit 2); nothing is grown beyond what the grammar's "
                                                      "prob gives")
        ->capture_default_str();
    maxGenesOption = command.add_option("--max-genes", o.maxGenes, "tree grammars: a derivation that would need more genes is abandoned and drawn again (same limit); "
                                                  "never truncated")
        ->capture_default_str();
    command.add_option("-o,--output", o.output, "model file (.obj, .ply or .glb; must not exist), or .png: one contact sheet "
                                                "of all --count models, three-quarter views in a grid, each labelled with its seed; "
                                                "a graph grammar: .svg, as the original tool draws it, or .png, that picture "
                                                "painted (one file per derivation)")
        ->required();
    command.add_option("--size", o.tileSize, "with -o .png: the size of each tile, WIDTHxHEIGHT in pixels (default 256x256); "
                                             "a graph grammar: the picture's size, the drawing fitted in it (default: the SVG's "
                                             "own size, one pixel per user unit)");
    command.add_option("--genome", o.genomeOutput, "tree grammars: also save the chromosome (a .genome file) for shapevo evaluate");
    command.add_option("--attr", o.attrs, "tree grammars: replace an attr of the grammar, NAME=VALUE (repeatable), as "
                                          "[grammar.attr] does in a config");
    command.add_option("--steps", o.steps, "graph grammars: stop each derivation after N steps (default: the file's "
                                           "options.max_derivations.all, else " + std::to_string(kDefaultGraphSampleSteps) +
                                           "; a derivation also stops when no production applies)");
    command.add_option("--margin", o.margin, "graph grammars: space around the vertices' box in model units (default 0.5, "
                                             "so shapes on the border stay whole; 0: the original's canvas)");
    command.add_option("--count", o.count, "write N variations, 1 to " + std::to_string(kMaxSampleCount) +
                                               "; for N > 1 every output name gets a number before its extension "
                                               "(out.obj -> out-001.obj, out-002.obj, ...; likewise --genome); all are "
                                               "checked before any is written")
        ->capture_default_str();
}

void SampleCommand::run(const CommandContext&) {
    sampleOptions.minGenesGiven = minGenesOption && minGenesOption->count() > 0;
    sampleOptions.maxGenesGiven = maxGenesOption && maxGenesOption->count() > 0;
    sampleModels(sampleOptions, std::cout);
}

}  // namespace shapevo

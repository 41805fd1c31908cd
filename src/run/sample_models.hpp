// sampleModels: what `shapevo sample` does. A graph grammar (.yml, .yaml) goes to sampleGraphs
// (sample_graphs.hpp); for a tree grammar: random derivations of a grammar (genome/sample.hpp:
// no evolution, every sibling position of a slot expressed with the slot's prob), written as
// model files (.obj, .ply, .glb; numbered when there are several) or as one contact sheet (.png),
// and optionally as .genome files for `shapevo evaluate`. Promises: file k is the derivation of
// seed + k - 1, the same as `--count 1 --seed (seed + k - 1)` writes; every option and every
// output name is checked, and every derivation drawn, before anything is written, so bad input
// or a size window that cannot be met leaves no files behind.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace shapevo {

/// Derivations drawn per file before the size window counts as unreachable, and the most files
/// one call writes.
inline constexpr std::uint32_t kSampleAttempts = 10000;
inline constexpr std::uint32_t kMaxSampleCount = 1000000;

/// The options of `shapevo sample`, as the command line gives them (texts are read, and refused
/// with an InputError naming the option, by sampleModels).
struct SampleRequest {
    std::string grammarPath;         ///< .grammar, CastleMaker .rule or .pcg graph file, or a .yml graph grammar
    std::string seed = "1";          ///< --seed: 0 to 2^64-1; file k uses seed + k - 1 (mod 2^64)
    std::string count = "1";         ///< --count: 1 to kMaxSampleCount files
    std::uint32_t minGenes = 1;      ///< --min-genes: smaller derivations are drawn again
    std::uint32_t maxGenes = 100;    ///< --max-genes: larger ones are abandoned and drawn again
    std::string output;              ///< -o: a model file, or a .png contact sheet of all of them
    std::string tileSize;            ///< --size: a contact sheet's tile, WIDTHxHEIGHT ("" = 256x256)
    std::string genomeOutput;        ///< --genome: also the chromosomes ("" = not)
    std::vector<std::string> attrs;  ///< --attr NAME=VALUE: replaced attrs of the grammar
    bool minGenesGiven = false;      ///< --min-genes was given (refused for a graph grammar)
    bool maxGenesGiven = false;      ///< --max-genes was given (likewise)
    std::string steps;               ///< --steps (graph grammars): "" = the file's options.max_derivations
    std::string margin;              ///< --margin (graph grammars): model units ("" = kDefaultGraphMargin)
};

/// Draws and writes what `request` asks for (a graph grammar: sampleGraphs); prints a line per model ("sampled 12 genes, 40
/// primitives (seed 7) -> castle.obj") and, for a contact sheet, a last line ("wrote ...") to
/// `out`. @throw InputError for bad options, an existing output file, a grammar that cannot be
/// read, or a size window (or primitive limit) the grammar does not meet.
void sampleModels(const SampleRequest& request, std::ostream& out);

}  // namespace shapevo

// `shapevo sample FILE.yml`: graph grammar derivations drawn as SVG or PNG (sample_graphs.hpp).
#include "run/sample_graphs.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string_view>

#include "base/atomic_write.hpp"
#include "genome/families/graph_family.hpp"
#include "genome/genome_file.hpp"
#include "graph/keyed_draws.hpp"
#include "base/input_error.hpp"
#include "graph/derive.hpp"
#include "graph/drawing.hpp"
#include "graph/read_graph_grammar.hpp"
#include "graph/svg_writer.hpp"
#include "report/graph_picture.hpp"
#include "run/command_options.hpp"
#include "run/model_export.hpp"

namespace shapevo {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace sample_graphs_parts {

constexpr std::array<std::string_view, 2> kGraphFormats{"svg", "png"};
constexpr double kMaxMargin = 1e6;

/// --steps: a whole number, 0 (the file's own limit) or more.
std::int64_t parseSteps(const std::string& text) {
    if (text.empty()) return 0;
    std::int64_t v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ptr != end || ec != std::errc() || v < 0)
        throw InputError("--steps", "", "expected a whole number of derivation steps, 0 or more (0: the file's "
                                        "options.max_derivations), got \"" + shortened(text) + "\"");
    return v;
}

/// --margin: model units, 0 to kMaxMargin.
double parseMargin(const std::string& text) {
    if (text.empty()) return kDefaultGraphMargin;
    double v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ptr != end || ec != std::errc() || !std::isfinite(v) || v < 0 || v > kMaxMargin)
        throw InputError("--margin", "", "expected a number of model units from 0 to 1e6 (0: the original's canvas, the "
                                         "vertices' box), got \"" + shortened(text) + "\"");
    return v;
}

/// The options `sample` has for tree grammars only, refused by name.
void refuseTreeOptions(const SampleRequest& r) {
    const auto refuse = [&](const char* option, const char* what) {
        throw InputError(option, "", std::string(what) + " applies to tree grammars (.grammar, .rule, .pcg), not to the graph grammar " +
                                         shortened(r.grammarPath, 256));
    };
    if (r.minGenesGiven) refuse("--min-genes", "a derivation's size window");
    if (r.maxGenesGiven) refuse("--max-genes", "a derivation's size window");
    if (!r.attrs.empty()) refuse("--attr", "replacing a grammar attr");
}

struct Derived {
    graph::DeriveResult result;
    graph::Drawing drawing;
};

/// The derivation of `seed`: the original's sequential draws, or (keyed) the genome of root seed
/// `seed` and no override (genome/families/graph_genome.hpp), as a run's genomes derive.
Derived deriveAndDraw(const graph::GraphGrammar& g, std::uint64_t seed, std::int64_t steps, bool keyed) {
    graph::SeededDraws seeded(seed);
    graph::KeyedDraws byKey(seed, {});
    graph::DeriveLimits limits;
    limits.maxSteps = steps;
    Derived d{graph::deriveGraph(g, 0, keyed ? static_cast<graph::DrawSource&>(byKey) : seeded, limits), {}};
    d.drawing = graph::drawingOf(d.result.graph, g.names, g.path);
    return d;
}

}  // namespace sample_graphs_parts

void sampleGraphs(const SampleRequest& r, std::ostream& out) {
    using namespace sample_graphs_parts;
    refuseTreeOptions(r);
    const std::uint64_t seed = parseSeed(r.seed, "--seed", UINT64_MAX);
    const std::uint32_t count = parseCount(r.count, kMaxSampleCount);
    std::int64_t steps = parseSteps(r.steps);
    const double margin = parseMargin(r.margin);
    const bool png = requireOutputFormat(r.output, kGraphFormats, "-o") == "png";
    if (!r.tileSize.empty() && !png) throw InputError("--size", "", "sizes a PNG picture: use it with -o FILE.png");
    const std::optional<PictureSize> size =
        r.tileSize.empty() ? std::nullopt : std::optional<PictureSize>(parsePictureSize(r.tileSize));
    const graph::GraphGrammar g = graph::readGraphGrammar(r.grammarPath);
    // A grammar that may never end (a Koch curve) and no limit anywhere: a default cap, said below.
    const bool defaultCap = steps == 0 && g.globalLimit == 0;
    if (defaultCap) steps = kDefaultGraphSampleSteps;
    for (std::uint32_t k = 1; k <= count; ++k) refuseExisting(numberedPath(r.output, k, count));
    // --genome: the derivations a genome makes (keyed), each genome written beside its drawing.
    const bool keyed = !r.genomeOutput.empty();
    if (keyed) {
        requireOutputFormat(r.genomeOutput, kGenomeFormats, "--genome");
        for (std::uint32_t k = 1; k <= count; ++k) refuseExisting(numberedPath(r.genomeOutput, k, count));
    }
    // Every derivation is made and drawn once before anything is written, so one that fails
    // leaves no files behind; the second time repeats the first exactly.
    for (std::uint32_t k = 1; k <= count; ++k) deriveAndDraw(g, seed + (k - 1), steps, keyed);
    const std::string name = std::filesystem::path(r.grammarPath).filename().string();
    for (std::uint32_t k = 1; k <= count; ++k) {
        const std::uint64_t seedK = seed + (k - 1);  // wraps mod 2^64
        const Derived d = deriveAndDraw(g, seedK, steps, keyed);
        const std::string path = numberedPath(r.output, k, count);
        const graph::DrawingCanvas canvas = graph::canvasOf(d.drawing, margin);
        if (png) {
            writeDrawingPng(d.drawing, canvas, size ? *size : naturalPictureSize(canvas), path);
        } else {
            const std::string svg = graph::drawingSvg(d.drawing, g.filters, canvas);
            writeStreamAtomically(path, [&](std::ostream& o) { o << svg; }, Replace::Never);
        }
        const graph::HostGraph& h = d.result.graph;
        out << name << " seed " << seedK << ": " << d.result.steps << (d.result.steps == 1 ? " step, " : " steps, ")
            << h.liveVertices() << (h.liveVertices() == 1 ? " vertex, " : " vertices, ") << h.liveEdges()
            << (h.liveEdges() == 1 ? " edge (" : " edges (") << h.danglingEdges() << " dangling), " << h.elements()
            << (h.elements() == 1 ? " element -> " : " elements -> ") << path;
        if (keyed) {
            Chromosome c;
            makeGraphGenome(c, seedK);
            const std::string genomePath = numberedPath(r.genomeOutput, k, count);
            writeGenome(GraphFamily(g, {}), c, genomePath);
            out << ", genome -> " << genomePath;
        }
        out << "\n";
        if (defaultCap && d.result.stop == graph::DeriveResult::Stop::StepLimit)
            out << "  stopped at " << steps << " steps, sample's default limit for a file without options.max_derivations "
                   "(--steps N for another)\n";
    }
}

}  // namespace shapevo

// `shapevo sample`: random derivations written as models, a contact sheet and genomes (sample_models.hpp).
#include "run/sample_models.hpp"

#include <array>
#include <optional>
#include <ostream>
#include <string_view>

#include "base/input_error.hpp"
#include "genome/families/tree_family.hpp"
#include "genome/genome_file.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "report/model_writer.hpp"
#include "report/render/contact_sheet.hpp"
#include "run/command_options.hpp"
#include "run/model_export.hpp"
#include "run/sample_graphs.hpp"

namespace shapevo {

namespace {

const std::string kNeverEnds = "a recursive stochastic rule may never end (castlemaker-crl.txt §5.2): ";

/// What every draw shares, and the model of the latest one.
struct Sampler {
    const Grammar& g;
    const SampleRequest& request;
    std::uint64_t seed;  ///< file 1's
    /// A recursion that ends only by chance (a rule file's recursive stochastic rule,
    /// castlemaker-crl.txt §5.2) may grow without end: --max-genes stops each draw, and
    /// genome.max_primitives (its default: sample has no config) each model.
    bool mayNeverEnd;
    Geometry geo;
    DeriveScratch scratch;
};

struct Drawn {
    std::uint64_t seed;       ///< the file's seed
    std::uint32_t attempts;   ///< derivations drawn for it, the kept one included
};

/// File k's derivation (seed + k - 1, wrapping mod 2^64) into `c`, and its model into s.geo.
/// @throw InputError when the size window or the primitive limit is not met.
Drawn drawModel(Sampler& s, std::uint32_t k, Chromosome& c) {
    const SampleRequest& r = s.request;
    const std::uint64_t seedK = s.seed + (k - 1);  // wraps mod 2^64
    Rng rng(seedK);
    const SampleOutcome o = sampleDerivation(s.g, c, rng, r.minGenes, r.maxGenes, kSampleAttempts);
    if (!o.found && s.mayNeverEnd && o.tooLarge == o.attempts)
        throw InputError("--max-genes", "",
                         "all " + std::to_string(o.attempts) + " derivations of " + r.grammarPath + " drawn (seed " +
                             std::to_string(seedK) + ") grew past the limit of " + std::to_string(r.maxGenes) +
                             " genes and were stopped there; " + kNeverEnds +
                             "lower the probabilities of the alternatives that recurse, or raise --max-genes");
    if (!o.found)
        throw InputError("--min-genes/--max-genes", "",
                         "no derivation of " + r.grammarPath + " with " + std::to_string(r.minGenes) + " to " +
                             std::to_string(r.maxGenes) + " genes in " + std::to_string(o.attempts) + " draws (seed " +
                             std::to_string(seedK) +
                             (o.tooLarge ? "; " + std::to_string(o.tooLarge) + " of them grew past --max-genes" : std::string()) +
                             "); the grammar's prob values make that size rare or impossible" +
                             (o.tooLarge && s.mayNeverEnd ? " (" + kNeverEnds.substr(0, kNeverEnds.size() - 2) + ")" : std::string()) +
                             ": widen the window");
    if (derive(s.g, c, s.geo, s.scratch) == DeriveStatus::Truncated)
        throw InputError("genome.max_primitives", "",
                         "the derivation of " + r.grammarPath + " drawn with seed " + std::to_string(seedK) + " (" +
                             std::to_string(c.genes) + (c.genes == 1 ? " gene" : " genes") + ") reached the limit of " +
                             std::to_string(kDefaultMaxPrimitives) +
                             " primitives (the limit genome.max_primitives sets; sample uses its default) and was stopped "
                             "there; " +
                             (s.mayNeverEnd ? kNeverEnds + "lower the probabilities of the alternatives that recurse, or --max-genes"
                                            : std::string("nested splits, repeats, comps and mirrors multiply what they hold: nest fewer of them")));
    return {seedK, o.attempts};
}

/// @throw InputError if no derivation of `g` can have between --min-genes and --max-genes genes.
void requireSizeWindow(const Grammar& g, const SampleRequest& r) {
    if (r.minGenes > r.maxGenes) throw InputError("--min-genes", "", "must not exceed --max-genes");
    if (g.mandatoryGenes[g.start] > r.maxGenes)
        throw InputError("--max-genes", "", std::to_string(r.maxGenes) + " is smaller than the " +
                                                std::to_string(g.mandatoryGenes[g.start]) + " genes every derivation of " +
                                                r.grammarPath + " needs");
}

}  // namespace

void sampleModels(const SampleRequest& r, std::ostream& out) {
    if (isGraphGrammarPath(r.grammarPath)) return sampleGraphs(r, out);
    if (!r.steps.empty()) throw InputError("--steps", "", "applies to graph grammars (.yml), not to " + shortened(r.grammarPath, 256));
    if (!r.margin.empty()) throw InputError("--margin", "", "applies to graph grammars (.yml), not to " + shortened(r.grammarPath, 256));
    const std::uint64_t seed = parseSeed(r.seed, "--seed", UINT64_MAX);
    const std::uint32_t count = parseCount(r.count, kMaxSampleCount);
    constexpr std::array<std::string_view, 4> kSampleFormats{"obj", "ply", "glb", "png"};
    const std::string format = requireOutputFormat(r.output, kSampleFormats, "-o");
    const bool sheetOut = format == "png";  // one contact sheet instead of numbered model files
    if (!r.tileSize.empty() && !sheetOut) throw InputError("--size", "", "sizes a contact sheet's tiles: use it with -o FILE.png");
    std::optional<ContactSheet> sheet;
    if (sheetOut) sheet.emplace(int(count), r.tileSize.empty() ? PictureSize{256, 256} : parsePictureSize(r.tileSize));
    if (!r.genomeOutput.empty()) requireOutputFormat(r.genomeOutput, kGenomeFormats, "--genome");
    const Grammar g = loadGrammar(r.grammarPath, parseAttrOptions(r.attrs));
    const TreeFamily family(g);
    requireSizeWindow(g, r);
    for (std::uint32_t k = 1; k <= count; ++k) {
        refuseExisting(sheetOut ? r.output : numberedPath(r.output, k, count));
        if (!r.genomeOutput.empty()) refuseExisting(numberedPath(r.genomeOutput, k, count));
    }
    // Every derivation is drawn once before anything is written, so a size window that cannot
    // be met leaves no files behind; the second draw repeats the first exactly.
    Sampler s{g, r, seed, grammarFrontEndFor(r.grammarPath).recursionsEndOnlyByChance || hasOptionalRecursion(g), {}, {}};
    Chromosome c;
    for (std::uint32_t k = 1; k <= count; ++k) drawModel(s, k, c);
    for (std::uint32_t k = 1; k <= count; ++k) {
        const Drawn d = drawModel(s, k, c);
        const std::string modelPath = sheetOut ? r.output + " tile " + std::to_string(k) : numberedPath(r.output, k, count);
        if (sheetOut) sheet->draw(int(k) - 1, meshOf(s.geo), std::to_string(d.seed));
        else writeModelFile(s.geo, format, modelPath, Replace::Never);
        out << "sampled " << c.genes << " genes, " << s.geo.primitives.size() << " primitives (seed " << d.seed;
        if (d.attempts > 1) out << ", draw " << d.attempts;
        out << ") -> " << modelPath;
        if (!r.genomeOutput.empty()) {
            const std::string genomePath = numberedPath(r.genomeOutput, k, count);
            writeGenome(family, c, genomePath);
            out << ", " << genomePath;
        }
        out << "\n";
    }
    if (sheetOut) {
        sheet->write(r.output);
        out << "wrote " << r.output << " (" << count << (count == 1 ? " model, " : " models, ") << sheet->width() << "x"
            << sheet->height() << " pixels)\n";
    }
}

}  // namespace shapevo

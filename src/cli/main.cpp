// shapevo command line: run, resume, inspect, export, render, sample, target, evaluate. Bad input
// (InputError, bad arguments, a wrong MPI set-up) prints one message and exits with code 2;
// other failures exit with code 1. Under mpirun every rank runs this; only run and resume use
// more than one rank. Results go to stdout; errors, warnings and notices ("shapevo: ...") to
// stderr (cli/log_router.hpp). Output file names are checked (extension, existence), and a new
// run's memory estimate, before anything is read or created.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <span>

#include <CLI/CLI.hpp>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"
#include "base/keep_freed_memory.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/checkpoint_path.hpp"
#include "genome/genome_file.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/parser.hpp"
#include "island/mpi_session.hpp"
#include "island/stop_signal.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_repair.hpp"
#include "report/model_writer.hpp"
#include "report/render/contact_sheet.hpp"
#include "report/render/model_picture.hpp"
#include "cli/log_router.hpp"
#include "run/config_file.hpp"
#include "run/island_loop.hpp"
#include "run/memory_check.hpp"
#include "run/model_export.hpp"
#include "run/run_job.hpp"
#include "run/scene.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "search/evaluator.hpp"

namespace {

using namespace shapevo;

void refuseExisting(const std::string& path) {
    if (std::filesystem::exists(path))
        throw InputError(path, "", "already exists; shapevo does not overwrite files (remove it or choose another -o)");
}

/// The seed an option gives: a whole number in [0, max], exactly (never saturated or wrapped).
std::uint64_t parseSeed(const std::string& text, const std::string& option, std::uint64_t max) {
    const std::string range = "[0, " + std::to_string(max) + "]";
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ptr != end || (ec != std::errc() && ec != std::errc::result_out_of_range))
        throw InputError(option, "", "expected a whole number in " + range + ", got \"" + shortened(text) + "\"");
    if (ec == std::errc::result_out_of_range || v > max)
        throw InputError(option, "", shortened(text) + " is out of range " + range +
                                         (max < UINT64_MAX ? " (the largest seed a config's run.seed holds; the run's config.toml records it)" : ""));
    return v;
}

/// --count: a whole number in [1, max].
std::uint32_t parseCount(const std::string& text, std::uint32_t max) {
    std::uint32_t v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ptr != end || ec != std::errc() || v < 1 || v > max)
        throw InputError("--count", "", "expected a whole number of files from 1 to " + std::to_string(max) + ", got \"" +
                                            shortened(text) + "\"");
    return v;
}

/// The k-th (1-based) of `count` output names: `path` itself if count is 1, else `path` with
/// "-NNN" before its extension (out.obj -> out-001.obj; at least 3 digits, as many as count has).
/// --attr NAME=VALUE options as attr overrides.
AttrOverrides parseAttrOptions(const std::vector<std::string>& options) {
    AttrOverrides attrs;
    for (const std::string& a : options) {
        const auto eq = a.find('=');
        char* end = nullptr;
        const double v = eq == std::string::npos ? 0.0 : std::strtod(a.c_str() + eq + 1, &end);
        if (eq == std::string::npos || eq == 0 || end == a.c_str() + eq + 1 || *end != '\0' || !std::isfinite(v))
            throw InputError("--attr", a, "expected NAME=NUMBER, e.g. --attr taper=0.6");
        attrs[a.substr(0, eq)] = v;
    }
    return attrs;
}

std::string numberedPath(const std::string& path, std::uint32_t k, std::uint32_t count) {
    if (count == 1) return path;
    const std::filesystem::path p(path);
    std::string n = std::to_string(k);
    n.insert(0, std::max<std::size_t>(3, std::to_string(count).size()) - n.size(), '0');
    return (p.parent_path() / (p.stem().string() + "-" + n + p.extension().string())).string();
}

/// MPI ranks on this machine, from the launcher's environment (Open MPI, MPICH, Slurm); 1 if unknown.
int ranksOnThisMachine() {
    for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS", "SLURM_NTASKS_PER_NODE"})
        if (const char* v = std::getenv(name)) {
            const int n = std::atoi(v);
            if (n > 0) return n;
        }
    return 1;
}

/// sample: derivations drawn per file before the size window counts as unreachable, and the
/// most files one call writes.
constexpr std::uint32_t kSampleAttempts = 10000;
constexpr std::uint32_t kMaxSampleCount = 1000000;

/// What inspect and export accept (checkpoint/checkpoint_path.hpp).
constexpr const char* kCheckpointPaths =
    "a run folder (its newest complete checkpoint), a checkpoint folder (checkpoint-NNNNNN), or a checkpoint's "
    "run.h5 or island-NNNN.h5 (the checkpoint that holds it)";

}  // namespace

int main(int argc, char** argv) {
    keepFreedMemory();
    MpiSession mpi(argc, argv);
    CLI::App app{"shapevo: evolve procedural models (grammars) until they fill a target volume.\n"
                 "Docs: README.md; grammar language: grammars/README.md"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "shapevo 0.1.0");

    // run
    auto* run = app.add_subcommand("run", "Evolve a model: shapevo run CONFIG.toml");
    std::string config;
    std::string seed;
    std::vector<std::string> sets;
    std::string out;
    bool quiet = false;
    int threads = -1;
    run->add_option("config", config, "TOML config (see configs/)")->required();
    auto* seedOpt = run->add_option("--seed", seed, "random seed, 0 to 2^63-1 (overrides run.seed; written into the run's config.toml)");
    run->add_option("--set", sets, "override a config value, e.g. --set ga.population=50 (repeatable)");
    run->add_option("--out", out, "output folder; must not exist (default runs/<name>, runs/<name>-2, ...)");
    run->add_option("--threads", threads, "threads (overrides run.threads; 0 = all cores)")->check(CLI::NonNegativeNumber);
    run->add_flag("-q,--quiet", quiet, "no per-generation progress lines");

    // sample
    auto* sample = app.add_subcommand("sample", "Write random derivations of a grammar (no evolution): every sibling position "
                                                "of a slot is expressed with the slot's prob, independently, recursively");
    std::string grammarPath, sampleOut, genomeOut;
    std::string sampleSeed = "1", sampleCount = "1";
    std::uint32_t minGenes = 1, maxGenes = 100;
    const std::string redraws = std::to_string(kSampleAttempts);
    sample->add_option("grammar", grammarPath, "grammar file: .grammar (grammars/README.md) or a CastleMaker .rule file (grammars/castlemaker/README.md)")->required();
    sample->add_option("--seed", sampleSeed, "random seed, 0 to 2^64-1; with --count N, file k uses seed + k - 1 (mod 2^64)")
        ->capture_default_str();
    sample->add_option("--min-genes", minGenes, "a derivation with fewer genes is dropped and drawn again (at most " + redraws +
                                                    " draws per file, then exit 2); nothing is grown beyond what the grammar's "
                                                    "prob gives")
        ->capture_default_str();
    sample->add_option("--max-genes", maxGenes, "a derivation that would need more genes is abandoned and drawn again (same limit); "
                                                "never truncated")
        ->capture_default_str();
    sample->add_option("-o,--output", sampleOut, "model file (.obj, .ply or .glb; must not exist), or .png: one contact sheet "
                                                 "of all --count models, three-quarter views in a grid, each labelled with its seed")
        ->required();
    std::string sampleSize;
    sample->add_option("--size", sampleSize, "with -o .png: the size of each tile, WIDTHxHEIGHT in pixels (default 256x256)");
    sample->add_option("--genome", genomeOut, "also save the chromosome (a .genome file) for shapevo evaluate");
    std::vector<std::string> sampleAttrs;
    sample->add_option("--attr", sampleAttrs, "replace an attr of the grammar, NAME=VALUE (repeatable), as [grammar.attr] does in a config");
    sample->add_option("--count", sampleCount, "write N variations, 1 to " + std::to_string(kMaxSampleCount) +
                                                   "; for N > 1 every output name gets a number before its extension "
                                                   "(out.obj -> out-001.obj, out-002.obj, ...; likewise --genome); all are "
                                                   "checked before any is written")
        ->capture_default_str();

    // target
    auto* target = app.add_subcommand("target", "Make a target from a mesh (OBJ, PLY, STL, OFF, glTF/GLB, FBX, 3MF, DAE, 3DS or any other "
                                                "format Assimp reads): a volume (OpenVDB level set of its "
                                                "inside; seams, small holes and non-manifold edges are repaired and reported) "
                                                "or, with --image, a picture of its silhouette or shadow");
    std::string meshPath, vdbOut, imageConfig;
    double voxelSize = 0.1;
    target->add_option("mesh", meshPath, "triangle mesh, format by extension: .obj, .ply, .stl (read by shapevo) or .off, "
                                         ".gltf, .glb, .fbx, .3mf, .dae, .3ds, .x, .blend, ... (read by Assimp; an unknown "
                                         "extension's error lists them all; a scene's meshes are merged in world space); for "
                                         "a volume its inside must be determinable (holes filled, at most half its surface)")
        ->required();
    target->add_option("-o,--output", vdbOut, "output .vdb, or .png with --image (must not exist)")->required();
    auto* voxelOpt = target->add_option("--voxel-size", voxelSize, "voxel edge length in model units")->capture_default_str();
    target->add_option("--image", imageConfig, "draw the mesh through the camera of this image config ([target] image and "
                                               "[camera]) into a PNG of the camera's size that its pixel rule reads as hit "
                                               "where the mesh is")
        ->excludes(voxelOpt);

    // translate
    auto* translate = app.add_subcommand("translate", "Print what a CastleMaker rule file (.rule) compiles into, in the shapevo "
                                                      "grammar language: shapevo translate FILE.rule");
    std::string translatePath;
    std::vector<std::string> translateAttrs;
    translate->add_option("rule_file", translatePath, "CastleMaker rule file (grammars/castlemaker/README.md)")->required();
    translate->add_option("--attr", translateAttrs, "replace an attr of the rule file, NAME=VALUE (repeatable)");

    // evaluate
    auto* evaluate = app.add_subcommand("evaluate", "Score a saved chromosome against a config's target (volume or image), "
                                                    "as run scores it: shapevo evaluate CONFIG.toml FILE.genome");
    std::string evalConfig, evalGenome;
    std::vector<std::string> evalSets;
    evaluate->add_option("config", evalConfig, "TOML config, any that run accepts (see configs/)")->required();
    evaluate->add_option("genome", evalGenome, ".genome file (best.genome of a run, or from sample --genome)")->required();
    evaluate->add_option("--set", evalSets, "override a config value as run --set does, e.g. --set score.form=weighted (repeatable)");

    // resume
    auto* resume = app.add_subcommand("resume", "Continue a run from its newest complete checkpoint: shapevo resume RUN_DIR");
    std::string runDir;
    std::uint32_t resumeGenerations = 0;
    bool resumeQuiet = false;
    resume->add_option("run_dir", runDir, "the run folder")->required();
    auto* resumeGenOpt = resume->add_option("--generations", resumeGenerations, "new generation limit (extends a finished run)");
    resume->add_flag("-q,--quiet", resumeQuiet, "no per-generation progress lines");
    bool allowChangedInputs = false;
    resume->add_flag("--allow-changed-inputs", allowChangedInputs,
                     "continue although an input file (config, grammar, mesh, target) changed since the run "
                     "started; the change is recorded in summary.json");

    // inspect
    auto* inspect = app.add_subcommand("inspect", "Summarise a checkpoint: shapevo inspect RUN_DIR|CHECKPOINT|ISLAND.h5");
    std::string inspectPath;
    bool inspectVerbose = false;
    inspect->add_option("path", inspectPath, kCheckpointPaths)->required();
    inspect->add_flag("-v,--verbose", inspectVerbose, "also print the config");

    // export
    auto* exportCmd = app.add_subcommand("export", "Write the best model of a checkpoint: shapevo export RUN_DIR|CHECKPOINT|ISLAND.h5 "
                                                   "--best -o FILE");
    std::string exportPath, exportOut;
    bool exportBest = false;
    exportCmd->add_option("path", exportPath, kCheckpointPaths)->required();
    exportCmd->add_flag("--best", exportBest, "the best individual over all islands (the only choice for now)")->required();
    exportCmd->add_option("-o,--output", exportOut, "output file (.obj, .ply, .glb, .vdb or .png); must not exist")->required();
    std::string exportFormat;
    exportCmd->add_option("--format", exportFormat,
                          "obj, ply, glb (the model), vdb (its voxels on a volume target's grid) or png (its silhouette "
                          "over an image target); must match the output file's extension")
        ->check(CLI::IsMember([] {
            const std::vector<std::string_view> formats = exportFormats();  // meshes and every target kind's
            return std::vector<std::string>(formats.begin(), formats.end());
        }()));

    // render
    auto* renderCmd = app.add_subcommand("render", "Draw a shaded picture of a model (PNG; on the CPU, no display needed): "
                                                   "shapevo render MODEL|RUN_DIR|CHECKPOINT -o view.png");
    std::string renderPath, renderOut, renderView = "three-quarter", renderSize = "800x600";
    renderCmd->add_option("path", renderPath,
                          "a mesh file (.obj, .ply, .stl; drawn in a neutral colour), or a run folder, checkpoint folder, or a "
                          "checkpoint's run.h5 or island-NNNN.h5 (the checkpoint's best model over all islands, in its colours)")
        ->required();
    renderCmd->add_option("-o,--output", renderOut, "PNG file to write; must not exist")->required();
    renderCmd->add_option("--view", renderView, "three-quarter (from the front right, 30 degrees up), front, side, top, or three "
                                                "(front, side and top side by side)")
        ->capture_default_str();
    renderCmd->add_option("--size", renderSize, "the size of each view, WIDTHxHEIGHT in pixels (16 to 8192 each)")->capture_default_str();

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        if (mpi.rank() == 0) app.exit(e);
        return 2;
    }
    const bool parallel = *run || *resume;
    if (parallel) installStopSignalHandlers();  // early: a signal while loading must not kill a rank
    if (mpi.size() > 1 && !parallel) {
        if (mpi.rank() == 0)
            std::cerr << "shapevo: error: only 'run' and 'resume' use several MPI ranks; start '"
                      << app.get_subcommands().front()->get_name() << "' without mpirun\n";
        return 2;
    }

    LogRouter router(std::cout, std::cerr);
    std::ostream log(&router);
    try {
        if (*run) {
            // --seed is an override like --set, after them (it wins), so the config text the run
            // stores (config.toml, checkpoints) holds the seed it ran with.
            if (*seedOpt) sets.push_back("run.seed=" + std::to_string(parseSeed(seed, "--seed", INT64_MAX)));
            RunSettings s = loadConfig(config, sets);
            if (threads >= 0) s.threads = threads;
            if (!out.empty()) s.out = out;
            if (const int used = Evaluator::usableThreads(s.threads); s.threads > used && mpi.rank() == 0)
                std::cerr << "shapevo: warning: " << (threads >= 0 ? "--threads " : "run.threads = ") << s.threads
                          << " is more than the " << used << " hardware thread(s) this process may use; using " << used << "\n";
            together(mpi, [&] { requireMemoryFits(s, loadGrammar(s.grammarPath, s.grammarAttrs), ranksOnThisMachine(), usableMemoryBytes()); });
            JobOptions o;
            o.quiet = quiet;
            runJob(mpi, s, o, log);
        } else if (*resume) {
            JobOptions o;
            o.quiet = resumeQuiet;
            if (*resumeGenOpt) o.generations = resumeGenerations;
            o.allowChangedInputs = allowChangedInputs;
            resumeJob(mpi, runDir, o, log);
        } else if (*inspect) {
            const std::string folder = resolveCheckpointPath(inspectPath);
            AttrOverrides attrs;  // the run's [grammar.attr], which its grammar was read with
            try {
                const RunMetadata meta = readRunMetadata(folder + "/run.h5");
                attrs = parseConfig(meta.configText, meta.configPath).grammarAttrs;
            } catch (const InputError&) {
                // describeCheckpoint reports what is wrong with the checkpoint itself
            }
            std::cout << describeCheckpoint(folder, inspectVerbose, attrs);
        } else if (*exportCmd) {
            requireOutputFormat(exportOut, exportFormats(), "-o", exportFormat);
            refuseExisting(exportOut);
            std::cout << exportCheckpointBest(bestOfCheckpoint(resolveCheckpointPath(exportPath)), exportFormat, exportOut) << "\n";
        } else if (*renderCmd) {
            requireOutputFormat(renderOut, std::array<std::string_view, 1>{"png"}, "-o");
            refuseExisting(renderOut);
            const std::vector<View> views = parseViews(renderView);
            const PictureSize size = parsePictureSize(renderSize);
            Mesh mesh;
            std::string what = renderPath;
            if (std::filesystem::is_directory(renderPath) || formatOfPath(renderPath) == "h5") {
                const CheckpointBest b = bestOfCheckpoint(resolveCheckpointPath(renderPath));
                Geometry geo;
                DeriveScratch scratch;
                derive(b.grammar, b.best, geo, scratch, b.settings.limits.maxPrimitives);
                mesh = meshOf(geo);
                what = "best model: " + b.from;
            } else {
                mesh = readMesh(renderPath);
            }
            writeModelPicture(mesh, views, size, renderOut);
            std::cout << "wrote " << renderOut << " (" << size.width * int(views.size()) << "x" << size.height << ", " << renderView
                      << " view" << (views.size() > 1 ? "s" : "") << " of " << mesh.triangles.size() << " triangles; " << what << ")\n";
        } else if (*sample) {
            const std::uint64_t sampleSeedValue = parseSeed(sampleSeed, "--seed", UINT64_MAX);
            const std::uint32_t count = parseCount(sampleCount, kMaxSampleCount);
            constexpr std::array<std::string_view, 4> kSampleFormats{"obj", "ply", "glb", "png"};
            const std::string sampleFormat = requireOutputFormat(sampleOut, kSampleFormats, "-o");
            const bool sheetOut = sampleFormat == "png";  // one contact sheet instead of numbered model files
            if (!sampleSize.empty() && !sheetOut)
                throw InputError("--size", "", "sizes a contact sheet's tiles: use it with -o FILE.png");
            std::optional<ContactSheet> sheet;
            if (sheetOut) sheet.emplace(int(count), sampleSize.empty() ? PictureSize{256, 256} : parsePictureSize(sampleSize));
            if (!genomeOut.empty()) requireOutputFormat(genomeOut, kGenomeFormats, "--genome");
            const Grammar g = loadGrammar(grammarPath, parseAttrOptions(sampleAttrs));
            if (minGenes > maxGenes) throw InputError("--min-genes", "", "must not exceed --max-genes");
            if (g.mandatoryGenes[g.start] > maxGenes)
                throw InputError("--max-genes", "", std::to_string(maxGenes) + " is smaller than the " +
                                                        std::to_string(g.mandatoryGenes[g.start]) + " genes every derivation of " +
                                                        grammarPath + " needs");
            for (std::uint32_t k = 1; k <= count; ++k) {
                refuseExisting(sheetOut ? sampleOut : numberedPath(sampleOut, k, count));
                if (!genomeOut.empty()) refuseExisting(numberedPath(genomeOut, k, count));
            }
            // File k is seed + k - 1, as --count 1 --seed (seed + k - 1) writes it. Every
            // derivation is drawn once before anything is written, so a size window that cannot
            // be met leaves no files behind; the second draw repeats the first exactly.
            // A recursion that ends only by chance (a rule file's recursive stochastic rule,
            // castlemaker-crl.txt §5.2) may grow without end: --max-genes stops each draw, and
            // genome.max_primitives (its default: sample has no config) each model.
            const bool mayNeverEnd = isRuleFile(grammarPath) || hasOptionalRecursion(g);
            const std::string neverEnds = "a recursive stochastic rule may never end (castlemaker-crl.txt §5.2): ";
            Geometry geo;
            DeriveScratch scratch;
            auto draw = [&](std::uint32_t k, Chromosome& c) {
                const std::uint64_t seedK = sampleSeedValue + (k - 1);  // wraps mod 2^64
                Rng rng(seedK);
                const SampleOutcome o = sampleDerivation(g, c, rng, minGenes, maxGenes, kSampleAttempts);
                if (!o.found && mayNeverEnd && o.tooLarge == o.attempts)
                    throw InputError("--max-genes", "",
                                     "all " + std::to_string(o.attempts) + " derivations of " + grammarPath + " drawn (seed " +
                                         std::to_string(seedK) + ") grew past the limit of " + std::to_string(maxGenes) +
                                         " genes and were stopped there; " + neverEnds +
                                         "lower the probabilities of the alternatives that recurse, or raise --max-genes");
                if (!o.found)
                    throw InputError("--min-genes/--max-genes", "",
                                     "no derivation of " + grammarPath + " with " + std::to_string(minGenes) + " to " +
                                         std::to_string(maxGenes) + " genes in " + std::to_string(o.attempts) + " draws (seed " +
                                         std::to_string(seedK) +
                                         (o.tooLarge ? "; " + std::to_string(o.tooLarge) + " of them grew past --max-genes" : std::string()) +
                                         "); the grammar's prob values make that size rare or impossible" +
                                         (o.tooLarge && mayNeverEnd ? " (" + neverEnds.substr(0, neverEnds.size() - 2) + ")" : std::string()) +
                                         ": widen the window");
                if (derive(g, c, geo, scratch) == DeriveStatus::Truncated)
                    throw InputError("genome.max_primitives", "",
                                     "the derivation of " + grammarPath + " drawn with seed " + std::to_string(seedK) + " (" +
                                         std::to_string(c.genes) + (c.genes == 1 ? " gene" : " genes") + ") reached the limit of " + std::to_string(kDefaultMaxPrimitives) +
                                         " primitives (the limit genome.max_primitives sets; sample uses its default) and was stopped "
                                         "there; " +
                                         (mayNeverEnd ? neverEnds + "lower the probabilities of the alternatives that recurse, or --max-genes"
                                                      : std::string("nested splits, repeats, comps and mirrors multiply what they hold: nest fewer of them")));
                return std::pair{seedK, o.attempts};
            };
            Chromosome c;
            for (std::uint32_t k = 1; k <= count; ++k) draw(k, c);
            for (std::uint32_t k = 1; k <= count; ++k) {
                const auto [seedK, attempts] = draw(k, c);
                const std::string modelPath = sheetOut ? sampleOut + " tile " + std::to_string(k) : numberedPath(sampleOut, k, count);
                if (sheetOut) sheet->draw(int(k) - 1, meshOf(geo), std::to_string(seedK));
                else writeModelFile(geo, sampleFormat, modelPath, Replace::Never);
                std::cout << "sampled " << c.genes << " genes, " << geo.primitives.size() << " primitives (seed " << seedK;
                if (attempts > 1) std::cout << ", draw " << attempts;
                std::cout << ") -> " << modelPath;
                if (!genomeOut.empty()) {
                    const std::string genomePath = numberedPath(genomeOut, k, count);
                    writeGenome(g, c, genomePath);
                    std::cout << ", " << genomePath;
                }
                std::cout << "\n";
            }
            if (sheetOut) {
                sheet->write(sampleOut);
                std::cout << "wrote " << sampleOut << " (" << count << (count == 1 ? " model, " : " models, ") << sheet->width()
                          << "x" << sheet->height() << " pixels)\n";
            }
        } else if (*target) {
            // --image: a picture through an image config's camera; otherwise a volume.
            constexpr std::array<std::string_view, 1> kImageFormats{"png"};
            requireOutputFormat(vdbOut, imageConfig.empty() ? std::span<const std::string_view>(kTargetFormats) : kImageFormats, "-o");
            refuseExisting(vdbOut);
            std::optional<RunSettings> imageSettings;
            if (!imageConfig.empty()) {
                imageSettings = loadConfig(imageConfig, {});
                if (!imageSettings->target->kind().drawMeshTarget)
                    throw InputError(imageConfig, "", "has no image target and camera ([target] image = \"FILE.png\" and a "
                                                      "[camera] section); --image draws through an image config's camera");
            }
            const Mesh mesh = readMesh(meshPath);
            for (const std::string& w : mesh.warnings) std::cerr << "shapevo: warning: " << w << "\n";
            if (imageSettings) {
                const TargetSettings& through = *imageSettings->target;
                std::cout << through.kind().drawMeshTarget(through, mesh, meshPath, imageConfig, vdbOut);
            } else {
                const MeshRepair repaired = repairForVolume(mesh, meshPath);
                std::cout << "mesh: " << describeRepair(repaired) << std::endl;
                const TargetVdbStats stats = writeTargetVdb(repaired.mesh, voxelSize, meshPath, vdbOut);
                std::cout << "inside: volume " << stats.insideVolume << " (model units^3), "
                          << groupedNumber(stats.insideVoxels) << " voxels of " << voxelSize << "\n"
                          << "wrote " << vdbOut << "\n";
            }
        } else if (*translate) {
            if (!isRuleFile(translatePath)) throw InputError(translatePath, "", "not a CastleMaker rule file (expected a .rule file)");
            std::cout << translateRuleFile(translatePath, parseAttrOptions(translateAttrs));
        } else if (*evaluate) {
            const RunSettings s = loadConfig(evalConfig, evalSets);
            const Grammar g = loadGrammar(s.grammarPath, s.grammarAttrs);
            const Chromosome c = readGenome(g, s.limits, evalGenome);
            std::cout << Scene::load(s, g)->evaluate(c).text << "\n";
        }
    } catch (const SilentFailure&) {
        return 2;  // another rank's input was bad; that rank has said why
    } catch (const RunFailure& e) {  // a fault every rank saw (a checkpoint that cannot be written)
        if (!e.message.empty()) std::cerr << "shapevo: error: " << e.message << "\n";
        return 1;
    } catch (const InputError& e) {
        log.flush();
        std::cerr << "shapevo: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        log.flush();
        std::cerr << "shapevo: failed" << (mpi.size() > 1 ? " on rank " + std::to_string(mpi.rank()) : "") << ": "
                  << e.what() << "\n";
        if (mpi.size() > 1) mpi.abort(1);  // the other ranks would wait for this one forever
        return 1;
    }
    return 0;
}

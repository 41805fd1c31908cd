// shapevo command line: run, sample, target, evaluate. Bad input (InputError, bad arguments)
// prints one message and exits with code 2; other failures exit with code 1.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/parser.hpp"
#include "io/config_file.hpp"
#include "io/genome_file.hpp"
#include "io/input_error.hpp"
#include "io/mesh_reader.hpp"
#include "io/model_writer.hpp"
#include "io/vdb_target_file.hpp"
#include "run/evolve.hpp"
#include "score/volume_scorer.hpp"

namespace {

using namespace shapevo;

void writeModel(const Geometry& geo, const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".obj") writeObj(meshOf(geo), path);
    else if (ext == ".ply") writePly(meshOf(geo), path);
    else throw InputError(path, "", "unknown model format '" + ext + "' (expected .obj or .ply)");
}

void refuseExisting(const std::string& path) {
    if (std::filesystem::exists(path))
        throw InputError(path, "", "already exists; shapevo does not overwrite files (remove it or choose another -o)");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"shapevo: evolve procedural models (grammars) until they fill a target volume.\n"
                 "Docs: README.md; grammar language: grammars/README.md"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "shapevo 0.1.0");

    // run
    auto* run = app.add_subcommand("run", "Evolve a model: shapevo run CONFIG.toml");
    std::string config;
    std::uint64_t seed = 0;
    std::vector<std::string> sets;
    std::string out;
    bool quiet = false;
    int threads = -1;
    run->add_option("config", config, "TOML config (see configs/)")->required();
    auto* seedOpt = run->add_option("--seed", seed, "random seed (overrides run.seed)");
    run->add_option("--set", sets, "override a config value, e.g. --set ga.population=50 (repeatable)");
    run->add_option("--out", out, "output folder; must not exist (default runs/<name>, runs/<name>-2, ...)");
    run->add_option("--threads", threads, "threads (overrides run.threads; 0 = all cores)");
    run->add_flag("-q,--quiet", quiet, "no per-generation progress lines");

    // sample
    auto* sample = app.add_subcommand("sample", "Write one random derivation of a grammar (no evolution)");
    std::string grammarPath, sampleOut, genomeOut;
    std::uint64_t sampleSeed = 1;
    std::uint32_t minGenes = 1, maxGenes = 100;
    sample->add_option("grammar", grammarPath, "grammar file")->required();
    sample->add_option("--seed", sampleSeed, "random seed")->capture_default_str();
    sample->add_option("--min-genes", minGenes, "grow to at least this many genes (if the grammar allows)")->capture_default_str();
    sample->add_option("--max-genes", maxGenes, "never more genes than this")->capture_default_str();
    sample->add_option("-o,--output", sampleOut, "model file (.obj or .ply)")->required();
    sample->add_option("--genome", genomeOut, "also save the chromosome (.genome) for shapevo evaluate");

    // target
    auto* target = app.add_subcommand("target", "Make a volume target: closed mesh (OBJ/PLY/STL) -> OpenVDB level set");
    std::string meshPath, vdbOut;
    double voxelSize = 0.1;
    target->add_option("mesh", meshPath, "closed triangle mesh")->required();
    target->add_option("-o,--output", vdbOut, "output .vdb (must not exist)")->required();
    target->add_option("--voxel-size", voxelSize, "voxel edge length in model units")->capture_default_str();

    // evaluate
    auto* evaluate = app.add_subcommand("evaluate", "Score a saved chromosome against a config's target");
    std::string evalConfig, evalGenome;
    evaluate->add_option("config", evalConfig, "TOML config")->required();
    evaluate->add_option("genome", evalGenome, ".genome file (best.genome of a run, or from sample --genome)")->required();

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    }

    try {
        if (*run) {
            RunSettings s = loadConfig(config, sets);
            if (*seedOpt) s.seed = seed;
            if (threads >= 0) s.threads = threads;
            if (!out.empty()) s.out = out;
            evolve(s, EvolveOptions{quiet}, std::cout);
        } else if (*sample) {
            const Grammar g = loadGrammar(grammarPath);
            refuseExisting(sampleOut);
            if (!genomeOut.empty()) refuseExisting(genomeOut);
            Rng rng(sampleSeed);
            const GenomeLimits limits{maxGenes};
            Chromosome c;
            while (c.genes < minGenes && grow(g, c, rng, limits)) {
            }
            Geometry geo;
            DeriveScratch scratch;
            derive(g, c, geo, scratch);
            writeModel(geo, sampleOut);
            if (!genomeOut.empty()) writeGenome(g, c, genomeOut);
            std::cout << "sampled " << c.genes << " genes, " << geo.primitives.size() << " primitives -> " << sampleOut << "\n";
        } else if (*target) {
            const Mesh mesh = readMesh(meshPath);
            requireClosed(mesh, meshPath);
            writeTargetVdb(mesh, voxelSize, meshPath, vdbOut);
            std::cout << "wrote " << vdbOut << " (" << mesh.triangles.size() << " triangles, voxel size " << voxelSize
                      << ")\n";
        } else if (*evaluate) {
            const RunSettings s = loadConfig(evalConfig);
            const Grammar g = loadGrammar(s.grammarPath);
            const Chromosome c = readGenome(g, s.limits, evalGenome);
            const VolumeTarget t = loadVolumeTarget(s.targets, s.grid ? &*s.grid : nullptr);
            const VolumeScorer scorer(g, t, s.fitness);
            auto ws = scorer.makeWorkspace();
            VoxelCounts counts;
            const double f = scorer.fitness(c, *ws, &counts);
            std::printf("fitness %.6f  voxel_iou %.4f  genes %u  primitives %zu  inside %llu  occupied %llu  "
                        "overlap %llu  outside %llu  target %llu\n",
                        f, voxelIoU(counts, t.fillCount), c.genes, ws->geometry.primitives.size(),
                        (unsigned long long)counts.inside, (unsigned long long)counts.occupied,
                        (unsigned long long)counts.overlap, (unsigned long long)counts.outside,
                        (unsigned long long)t.fillCount);
        }
    } catch (const InputError& e) {
        std::cerr << "shapevo: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "shapevo: failed: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

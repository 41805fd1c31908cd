// evolve: load, evolve with progress lines, write the run folder.
#include "run/evolve.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>

#include "grammar/parser.hpp"
#include "io/genome_file.hpp"
#include "io/model_writer.hpp"
#include "io/run_report.hpp"
#include "run/output_folder.hpp"
#include "search/genetic_algorithm.hpp"

namespace shapevo {

namespace {
std::string humanSeconds(double s) {
    char b[32];
    if (s < 100) std::snprintf(b, sizeof b, "%.2fs", s);
    else if (s < 6000) std::snprintf(b, sizeof b, "%dm%02ds", int(s) / 60, int(s) % 60);
    else std::snprintf(b, sizeof b, "%dh%02dm", int(s) / 3600, int(s) / 60 % 60);
    return b;
}
void writeFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}
}  // namespace

EvolveResult evolve(const RunSettings& s, const EvolveOptions& options, std::ostream& log) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    // Read every input before creating anything, so bad input leaves no trace.
    const Grammar grammar = loadGrammar(s.grammarPath);
    const VolumeTarget target = loadVolumeTarget(s.targets, s.grid ? &*s.grid : nullptr);
    const std::string folder = claimOutputFolder(s.out, s.name);
    namespace fs = std::filesystem;
    writeFile(folder + "/config.toml", s.configText);
    writeFile(folder + "/" + fs::path(s.grammarPath).filename().string(), grammar.source);

    const VolumeScorer scorer(grammar, target, s.fitness);
    Evaluator evaluator(scorer, s.threads);
    GeneticAlgorithm ga(grammar, s.ga, s.limits, s.seed);
    std::vector<GenerationStats> curve;
    curve.reserve(s.ga.generations);
    const auto gaStart = Clock::now();
    auto record = [&] {
        GenerationStats st = ga.stats();
        st.seconds = std::chrono::duration<double>(Clock::now() - gaStart).count();
        curve.push_back(st);
        if (options.quiet) return;
        const double rate = st.seconds > 0 ? double(st.evaluations) / st.seconds : 0;
        const double eta = st.generation > 0 ? st.seconds / st.generation * (s.ga.generations - st.generation) : 0;
        char line[200];
        std::snprintf(line, sizeof line, "gen %*u/%u  best %.5f  mean %.5f  %.0f evals/s  elapsed %s  ETA %s\n",
                      int(std::to_string(s.ga.generations).size()), st.generation, s.ga.generations, st.best, st.mean,
                      rate, humanSeconds(st.seconds).c_str(), humanSeconds(eta).c_str());
        log << line << std::flush;
    };
    if (!options.quiet)
        log << "shapevo run " << s.name << ": grammar " << s.grammarPath << ", target " << s.targets.front().path << " ("
            << target.grid.nx << "x" << target.grid.ny << "x" << target.grid.nz << " voxels, " << target.fillCount
            << " to fill), " << evaluator.threads() << " thread(s), seed " << s.seed << ", output " << folder << "\n";
    ga.initialize(evaluator);
    record();
    while (ga.generation() < s.ga.generations) {
        ga.step(evaluator);
        record();
    }

    const Population& pop = ga.population();
    const std::size_t best = pop.best();
    const Chromosome& champion = pop.individuals[best];
    auto ws = scorer.makeWorkspace();
    VoxelCounts counts;
    scorer.fitness(champion, *ws, &counts);
    const Mesh mesh = meshOf(ws->geometry);
    writeObj(mesh, folder + "/best.obj");
    writePly(mesh, folder + "/best.ply");
    writeGenome(grammar, champion, folder + "/best.genome");
    writeCurveCsv(curve, folder + "/curve.csv");

    EvolveResult r;
    r.folder = folder;
    r.bestFitness = pop.fitness[best];
    r.voxelIoU = voxelIoU(counts, target.fillCount);
    r.evaluations = ga.evaluations();
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    RunSummary sum;
    sum.name = s.name;
    sum.config = s.configPath;
    sum.grammar = s.grammarPath;
    sum.seed = s.seed;
    sum.generations = ga.generation();
    sum.evaluations = r.evaluations;
    sum.wallSeconds = r.wallSeconds;
    sum.bestFitness = r.bestFitness;
    sum.voxelIoU = r.voxelIoU;
    sum.bestGenes = champion.genes;
    sum.bestPrimitives = ws->geometry.primitives.size();
    sum.targetHash = target.hash;
    sum.threads = evaluator.threads();
    writeSummaryJson(sum, folder + "/summary.json");
    if (!options.quiet) {
        char line[200];
        std::snprintf(line, sizeof line, "done: best fitness %.5f, voxel IoU %.4f, %llu evaluations in %s -> %s/\n",
                      r.bestFitness, r.voxelIoU, static_cast<unsigned long long>(r.evaluations),
                      humanSeconds(r.wallSeconds).c_str(), folder.c_str());
        log << line;
    }
    return r;
}

}  // namespace shapevo

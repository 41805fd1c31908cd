// The end of a run: gather the champion and the totals, write the outputs (see the header).
#include "run/run_outputs.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <iostream>
#include <ostream>
#include <vector>

#include "base/side_by_side.hpp"
#include "genome/genome_file.hpp"
#include "geometry/derive.hpp"
#include "mesh/glb_writer.hpp"
#include "report/curve_plot.hpp"
#include "report/model_writer.hpp"
#include "report/render/model_picture.hpp"
#include "report/run_report.hpp"
#include "run/progress_line.hpp"

namespace shapevo {

Champion gatherChampion(const MpiSession& mpi, const Population& population) {
    const std::size_t bestIndex = population.best();
    const auto [bestFitness, bestRank] = mpi.maxLoc(population.fitness[bestIndex]);
    std::vector<std::uint32_t> packed;
    if (mpi.rank() == bestRank) {
        const Chromosome& c = population.individuals[bestIndex];
        packed.push_back(c.genes);
        packed.insert(packed.end(), c.words.begin(), c.words.end());
    }
    packed = mpi.transfer(packed, bestRank, 0);
    Champion champion;
    champion.fitness = bestFitness;
    if (mpi.rank() == 0) {
        champion.chromosome.genes = packed.front();
        champion.chromosome.words.assign(packed.begin() + 1, packed.end());
    }
    return champion;
}

RunTotals gatherTotals(const MpiSession& mpi, const IslandTotals& own, const LoopClock& clock) {
    std::vector<double> totals{double(own.evaluations), double(own.anomalies.nonFinite), double(own.anomalies.truncated)};
    mpi.sum(totals);
    // waiting over the wall time: all of it, and the part outside checkpoints (async mode's promise)
    const double ownWait = clock.waitShare(),
                 ownWaitOutside = ownWait - own.checkpointWaitedSeconds / std::max(1e-9, clock.sessionSeconds());
    std::vector<double> overhead{own.migrationSeconds,
                                 own.checkpointSeconds,
                                 own.iouSeconds,
                                 ownWait,
                                 ownWaitOutside,
                                 double(own.cacheBytes),
                                 double(own.modelBytes),
                                 double(own.peakResidentBytes)};
    mpi.max(overhead);  // the slowest rank's share is what the run waited for; the largest rank's memory
    std::vector<double> waitSum{ownWait, ownWaitOutside};
    mpi.sum(waitSum);
    RunTotals t;
    t.evaluations = std::uint64_t(totals[0]);
    t.nonFiniteModels = std::uint64_t(totals[1]);
    t.truncatedModels = std::uint64_t(totals[2]);
    t.migrationSeconds = overhead[0];
    t.checkpointSeconds = overhead[1];
    t.iouSeconds = overhead[2];
    t.waitShareMax = overhead[3];
    t.waitShareOutsideCheckpointsMax = overhead[4];
    t.cacheBytes = std::uint64_t(overhead[5]);
    t.modelBytes = std::uint64_t(overhead[6]);
    t.maxRssBytes = std::uint64_t(overhead[7]);
    t.waitShareSum = waitSum[0];
    t.waitShareOutsideCheckpointsSum = waitSum[1];
    return t;
}

namespace {

/// The best model's files (its family's: best.png, best.obj, best.ply, best.glb for a tree;
/// best.svg, best.png for a drawing; and best.genome), the curves (curve.csv, curve.svg,
/// curve.png) and the target kind's files (Scene::reportBest: best.vdb, best-overlay.png), written
/// side by side (base/side_by_side.hpp): each waits for the disk, and the pictures' drawing and
/// compressing take most of the rest; what must come last (a textured OBJ) comes after. Fills the
/// summary's primitive count and IoU.
void writeModelAndCurves(const RunEnd& end, RunSummary& sum) {
    const std::unique_ptr<BestModelFiles> model = end.model.bestFiles(end.champion);
    sum.bestPrimitives = model->size();
    const std::string& folder = end.folder;
    CurvePlotLabels plot;
    plot.title = (end.s.name.empty() ? std::string("shapevo run") : end.s.name) + ": " + end.scene.description();
    plot.iouName = end.scene.kind().iouName;
    const std::vector<GenerationStats>& curve = end.meta.curve;
    std::vector<std::function<void()>> jobs{
        [&] { writeGenome(end.model.family(), end.champion, folder + "/best.genome"); },
        [&] { writeCurveCsv(curve, folder + "/curve.csv"); },
        [&] { writeCurveSvg(curve, plot, folder + "/curve.svg"); },
        [&] { writeCurvePng(curve, plot, folder + "/curve.png"); },
        [&] { end.scene.reportBest(end.champion, folder, sum); },
    };
    model->addJobs(folder, jobs);
    runSideBySide(jobs);
    model->afterJobs(folder);
}

/// The scorer's warnings (stderr): evaluations that got the worst fitness or were truncated.
void warnAboutModels(const RunSummary& sum, const GenomeLimits& limits) {
    if (sum.nonFiniteModels > 0)
        std::cerr << "shapevo: warning: " << sum.nonFiniteModels << " evaluation(s) made a primitive with a non-finite "
                  << "coordinate or one beyond 1e6 and got the worst fitness (" << Scorer::kWorstFitness << ")\n";
    if (sum.truncatedModels > 0)
        std::cerr << "shapevo: warning: " << sum.truncatedModels << " evaluation(s) reached genome.max_primitives = "
                  << limits.maxPrimitives << " and were scored on their first " << limits.maxPrimitives
                  << " primitives\n";
}

/// "done ...: best fitness ..., voxel IoU ..." or "stopped on SIGTERM after generation ...".
void printClosingLine(const RunEnd& end, const JobResult& result, std::ostream& log) {
    const std::string& stopReason = end.stop.why;
    const std::string& folder = end.folder;
    char line[300];
    if (!end.stop.bySignal)
        std::snprintf(line, sizeof line, "done%s%s: best fitness %.5f, %s %.4f, %llu evaluations in %s -> %s/\n",
                      stopReason == "done" ? "" : " after ", stopReason == "done" ? "" : stopReason.c_str(),
                      result.bestFitness, std::string(end.scene.kind().iouName).c_str(), result.iou, static_cast<unsigned long long>(result.evaluations),
                      humanSeconds(result.wallSeconds).c_str(), folder.c_str());
    else
        std::snprintf(line, sizeof line,
                      "stopped on %s after generation %u: checkpoint written; continue with: shapevo resume %s\n",
                      stopReason.c_str(), end.generation, folder.c_str());
    log << line;
}

}  // namespace

void writeRunOutputs(const RunEnd& end, JobResult& result, std::ostream& log) {
    const RunSettings& s = end.s;
    const RunMetadata& meta = end.meta;
    const RunTotals& t = end.totals;
    RunSummary sum;
    writeModelAndCurves(end, sum);
    sum.name = s.name;
    sum.config = meta.configPath;
    sum.grammar = meta.grammarPath;
    sum.seed = s.seed;
    sum.generations = end.generation;
    sum.evaluations = result.evaluations;
    sum.wallSeconds = result.wallSeconds;
    sum.bestFitness = result.bestFitness;
    sum.bestGenes = end.champion.genes;
    sum.targetHash = end.scene.hash();
    result.iou = sum.iou;
    sum.threads = end.threads;
    sum.islands = end.ranks;
    sum.changedInputs = end.options.changedInputs;
    sum.nonFiniteModels = t.nonFiniteModels;
    sum.truncatedModels = t.truncatedModels;
    warnAboutModels(sum, s.limits);
    sum.migrationSeconds = t.migrationSeconds;
    sum.checkpointSeconds = t.checkpointSeconds;
    sum.iouSeconds = t.iouSeconds;
    sum.waitShareMax = t.waitShareMax;
    sum.waitShareMean = t.waitShareSum / end.islands;
    sum.waitShareOutsideCheckpointsMax = t.waitShareOutsideCheckpointsMax;
    sum.waitShareOutsideCheckpointsMean = t.waitShareOutsideCheckpointsSum / end.islands;
    sum.cacheBytes = t.cacheBytes;
    sum.modelBytes = t.modelBytes;
    sum.maxRssBytes = t.maxRssBytes;
    sum.population = end.population;
    writeSummaryJson(sum, end.folder + "/summary.json");
    if (!end.options.quiet || result.stoppedBySignal) printClosingLine(end, result, log);
}

}  // namespace shapevo

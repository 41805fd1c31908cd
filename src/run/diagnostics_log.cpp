// DiagnosticsLog: a row per generation, flushed as it is written (a run stopped any way keeps every
// finished row).
#include "run/diagnostics_log.hpp"

#include <string>

#include "base/input_error.hpp"

namespace shapevo {

DiagnosticsLog::DiagnosticsLog(const std::string& path, const GenomeFamily& family) : path_(path), family_(family) {
    file_ = std::fopen(path.c_str(), "a");
    if (!file_) throw InputError(path, "", "cannot write the diagnostics file");
    if (std::ftell(file_) == 0) {
        std::fputs("generation,seconds,evaluations,best,mean,distinct_genomes,distinct_structures,mean_genes,max_genes,"
                   "us_per_evaluation,distinct_parents",
                   file_);
        for (const char* op : OperatorOutcomes::kOpNames)
            for (const char* result : OperatorOutcomes::kResultNames) std::fprintf(file_, ",%s_%s", op, result);
        std::fputs("\n", file_);
    }
}

DiagnosticsLog::~DiagnosticsLog() {
    if (file_) std::fclose(file_);
}

void DiagnosticsLog::write(const SearchMethod& method, double seconds) {
    const GenerationStats stats = method.stats();
    const Diversity d = measureDiversity(family_, method.population(), scratch_);
    const std::uint64_t evaluations = method.evaluations() - lastEvaluations_;
    const double perEvaluation =
        lastSeconds_ >= 0 && evaluations > 0 ? (seconds - lastSeconds_) * 1e6 / double(evaluations) : 0.0;
    OperatorOutcomes now;
    if (const OperatorOutcomes* o = method.operatorOutcomes()) now = *o;
    const std::uint64_t picks = now.parentsPicked - last_.parentsPicked;
    const double parents = picks ? double(now.distinctParents - last_.distinctParents) / double(picks) : 0.0;
    // distinct_structures stays empty for a family without a tree grammar (not counted)
    const std::string structures = d.structuresCounted ? std::to_string(d.distinctStructures) : "";
    std::fprintf(file_, "%u,%.6f,%llu,%.17g,%.17g,%zu,%s,%.3f,%u,%.3f,%.4f", method.generation(), seconds,
                 static_cast<unsigned long long>(method.evaluations()), stats.best, stats.mean, d.distinctGenomes,
                 structures.c_str(), d.meanGenes, d.maxGenes, perEvaluation, parents);
    for (int op = 0; op < OperatorOutcomes::kOps; ++op)
        for (int r = 0; r < OperatorOutcomes::kResults; ++r)
            std::fprintf(file_, ",%llu", static_cast<unsigned long long>(now.children[op][r] - last_.children[op][r]));
    std::fputs("\n", file_);
    std::fflush(file_);
    last_ = now;
    lastEvaluations_ = method.evaluations();
    lastSeconds_ = seconds;
}

}  // namespace shapevo

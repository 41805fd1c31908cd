// DiagnosticsLog: with search.diagnostics = true, rank 0 writes diagnostics.csv into the run
// folder, one row per generation of its own island: what explains progress or a stall
// (docs/search-diagnosis.md). Columns:
//   generation, seconds, evaluations, best, mean          as in curve.csv (this island)
//   distinct_genomes, distinct_structures                 population diversity, counted exactly
//                                                         (search/population_diversity.hpp; structures
//                                                         empty for a family without a tree grammar)
//   mean_genes, max_genes                                 chromosome lengths (bloat)
//   us_per_evaluation                                     wall time of the generation / its evaluations
//   distinct_parents                                      share of selections that picked a new individual
//   <op>_better, <op>_equal, <op>_worse                   this generation's children of each operator
//                                                         (grow, cut, alter, crossover, copy) against their
//                                                         parent (crossover: the better parent)
// Diagnostics read the population only: a run with them is the same run (same models, curve,
// checkpoints). A resumed run appends to the file.
#pragma once
#include <cstdio>
#include <string>

#include "search/operator_outcomes.hpp"
#include "search/population_diversity.hpp"
#include "search/search_method.hpp"

namespace shapevo {

class DiagnosticsLog {
public:
    /// Opens `path` for appending (the header only into a new or empty file). @throw InputError
    /// if it cannot be written.
    DiagnosticsLog(const std::string& path, const GenomeFamily& family);
    ~DiagnosticsLog();
    DiagnosticsLog(const DiagnosticsLog&) = delete;
    DiagnosticsLog& operator=(const DiagnosticsLog&) = delete;

    /// One row for the generation `method` has just finished, `seconds` into the run.
    void write(const SearchMethod& method, double seconds);

private:
    std::string path_;
    const GenomeFamily& family_;
    std::FILE* file_ = nullptr;
    DiversityScratch scratch_;
    OperatorOutcomes last_;
    std::uint64_t lastEvaluations_ = 0;
    double lastSeconds_ = -1;
};

}  // namespace shapevo

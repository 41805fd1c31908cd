// HybridSearch ("hybrid"): the GA of ShapeGenetics made harder to stall, from what
// docs/search-diagnosis.md measured (late progress comes from small local changes, crossover
// rarely improves, one short-model population can sit still for seconds).
//
// - Islands in one process: the population is split into `islands` contiguous ranges of slots;
//   each breeds only from its own members (elitism, tournament and roulette within the range),
//   and every `migration_interval` generations each island's best replaces the worst of the next
//   island around a ring. With MPI ranks this runs inside every rank's island.
// - Mutation over crossover: a pair is mutated with probability `mutation` (the paper: 0.3); a
//   mutation is a regrow (GenomeOperators::regrow; the tree family: RJMCMC's jump, a
//   non-terminal's subtree cut and grown anew, genome/regrow.hpp) with probability `regrow`, else
//   grow, cut or alter by [ga]'s weights.
// - Elite refinement: each generation an island of m members makes refine x m local moves (a
//   regrow with probability `refine_jump`, else on odd islands a nudge (genome/nudge.hpp: one
//   parameter moved a small step) with probability `refine_nudge`, else an alter) dealt to its
//   elites round robin, best first; each elite is replaced by the best of its moves if that is
//   not worse — greedy chains on the best models.
// - Restarts: every `restart_interval` generations the island whose best is lowest starts again
//   from random growth (a basin none of the islands has found may be where the target is).
// - A scout (`scout_interval` > 0, 3 or more islands): the last island neither sends nor receives
//   migrants and is never the restarted worst island, so that a basin it finds can mature
//   before the others' best models reach it; every `scout_interval` generations, if its best is
//   higher than the lowest best of the other islands, its members replace that island's (best
//   first), and it starts again from random growth. (A restart of the worst island is met by a
//   migrant within `migration_interval` generations: the island falls back into the basin that
//   every island already holds.)
//
// Promises, as for every method (search_method.hpp): the state is the population, the Rng, the
// generation and the evaluation count (island ranges are a function of the population size; the
// migration, restart and scout schedules of the generation), so checkpoints resume exactly; all
// children and refine proposals of a generation are evaluated in one batch, so the thread count
// changes nothing; every random draw comes from rng() in a fixed order. Any model family: every
// genome is made and changed by the family's operators (genome/genome_family.hpp).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "genome/genome_family.hpp"
#include "search/evaluation_batch.hpp"
#include "search/population_settings.hpp"
#include "search/search_method.hpp"
#include "search/selection.hpp"

namespace shapevo {

class HybridSearch final : public SearchMethod {
public:
    /// Breeds `family`'s genomes with its operators within `limits`.
    HybridSearch(const GenomeFamily& family, const HybridSettings& settings, const PopulationSettings& population,
                 const GaSettings& ga, const GenomeLimits& limits, std::uint64_t seed);

    /// Generation 1: grow and evaluate the initial population (as the GA).
    void initialize(Evaluator& evaluator) override;
    /// Breed every island, refine the elites, evaluate all in one batch, migrate on schedule.
    void step(Evaluator& evaluator) override;
    const OperatorOutcomes* operatorOutcomes() const override { return &outcomes_; }

    /// First slot of island k (k = islands() gives the population size): islands differ in size
    /// by at most one, the larger first.
    std::size_t islandBegin(std::size_t k) const;
    std::size_t islands() const { return islands_; }
    /// Elites island k keeps (the config's elitism scaled to the island, at least 1).
    std::size_t islandElites(std::size_t k) const;
    /// Local moves of island k's elites per generation: refine x its size, rounded.
    std::size_t refineMoves(std::size_t k) const;
    /// Migrants from other ranks land in the main islands only: a scout evolves alone.
    std::size_t migrantSlots() const override { return islandBegin(mainIslands()); }

private:
    void restored() override;
    void resize(std::size_t n);
    OperatorOutcomes::Op mutate(Chromosome& c);
    /// y = a local move of x (regrow, nudge or alter); false if none applies.
    bool localMove(const Chromosome& x, Chromosome& y, double nudgeShare);
    void breedIsland(std::size_t k);
    void migrate();
    void restartWorstIsland(Evaluator& evaluator);
    /// Regrow island k from random growth and evaluate it.
    void restartIsland(std::size_t k, Evaluator& evaluator);
    /// The scout's turn: adopt it into the worst other island if it is better, then restart it.
    void scoutTurn(Evaluator& evaluator);
    /// Whether the last island is a scout (scout_interval > 0 and at least 3 islands).
    bool hasScout() const { return settings_.scoutInterval > 0 && islands_ >= 3; }
    /// The islands that migrate and may be restarted as the worst: all but a scout.
    std::size_t mainIslands() const { return hasScout() ? islands_ - 1 : islands_; }
    /// The slot of island k's best (the migration policy's emigrant: the lowest slot among equals).
    std::size_t bestSlot(std::size_t k) const;
    /// The main island whose best is lowest (the last among equals).
    std::size_t worstMainIsland() const;

    std::unique_ptr<GenomeOperators> ops_;
    HybridSettings settings_;
    PopulationSettings population_;
    GaSettings ga_;
    std::size_t islands_ = 1;
    Population next_;
    Chromosome scratchChild_;  ///< second child of an odd last pair, discarded
    Chromosome scratchRegrow_; ///< a regrow mutation's result before it is swapped in
    std::vector<std::size_t> order_;
    RouletteWheel wheel_;
    EvaluationBatch batch_;
    // refine proposals of this generation: the chromosome, the next_ slot of the elite it came
    // from, the elite's fitness, its operator
    std::vector<Chromosome> proposals_;
    struct Refinement {
        std::size_t slot = 0, batchIndex = 0;
        double parentFitness = 0;
    };
    std::vector<Refinement> refinements_;
    std::vector<std::int64_t> chosen_;          ///< per elite slot: its best refinement (-1: none)
    std::vector<std::size_t> childBatchStart_;  ///< per island: its first child's batch index
    std::vector<std::size_t> migrationSlots_;   ///< per island: best slot, then worst slot
    std::vector<OperatorOutcomes::Op> childOp_;
    std::vector<double> parentFitness_;
    std::vector<std::uint8_t> picked_;
    OperatorOutcomes outcomes_;
};

}  // namespace shapevo

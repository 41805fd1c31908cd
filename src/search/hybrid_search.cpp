// HybridSearch: islands bred in slot order, refine proposals after each island's children, one
// evaluation batch per generation, then greedy acceptance of refinements and the migration ring.
#include "search/hybrid_search.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "search/migration_policy.hpp"
#include "search/pair_breeding.hpp"

namespace shapevo {

HybridSearch::HybridSearch(const GenomeFamily& family, const HybridSettings& settings,
                           const PopulationSettings& population, const GaSettings& ga, const GenomeLimits& limits,
                           std::uint64_t seed)
    : SearchMethod(seed), ops_(family.makeOperators(limits)), settings_(settings), population_(population), ga_(ga) {
    resize(population.population);
}

void HybridSearch::resize(std::size_t n) {
    islands_ = std::max<std::size_t>(1, std::min<std::size_t>(settings_.islands, n / 2));
    pop_.individuals.resize(n);
    pop_.fitness.resize(n, 0.0);
    next_.individuals.resize(n);
    next_.fitness.resize(n);
    order_.resize(n);
    childOp_.resize(n + 1);
    parentFitness_.resize(n + 1);
    picked_.resize(n);
    std::size_t moves = 0;
    for (std::size_t k = 0; k < islands_; ++k) moves += refineMoves(k);
    proposals_.resize(moves);
    refinements_.reserve(moves);
    chosen_.resize(n);
    childBatchStart_.resize(islands_);
    migrationSlots_.resize(2 * islands_);
}

void HybridSearch::restored() { resize(pop_.size()); }

std::size_t HybridSearch::islandBegin(std::size_t k) const {
    const std::size_t n = pop_.size(), base = n / islands_, extra = n % islands_;
    return k * base + std::min(k, extra);
}

std::size_t HybridSearch::refineMoves(std::size_t k) const {
    return std::size_t(std::llround(settings_.refine * double(islandBegin(k + 1) - islandBegin(k))));
}

std::size_t HybridSearch::islandElites(std::size_t k) const {
    const std::size_t m = islandBegin(k + 1) - islandBegin(k);
    const double scaled = std::round(double(ga_.elitism) * double(m) / double(pop_.size()));
    return std::clamp<std::size_t>(std::size_t(scaled), 1, m - 1);
}

void HybridSearch::initialize(Evaluator& evaluator) {
    startFromRandomGrowth(*ops_, population_.initialGenesMin, population_.initialGenesMax, evaluator);
}

bool HybridSearch::localMove(const Chromosome& x, Chromosome& y, double nudgeShare) {
    if (rng_.uniform() < settings_.refineJump) {
        // A regrow that drew (x has a point to regrow below) is the move, even if it failed (past
        // max_genes); one that did not draw (no such point) falls back to a nudge or an alter.
        const auto before = rng_.state();
        if (ops_->regrow(x, y, rng_)) return true;
        if (rng_.state() != before) return false;
    }
    y.copyFrom(x);
    if (rng_.uniform() < nudgeShare) return ops_->nudge(y, rng_);
    return ops_->alter(y, rng_);
}

OperatorOutcomes::Op HybridSearch::mutate(Chromosome& c) {
    if (rng_.uniform() < settings_.regrow && ops_->regrow(c, scratchRegrow_, rng_)) {
        std::swap(c, scratchRegrow_);
        return OperatorOutcomes::Regrow;
    }
    return mutateByWeight(*ops_, c, rng_, ga_);
}

void HybridSearch::breedIsland(std::size_t k) {
    const std::size_t b = islandBegin(k), e = islandBegin(k + 1), m = e - b, elite = islandElites(k);
    const std::span<const double> fitness(pop_.fitness.data() + b, m);
    std::size_t* order = order_.data() + b;
    for (std::size_t i = 0; i < m; ++i) order[i] = b + i;
    std::sort(order, order + m, [&](std::size_t x, std::size_t y) {
        return pop_.fitness[x] > pop_.fitness[y] || (pop_.fitness[x] == pop_.fitness[y] && x < y);
    });
    for (std::size_t j = 0; j < elite; ++j) {
        next_.individuals[b + j] = pop_.individuals[order[j]];
        next_.fitness[b + j] = pop_.fitness[order[j]];
    }
    wheel_.prepare(fitness);
    for (std::size_t i = b + elite; i < e; i += 2) {
        const std::size_t p1 = b + tournamentSelect(fitness, ga_.tournament, rng_);
        const std::size_t p2 = b + wheel_.select(rng_);
        picked_[p1] = picked_[p2] = 1;
        const bool pair = i + 1 < e;
        Chromosome& c1 = next_.individuals[i];
        Chromosome& c2 = pair ? next_.individuals[i + 1] : scratchChild_;
        const BredPair bred = breedPair(*ops_, pop_, p1, p2, c1, c2, pair, settings_.mutation, ga_.crossoverRetries, rng_,
                                        [&](Chromosome& c) { return mutate(c); });
        childOp_[i] = bred.op1;
        childOp_[i + 1] = bred.op2;
        parentFitness_[i] = bred.parent1;
        parentFitness_[i + 1] = bred.parent2;
        outcomes_.parentsPicked += 2;
    }
    childBatchStart_[k] = batch_.size();
    for (std::size_t i = b + elite; i < e; ++i) batch_.add(next_.individuals[i]);
    // Refinement: refine * m local moves, dealt to the elites (already in next_[b, b + elite),
    // best first) round robin; each elite keeps the best of its moves if that is not worse.
    const std::size_t moves = refineMoves(k);
    const double nudgeShare = k % 2 == 1 ? settings_.refineNudge : 0.0;  // even islands alter, odd ones nudge
    for (std::size_t r = 0; r < moves; ++r) {
        const std::size_t j = r % elite;
        Chromosome& y = proposals_[refinements_.size()];
        if (!localMove(next_.individuals[b + j], y, nudgeShare)) continue;
        refinements_.push_back({b + j, batch_.add(y), next_.fitness[b + j]});
    }
}

void HybridSearch::step(Evaluator& evaluator) {
    batch_.clear();
    refinements_.clear();
    std::fill(picked_.begin(), picked_.end(), 0);
    for (std::size_t k = 0; k < islands_; ++k) breedIsland(k);
    for (std::uint8_t p : picked_) outcomes_.distinctParents += p;
    evaluations_ += batch_.evaluate(evaluator);
    for (std::size_t k = 0; k < islands_; ++k) {
        const std::size_t first = islandBegin(k) + islandElites(k);
        for (std::size_t i = first; i < islandBegin(k + 1); ++i) {
            next_.fitness[i] = batch_.fitness(childBatchStart_[k] + (i - first));
            outcomes_.count(childOp_[i], next_.fitness[i], parentFitness_[i]);
        }
    }
    // Per elite, the best of its moves (the first among equals) replaces it if not worse.
    for (const Refinement& ref : refinements_) chosen_[ref.slot] = -1;
    for (std::size_t r = 0; r < refinements_.size(); ++r) {
        const Refinement& ref = refinements_[r];
        const double f = batch_.fitness(ref.batchIndex);
        outcomes_.count(OperatorOutcomes::Refine, f, ref.parentFitness);
        std::int64_t& c = chosen_[ref.slot];
        if (f >= ref.parentFitness && (c < 0 || f > batch_.fitness(refinements_[std::size_t(c)].batchIndex)))
            c = std::int64_t(r);
    }
    for (std::size_t r = 0; r < refinements_.size(); ++r) {
        const Refinement& ref = refinements_[r];
        if (chosen_[ref.slot] != std::int64_t(r)) continue;
        std::swap(next_.individuals[ref.slot], proposals_[r]);
        next_.fitness[ref.slot] = batch_.fitness(ref.batchIndex);
    }
    std::swap(pop_, next_);
    ++generation_;
    if (mainIslands() > 1 && settings_.migrationInterval > 0 && generation_ % settings_.migrationInterval == 0)
        migrate();
    if (mainIslands() > 1 && settings_.restartInterval > 0 && generation_ % settings_.restartInterval == 0)
        restartWorstIsland(evaluator);
    if (hasScout() && generation_ % settings_.scoutInterval == 0) scoutTurn(evaluator);
}

std::size_t HybridSearch::bestSlot(std::size_t k) const { return bestEmigrant(pop_.fitness, islandBegin(k), islandBegin(k + 1)); }

std::size_t HybridSearch::worstMainIsland() const {
    std::size_t worst = 0;
    for (std::size_t k = 1; k < mainIslands(); ++k)
        if (pop_.fitness[bestSlot(k)] <= pop_.fitness[bestSlot(worst)]) worst = k;
    return worst;
}

void HybridSearch::restartWorstIsland(Evaluator& evaluator) { restartIsland(worstMainIsland(), evaluator); }

void HybridSearch::restartIsland(std::size_t k, Evaluator& evaluator) {
    batch_.clear();
    for (std::size_t i = islandBegin(k); i < islandBegin(k + 1); ++i) {
        ops_->randomGenome(pop_.individuals[i], rng_, population_.initialGenesMin, population_.initialGenesMax);
        batch_.add(pop_.individuals[i]);
    }
    evaluations_ += batch_.evaluate(evaluator);
    for (std::size_t i = islandBegin(k), j = 0; i < islandBegin(k + 1); ++i, ++j) pop_.fitness[i] = batch_.fitness(j);
}

void HybridSearch::scoutTurn(Evaluator& evaluator) {
    const std::size_t scout = islands_ - 1;
    const std::size_t worst = worstMainIsland();
    if (pop_.fitness[bestSlot(scout)] > pop_.fitness[bestSlot(worst)]) {
        // The scout's members, best first (the lower slot among equals), fill the worst island;
        // it may be one larger than the scout: the scout's best fills the rest.
        const std::size_t b = islandBegin(scout), m = islandBegin(scout + 1) - b;
        std::size_t* order = order_.data() + b;
        for (std::size_t i = 0; i < m; ++i) order[i] = b + i;
        std::sort(order, order + m, [&](std::size_t x, std::size_t y) {
            return pop_.fitness[x] > pop_.fitness[y] || (pop_.fitness[x] == pop_.fitness[y] && x < y);
        });
        for (std::size_t i = islandBegin(worst), j = 0; i < islandBegin(worst + 1); ++i, ++j) {
            const std::size_t from = order[j < m ? j : 0];
            pop_.individuals[i] = pop_.individuals[from];
            pop_.fitness[i] = pop_.fitness[from];
        }
    }
    restartIsland(scout, evaluator);
}

void HybridSearch::migrate() {
    // Every island's best and worst first, then the copies: island k's best replaces island
    // k + 1's worst around the ring of the main islands (a scout takes no part). Who emigrates and
    // who is replaced is the migration policy's (search/migration_policy.hpp), as between ranks.
    const std::size_t n = mainIslands();
    std::vector<std::size_t>& best = migrationSlots_;  // [0, n) best, [islands, islands + n) worst
    for (std::size_t k = 0; k < n; ++k) {
        best[k] = bestSlot(k);
        best[islands_ + k] = worstReplaced(pop_.fitness, islandBegin(k), islandBegin(k + 1));
    }
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t from = best[k], to = best[islands_ + (k + 1) % n];
        pop_.individuals[to] = pop_.individuals[from];
        pop_.fitness[to] = pop_.fitness[from];
    }
}

}  // namespace shapevo

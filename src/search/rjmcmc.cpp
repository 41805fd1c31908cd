// Rjmcmc: proposals in chain order, one evaluation batch per stage, accept/reject in chain
// order, then tempering swaps. Every random draw comes from rng_ in that fixed order.
#include "search/rjmcmc.hpp"

#include <algorithm>
#include <cstring>

#include "genome/operators.hpp"
#include "search/mcmc_acceptance.hpp"

namespace shapevo {

Rjmcmc::Rjmcmc(const Grammar& g, const RjmcmcSettings& settings, const PopulationSettings& population,
               const GenomeLimits& limits, std::uint64_t seed)
    : SearchMethod(seed), grammar_(g), settings_(settings), population_(population), limits_(limits), growth_(g, limits) {
    resize(population.population);
}

void Rjmcmc::resize(std::size_t n) {
    pop_.individuals.resize(n);
    pop_.fitness.resize(n, 0.0);
    proposals_.resize(n);
    second_.resize(n);
    star_.resize(n);
    info_.resize(n);
    matched_.resize(n);
    temperature_.resize(n);
}

double Rjmcmc::temperature(std::size_t i) const {
    return chainTemperature(std::uint32_t(i), std::uint32_t(pop_.size()), generation_, settings_.temperature,
                            settings_.temperatureRatio, settings_.annealing, settings_.annealingInterval);
}

void Rjmcmc::initialize(Evaluator& evaluator) {
    startFromRandomGrowth(growth_, population_.initialGenesMin, population_.initialGenesMax, evaluator);
}

void Rjmcmc::restored() { resize(pop_.size()); }

void Rjmcmc::propose(std::size_t i) {
    Proposal& p = info_[i];
    p = Proposal{};
    const Chromosome& x = pop_.individuals[i];
    Chromosome& y = proposals_[i];
    if (rng_.uniform() < settings_.jumpProbability) {
        p.weightBefore = jumpWeightTotal(grammar_, x, settings_.depthBias, regrow_);
        if (!(p.weightBefore > 0)) return;
        const std::uint32_t v = pickJumpGene(grammar_, x, p.weightBefore, rng_, regrow_);
        ++counters_.jumps;
        if (!regrowBelow(grammar_, x, v, y, rng_, limits_, regrow_, settings_.delayedRejection ? &matched_[i] : nullptr))
            return;  // past max_genes: outside the space, rejected
        p.weightAfter = jumpWeightTotal(grammar_, y, settings_.depthBias, regrow_);
        p.move = Move::Jump;
    } else {
        y.copyFrom(x);
        bool altered = false;
        for (std::uint32_t k = 0; k < settings_.diffusionAlters; ++k) altered = alter(grammar_, y, rng_) || altered;
        if (!altered) return;
        ++counters_.diffusions;
        p.move = Move::Diffusion;
    }
}

void Rjmcmc::step(Evaluator& evaluator) {
    const std::size_t n = pop_.size();
    for (std::size_t i = 0; i < n; ++i) temperature_[i] = temperature(i);
    batch_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        propose(i);
        if (info_[i].move != Move::None) info_[i].slot = batch_.add(proposals_[i]);
    }
    evaluations_ += batch_.evaluate(evaluator);
    delayed_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        Proposal& p = info_[i];
        if (p.move == Move::None) continue;
        p.fitness = batch_.fitness(p.slot);
        const double f = pop_.fitness[i], t = temperature_[i];
        const double logRatio = p.move == Move::Jump ? jumpLogRatio(f, p.fitness, t, p.weightBefore, p.weightAfter)
                                                     : (p.fitness - f) / t;
        if (rng_.uniform() < acceptanceFromLog(logRatio)) {
            std::swap(pop_.individuals[i], proposals_[i]);
            pop_.fitness[i] = p.fitness;
            ++(p.move == Move::Jump ? counters_.jumpsAccepted : counters_.diffusionsAccepted);
        } else if (p.move == Move::Jump && settings_.delayedRejection && !matched_[i].empty()) {
            delayed_.push_back(i);
        }
    }
    if (!delayed_.empty()) secondStage(evaluator);
    // Parallel tempering: neighbours swap states; pairs alternate between even and odd sweeps.
    for (std::size_t i = generation_ % 2; i + 1 < n; i += 2) {
        ++counters_.swaps;
        if (rng_.uniform() < swapAcceptance(pop_.fitness[i], pop_.fitness[i + 1], temperature_[i], temperature_[i + 1])) {
            std::swap(pop_.individuals[i], pop_.individuals[i + 1]);
            std::swap(pop_.fitness[i], pop_.fitness[i + 1]);
            ++counters_.swapsAccepted;
        }
    }
    ++generation_;
}

void Rjmcmc::secondStage(Evaluator& evaluator) {
    batch_.clear();
    for (const std::size_t i : delayed_) {
        // y2 = y1 with one reused (paired) gene re-drawn; y1* = x with that gene's partner set to
        // the same new values (the reverse path's intermediate).
        const std::vector<MatchedGene>& m = matched_[i];
        const MatchedGene pick = m[rng_.below(std::uint32_t(m.size()))];
        const Chromosome& x = pop_.individuals[i];
        second_[i] = proposals_[i];
        drawParams(grammar_, second_[i], pick.to, rng_);
        star_[i] = x;
        const Rule& r = grammar_.rules[x.rule(pick.from)];
        std::memcpy(&star_[i].words[Chromosome::paramWord(pick.from, r)],
                    &second_[i].words[Chromosome::paramWord(pick.to, r)], r.paramFloats * sizeof(std::uint32_t));
        batch_.add(second_[i]);
        batch_.add(star_[i]);
    }
    evaluations_ += batch_.evaluate(evaluator);
    for (std::size_t k = 0; k < delayed_.size(); ++k) {
        const std::size_t i = delayed_[k];
        const Proposal& p = info_[i];
        const double f2 = batch_.fitness(2 * k), fStar = batch_.fitness(2 * k + 1);
        const double a = delayedRejectionAcceptance(pop_.fitness[i], p.fitness, f2, fStar, temperature_[i],
                                                    p.weightBefore, p.weightAfter);
        ++counters_.secondStages;
        if (rng_.uniform() < a) {
            std::swap(pop_.individuals[i], second_[i]);
            pop_.fitness[i] = f2;
            ++counters_.secondStagesAccepted;
        }
    }
}

}  // namespace shapevo

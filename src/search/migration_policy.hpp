// The migration policy of both rings, the MPI ring of islands (island/ring_migration.hpp) and the
// hybrid search's in-process islands (search/hybrid_search.hpp): the best `count` of the sender
// emigrate and replace the worst of the receiver. One place for who leaves and who is replaced,
// with one tie-breaking, so that the two rings cannot drift apart and seeded runs stay repeatable:
//  - emigrants: the highest fitness first; among equals the lower slot first;
//  - replaced: the lowest fitness first; among equals the higher slot first (the elite, kept at
//    the early slots, stays).
// Fitness values are finite (an evaluator gives no NaN; migrants with another are rejected).
// Selecting one (the hybrid's islands) is a single scan and allocates nothing.
#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "genome/chromosome.hpp"
#include "search/population.hpp"

namespace shapevo {

/// Slots [first, last) of `fitness`: the `count` best (fewer if the range is shorter), best first,
/// into `out` (cleared first).
void selectEmigrants(std::span<const double> fitness, std::size_t first, std::size_t last, std::size_t count,
                     std::vector<std::size_t>& out);
/// The best slot of [first, last) (first < last): selectEmigrants with count 1.
std::size_t bestEmigrant(std::span<const double> fitness, std::size_t first, std::size_t last);

/// Slots [first, last) of `fitness`: the `count` worst (fewer if the range is shorter), worst
/// first, into `out` (cleared first).
void selectReplaced(std::span<const double> fitness, std::size_t first, std::size_t last, std::size_t count,
                    std::vector<std::size_t>& out);
/// The worst slot of [first, last) (first < last): selectReplaced with count 1.
std::size_t worstReplaced(std::span<const double> fitness, std::size_t first, std::size_t last);

/// Indices of the `count` best individuals of `pop`, best first.
std::vector<std::size_t> bestIndices(const Population& pop, std::size_t count);
/// Replace the worst individuals among the first `slots` of `pop` by the arrivals, in order: the
/// first arrival replaces the worst (extra arrivals are dropped).
void replaceWorst(Population& pop, const std::vector<Chromosome>& arrivals, const std::vector<double>& fitness,
                  std::size_t slots);

}  // namespace shapevo

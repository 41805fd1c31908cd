// The list orderings of PCGR §4.4: order by (several keys, each ascending or descending), reverse
// and shuffle. Each writes list positions (0..n-1) in their new order; apply them with
// selectEntities (entity_list.hpp). Deterministic (same bytes on any machine and thread count);
// nothing allocates once `order` and the workspace have grown.
//
// order by: keys[i * keyCount + k] is key k of the entity at list position i; entities compare by
// key 0, then key 1, ... each in its direction; entities equal in every key keep their list order
// (stable). A NaN key sorts after every number in both directions; NaNs tie with each other. -0
// and +0 tie (they compare equal).
// shuffle: a permutation that depends on every bit of `u` (a gene parameter in [0, 1)) and of
// `key` (e.g. the invocation's piece key); Fisher-Yates driven by xoshiro256** (base/random.hpp)
// seeded with both, so every permutation of n entities is about equally likely (Lemire's
// draw: bias below 2^-32).
#pragma once
#include <cstdint>
#include <span>
#include <vector>



namespace shapevo::lists {

enum class SortDirection : std::uint8_t { Ascending, Descending };

/// `order` = the positions 0..n-1 (n = keys.size() / directions.size()) sorted by the keys.
/// directions.size() is the number of keys per entity (at least 1).
void orderBy(std::span<const double> keys, std::span<const SortDirection> directions, std::vector<std::uint32_t>& order);

/// Reverses `order` in place (apply it to 0..n-1 for the reversed list).
void reverseOrder(std::span<std::uint32_t> order);

/// `order` = a permutation of 0..n-1 drawn from `u` and `key`.
void shuffleOrder(std::uint32_t n, double u, std::uint64_t key, std::vector<std::uint32_t>& order);

/// `order` = 0..n-1 (the identity).
void identityOrder(std::uint32_t n, std::vector<std::uint32_t>& order);

/// The total order of order by on one key: -1 if a sorts before b, 1 if after, 0 if they tie.
int compareKey(double a, double b, SortDirection direction);

}  // namespace shapevo::lists

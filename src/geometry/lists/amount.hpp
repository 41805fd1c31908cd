// Counting and amount filtering (PCGR §4.3, §4.6): count / index, "amount filter" and "amount
// filter by" (per group). Results are list positions in list order; nothing allocates once the
// output vectors have grown.
//
// count / index: the count of a list is its size n; index i of the entity at position i is i.
// amount filter (from k, amount m): positions k .. k+m-1 that exist go to `kept`, every other
// position to `rest`, both in list order. k at or beyond the size: everything to `rest`; k + m
// beyond the size: every position from k on to `kept`; an empty list: both empty, no error. The
// caller turns expression values into k and m (e.g. floor, negative as 0).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/lists/entity_list.hpp"
#include "geometry/lists/grouping.hpp"

namespace shapevo::lists {

/// index[i] = i for every position of `index` (the list's size is index.size()).
void writeIndices(std::span<double> index);

/// Writes each entity's index into attribute slot `slot` of `list` (< list.width) and returns the
/// count (PCGR's "count" node with its index mapped to an attribute).
std::uint32_t countInto(EntityList& list, std::uint32_t slot);

/// The amount filter on a list of n entities.
void amountFilter(std::uint32_t n, std::uint64_t from, std::uint64_t amount, std::vector<std::uint32_t>& kept,
                  std::vector<std::uint32_t>& rest);

/// The amount filter within each group: in every group, the members from member index `from`
/// (amount of them) go to `kept`; the others to `rest`. Both in list order.
void amountFilterByGroup(const Grouping& groups, std::uint64_t from, std::uint64_t amount, std::vector<std::uint32_t>& kept,
                         std::vector<std::uint32_t>& rest);

}  // namespace shapevo::lists

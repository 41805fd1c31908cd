// Groups of a list (PCGR §4.1 "group", and the components unify and cluster make): a partition of
// list positions into groups. Groups come in order of first appearance (the group holding the
// smallest position first); members keep list order. groupBy groups by exact key equality;
// ungroupEntities puts a grouped copy of the entities back into list order, bit for bit.
// Nothing allocates once the vectors have grown.
//
// Key equality (groupBy): keys[i * keyCount + k] is key k of position i; two entities share a
// group when every key compares equal with ==, except that NaN equals NaN (all NaNs form one
// value) and -0 equals +0.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/lists/entity_list.hpp"
#include "geometry/lists/list_workspace.hpp"

namespace shapevo::lists {

struct Grouping {
    std::vector<std::uint32_t> members;  ///< list positions, group after group, each group in list order
    std::vector<std::uint32_t> starts;   ///< group g is members[starts[g], starts[g + 1]); count() + 1 entries
    std::vector<std::uint32_t> groupOf;  ///< per list position, its group

    std::uint32_t count() const { return starts.empty() ? 0 : std::uint32_t(starts.size() - 1); }
    std::span<const std::uint32_t> group(std::uint32_t g) const {
        return {members.data() + starts[g], starts[g + 1] - starts[g]};
    }
};

/// Groups positions 0..n-1 (n = keys.size() / keyCount; keyCount >= 1) by their keys.
void groupBy(std::span<const double> keys, std::uint32_t keyCount, Grouping& out, ListWorkspace& ws);

/// Fills members and starts from groupOf (labels 0..groupCount-1 in any order of appearance):
/// relabels groups in order of first appearance and lists members in list order.
void groupFromLabels(std::span<const std::uint32_t> labels, std::uint32_t groupCount, Grouping& out, ListWorkspace& ws);

/// `grouped` holds the entities in the order of `grouping.members` (selectEntities(list,
/// grouping.members, grouped)); `out` = the same entities back in list order, bit for bit.
void ungroupEntities(const EntityList& grouped, const Grouping& grouping, EntityList& out);

}  // namespace shapevo::lists

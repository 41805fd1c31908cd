// Aggregates (PCGR §4.2): min, max, avg and sum of one value per entity, a scalar or a 3-vector
// (componentwise), over a whole list or per group. The caller evaluates the expression per entity;
// the values come in list order. Deterministic: one pass left to right in list order (a group: in
// its members' list order), so the result is the same bytes on every machine and thread count.
//
// sum: 0.0 + v0 + v1 + ... (left to right); avg: that sum / n; min / max: the first value that no
// later value is strictly below / above, NaN values skipped. An empty list (or all NaN for min /
// max): sum 0, avg NaN, min and max NaN. avg of values with a NaN is NaN (the sum is).
#pragma once
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "geometry/lists/grouping.hpp"

namespace shapevo::lists {

enum class Aggregate : std::uint8_t { Min, Max, Avg, Sum };

double aggregate(Aggregate kind, std::span<const double> values);
glm::dvec3 aggregate(Aggregate kind, std::span<const glm::dvec3> values);

/// out[g] = the aggregate over group g's members (values indexed by list position);
/// out.size() == groups.count().
void aggregateGroups(Aggregate kind, std::span<const double> values, const Grouping& groups, std::span<double> out);
void aggregateGroups(Aggregate kind, std::span<const glm::dvec3> values, const Grouping& groups, std::span<glm::dvec3> out);

}  // namespace shapevo::lists

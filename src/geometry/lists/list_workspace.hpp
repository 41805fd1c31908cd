// ListWorkspace: the scratch vectors the list operations of this folder reuse, so that an
// operation allocates nothing once the vectors have grown to the largest list it has seen. One
// workspace per thread; an operation's results never live in it (they go to the caller's
// vectors), so any operation may run after any other on the same workspace.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace shapevo::lists {

struct ListWorkspace {
    std::vector<std::uint32_t> indices;    ///< positions being sorted (order by, group by)
    std::vector<std::uint32_t> indices2;   ///< a second set (group by's runs, unify's edges)
    std::vector<std::uint32_t> counts;     ///< per group / cluster / component
    std::vector<std::uint32_t> labels;     ///< per entity (k-means' previous assignment, union-find parents)
    std::vector<double> numbers;           ///< per edge boxes (unify)
    std::vector<glm::dvec3> points;        ///< k-means' sums, unify's edge end points
};

}  // namespace shapevo::lists

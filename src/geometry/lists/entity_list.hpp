// EntityList: what a PCGR list holds (NOTES.md §4.2 "Lists"): entities, each a scope (world
// centre, axes, size, look; geometry/pieces.hpp) plus a fixed number of attribute values
// (doubles; a 3-vector attribute takes three consecutive slots). The list operations of this
// folder work on list positions (0..n-1) and return positions or values; selectEntities applies
// such an order. Nothing here allocates once the vectors have grown (clear keeps capacity).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/pieces.hpp"

namespace shapevo::lists {

/// A list of entities in list order. Entity i's attributes are values[i * width, (i + 1) * width).
struct EntityList {
    std::uint32_t width = 0;      ///< attribute values per entity
    std::vector<Scope> scopes;    ///< one per entity, in list order
    std::vector<double> values;   ///< scopes.size() * width

    std::uint32_t size() const { return std::uint32_t(scopes.size()); }
    std::span<const double> attributes(std::uint32_t i) const { return {values.data() + std::size_t(i) * width, width}; }
    std::span<double> attributes(std::uint32_t i) { return {values.data() + std::size_t(i) * width, width}; }
    /// Empties the list and sets its width; the vectors keep their capacity.
    void clear(std::uint32_t newWidth) {
        width = newWidth;
        scopes.clear();
        values.clear();
    }
    /// Appends one entity; `attrs` holds `width` values.
    void append(const Scope& s, std::span<const double> attrs) {
        scopes.push_back(s);
        values.insert(values.end(), attrs.begin(), attrs.begin() + width);
    }
};

/// out = the entities of `in` at the positions `order` (a permutation, a selection or repeats),
/// copied bit for bit in that order. `out` must not be `in`.
void selectEntities(const EntityList& in, std::span<const std::uint32_t> order, EntityList& out);

/// The world points of a list's scope origins, in list order (k-means' usual input).
void scopeOrigins(std::span<const Scope> scopes, std::vector<glm::dvec3>& out);

}  // namespace shapevo::lists

// Collections: the lists a derivation has open (PCGR's collective inputs; grammar/grammar.hpp
// StatementKind::Open, Send, Gather). A rule body that gathers opens one collection per gather
// when an invocation of it starts; `send` appends the current scope to the innermost open
// collection of its list; the gather runs when everything the invocation started is done, and
// closes it. Collections nest like the invocations (a stack), and a sibling invocation never sees
// another's. Nothing allocates once the vectors have grown (a closed collection keeps its
// capacity for the next one opened at its depth).
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/lists/entity_list.hpp"
#include "geometry/lists/facing.hpp"
#include "geometry/lists/grouping.hpp"
#include "geometry/lists/list_workspace.hpp"
#include "geometry/lists/ordering.hpp"
#include "geometry/lists/ray_cast.hpp"

namespace shapevo {

struct Collection {
    std::uint16_t list = 0;       ///< Grammar::listNames
    std::uint32_t gather = 0;     ///< Grammar::gathers
    std::uint32_t frame = UINT32_MAX;  ///< its rule's let values when the gather statement was reached (DeriveScratch::frames)
    lists::EntityList entities;   ///< in the order they were sent (the derivation's order); with carried
                                  ///< attributes, attribute 0 is each one's carried block (DeriveScratch::carried)
};

struct Collections {
    std::vector<Collection> pool;  ///< [0, open) are open, innermost last
    std::size_t open = 0;

    void clear() { open = 0; }
    /// Opens a collection whose entities carry `width` attribute values (1: their carried block).
    Collection& push(std::uint16_t list, std::uint32_t gather, std::uint32_t frame, std::uint32_t width) {
        if (open == pool.size()) pool.emplace_back();
        Collection& c = pool[open++];
        c.list = list;
        c.gather = gather;
        c.frame = frame;
        c.entities.clear(width);
        return c;
    }
    /// The innermost open collection of `list` (nullptr: none).
    Collection* innermost(std::uint16_t list) {
        for (std::size_t k = open; k-- > 0;)
            if (pool[k].list == list) return &pool[k];
        return nullptr;
    }
    /// The innermost open collection of gather `gather` (nullptr: none).
    Collection* ofGather(std::uint32_t gather) {
        for (std::size_t k = open; k-- > 0;)
            if (pool[k].gather == gather) return &pool[k];
        return nullptr;
    }

    // Work space of the gathers' steps (geometry/gather.cpp).
    lists::EntityList spare;
    lists::ListWorkspace workspace;
    lists::Grouping grouping;
    std::vector<double> keys;
    std::vector<lists::SortDirection> directions;
    std::vector<std::uint32_t> order, part, kept, rest;
    std::vector<std::uint32_t> starts;                 ///< the list's groups: group k is [starts[k], starts[k + 1])
    std::vector<std::uint32_t> keptStarts, restStarts;  ///< a route's kept / rest positions, per group
    std::vector<std::uint32_t> frameOf, spareFrameOf;   ///< per entity, its let values in `localFrames`
    std::vector<float> localFrames;                     ///< let values, Rule::frameFloats per frame
    std::vector<std::uint32_t> storedFrame;             ///< per local frame, where the route stored it (DeriveScratch::frames)
    std::vector<double> values;
    std::vector<glm::dvec3> points, centroids;
    std::vector<std::uint32_t> clusterOf;
    lists::BoxTree tree;
    std::vector<lists::RayHit> hits;
    std::vector<lists::StreetSegment> streets;
    std::vector<std::uint8_t> flags;
};

}  // namespace shapevo

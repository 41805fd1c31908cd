// Running a gather (grammar/grammar.hpp ListOp): its steps on the collection its invocation
// filled, in order, then its route, which pushes one task per routed entity running the route's
// successor on that entity's scope. Internal to derive (geometry/derive.cpp).
//
// Promises: deterministic (the list operations of geometry/lists/ are; values are evaluated per
// entity in list order); groups (group by, cluster, unify) are runs of the list, each entity
// with its own copy of the let values (its group's); an entity routed to successor s (0 or 1)
// of gather i is the k-th of the n entities of its group routed there, and its task reads
// piece.index k and piece.count n and, for `per piece` parameters, the piece key of the j-th
// piece of kind 2i + s below the invocation's (j: its place among all routed there), and the
// carried attribute values the entity had when it was sent; the first routed entity runs first. Nothing allocates once the work space (Collections) has grown.
#pragma once
#include "geometry/derive.hpp"

namespace shapevo {

/// An Open statement `st` of `task` on scope `s`: one collection per gather of the rule's body
/// (their frame: `frame`, the task's let values now), and below everything the invocation will
/// push, a marker task for each (the first gather's on top: it runs first, so its routes may
/// send to the later ones).
void openCollections(const Grammar& g, const Statement& st, const DeriveScratch::Task& task, const Scope& s,
                     std::uint32_t frame, DeriveScratch& scratch);

/// A Send statement: `s` into the innermost open collection of its list (the parser checked that
/// one exists), with `carried` (its carried values' block, DeriveScratch::carried) when the
/// grammar declares carried attributes; false when that collection is full (kMaxListEntities).
bool sendScope(Collections& collections, const Statement& st, const Scope& s, std::uint32_t carried);

/// A marker task: its gene's parameters, the gather's let values and the invocation's mark into
/// `params`, then runGather.
void runGatherMarker(const Grammar& g, const Chromosome& c, const DeriveScratch::Task& marker, float* params,
                     float* evalStack, DeriveScratch& scratch);

/// The gather of marker task `marker` (end kGatherMarker, statement: the gather's index) on the
/// innermost open collection, which it closes. `params` holds the gene's parameters, the gather's
/// let values and the invocation's mark.
void runGather(const Grammar& g, const Rule& r, const DeriveScratch::Task& marker, float* params, float* evalStack,
               DeriveScratch& scratch);

}  // namespace shapevo

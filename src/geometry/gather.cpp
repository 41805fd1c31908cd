// Running a gather: see geometry/gather.hpp.
#include "geometry/gather.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "geometry/lists/aggregate.hpp"
#include "geometry/lists/amount.hpp"
#include "grammar/expression.hpp"

namespace shapevo {

namespace {
/// A count or a position from an expression's value: its floor, 0 for a negative value or NaN.
std::uint64_t wholeCount(float v) {
    if (!(v > 0.0f)) return 0;
    return v >= 4294967296.0f ? (std::uint64_t(1) << 32) : std::uint64_t(std::floor(v));
}

/// The values of a gather's expressions, evaluated on one entity's scope at a time (with its
/// frame written where scope.origin and scope.axis read it).
struct EntityEvaluator {
    const Grammar& g;
    float* params;
    float* evalStack;
    glm::vec3 parentSize;
    float operator()(const ExprRef& e, const Scope& s) const {
        std::memcpy(params + kScopeOriginSlot, &s.origin[0], 3 * sizeof(float));
        std::memcpy(params + kScopeAxisSlot, &s.axes[0][0], 9 * sizeof(float));
        return evaluate(g, e, params, &s.size.x, &parentSize.x, evalStack);
    }
};

/// The aggregate of a let in a gather over `list`, into its frame floats.
void aggregateInto(const ListOp& op, const lists::EntityList& list, const EntityEvaluator& eval, Collections& cs,
                   float* params) {
    const auto kind = lists::Aggregate(op.detail);
    if (op.dims == 1) {
        cs.values.clear();
        for (const Scope& s : list.scopes) cs.values.push_back(eval(op.expr[0], s));
        params[op.slot] = float(lists::aggregate(kind, cs.values));
        return;
    }
    cs.points.clear();
    for (const Scope& s : list.scopes) cs.points.emplace_back(eval(op.expr[0], s), eval(op.expr[1], s), eval(op.expr[2], s));
    const glm::dvec3 v = lists::aggregate(kind, cs.points);
    for (int k = 0; k < 3; ++k) params[op.slot + k] = float(v[k]);
}

/// One task per entity of `list` at `positions`, running statements [begin, end) of the rule,
/// last first so that the first runs first.
void pushRouted(const Grammar& g, const DeriveScratch::Task& marker, std::uint32_t begin, std::uint32_t end,
                std::uint32_t successor, const lists::EntityList& list, const std::vector<std::uint32_t>& positions,
                std::uint32_t frame, DeriveScratch& scratch) {
    if (begin == end) return;  // nil
    const auto n = std::uint32_t(positions.size());
    for (std::uint32_t k = n; k-- > 0;) {
        scratch.scopes.push_back(list.scopes[positions[k]]);
        const auto at = std::uint32_t(scratch.scopes.size() - 1);
        PieceMark mark = marker.mark;
        if (g.usesPieceKeys) mark.key = pieceKey(marker.mark.key, successor, k);
        if (g.usesPiecePlaces) mark.place = piecePlace(k, n);
        scratch.stack.push_back({marker.gene, begin, end, at, marker.parent, frame, mark});
    }
}
}  // namespace

void runGather(const Grammar& g, const Rule& r, const DeriveScratch::Task& marker, float* params, float* evalStack,
               DeriveScratch& scratch) {
    Collections& cs = scratch.collections;
    Collection& c = cs.pool[cs.open - 1];  // the marker's: collections close in the order their markers pop
    const Gather& gather = g.gathers[marker.statement];
    const Scope invocation = scratch.scopes[marker.scope];
    const EntityEvaluator eval{g, params, evalStack, scratch.scopes[marker.parent].size};
    lists::EntityList* list = &c.entities;
    lists::EntityList* spare = &cs.spare;
    auto reorder = [&] {
        lists::selectEntities(*list, cs.order, *spare);
        std::swap(list, spare);
    };
    const ListOp* ops = g.listOps.data() + gather.firstOp;
    for (std::uint32_t i = 0; i < gather.ops; ++i) {
        const ListOp& op = ops[i];
        const std::uint32_t n = list->size();
        switch (op.kind) {
        case ListOpKind::OrderBy: {
            const std::uint32_t keys = op.keys;
            cs.keys.resize(std::size_t(n) * keys);
            cs.directions.clear();
            for (std::uint32_t k = 0; k < keys; ++k)
                cs.directions.push_back(ops[i + k].detail ? lists::SortDirection::Descending : lists::SortDirection::Ascending);
            for (std::uint32_t e = 0; e < n; ++e)
                for (std::uint32_t k = 0; k < keys; ++k) cs.keys[std::size_t(e) * keys + k] = eval(ops[i + k].expr[0], list->scopes[e]);
            lists::orderBy(cs.keys, cs.directions, cs.order);
            reorder();
            i += keys - 1;
            break;
        }
        case ListOpKind::Reverse:
            lists::identityOrder(n, cs.order);
            lists::reverseOrder(cs.order);
            reorder();
            break;
        case ListOpKind::Shuffle: {
            const double u = eval(op.expr[0], invocation);
            lists::shuffleOrder(n, u, std::uint64_t(marker.mark.key) << 32 | marker.statement, cs.order);
            reorder();
            break;
        }
        case ListOpKind::Aggregate:
            aggregateInto(op, *list, eval, cs, params);
            break;
        case ListOpKind::KeepFirst:
            lists::amountFilter(n, wholeCount(eval(op.expr[1], invocation)), wholeCount(eval(op.expr[0], invocation)),
                                cs.kept, cs.rest);
            break;
        case ListOpKind::Each:
            lists::identityOrder(n, cs.kept);
            cs.rest.clear();
            break;
        case ListOpKind::Where:
            cs.kept.clear();
            cs.rest.clear();
            for (std::uint32_t e = 0; e < n; ++e) {
                const float v = eval(op.expr[0], list->scopes[e]);
                (v > 0.0f || v < 0.0f ? cs.kept : cs.rest).push_back(e);  // 0 and NaN are false
            }
            break;
        }
    }
    --cs.open;  // closed: its entities stay readable until a collection opens at its depth
    const ListOp& route = ops[gather.ops - 1];
    const std::uint32_t frame =
        r.frameFloats == 0 ? DeriveScratch::kNoFrame : std::uint32_t(scratch.frames.size());
    if (r.frameFloats > 0) scratch.frames.insert(scratch.frames.end(), params + kFrameBase, params + kFrameBase + r.frameFloats);
    pushRouted(g, marker, route.begin[1], route.end[1], 1, *list, cs.rest, frame, scratch);
    pushRouted(g, marker, route.begin[0], route.end[0], 0, *list, cs.kept, frame, scratch);
}

void openCollections(const Grammar& g, const Statement& st, const DeriveScratch::Task& task, const Scope& s,
                     std::uint32_t frame, DeriveScratch& scratch) {
    scratch.scopes.push_back(s);
    const auto at = std::uint32_t(scratch.scopes.size() - 1);
    for (std::uint32_t k = st.end; k-- > 0;) {
        const std::uint32_t gather = st.slot + k;
        scratch.collections.push(g.gathers[gather].list, gather, frame);
        scratch.stack.push_back({task.gene, gather, DeriveScratch::kGatherMarker, at, task.parent, frame, task.mark});
    }
}

bool sendScope(Collections& collections, const Statement& st, const Scope& s) {
    Collection* c = collections.innermost(st.slot);
    if (c == nullptr || c->entities.size() >= kMaxListEntities) return false;
    c->entities.scopes.push_back(s);
    return true;
}

void runGatherMarker(const Grammar& g, const Chromosome& c, const DeriveScratch::Task& marker, float* params,
                     float* evalStack, DeriveScratch& scratch) {
    const Rule& r = g.rules[c.rule(marker.gene)];
    const Collection& open = scratch.collections.pool[scratch.collections.open - 1];
    if (r.paramFloats > 0)
        std::memcpy(params, &c.words[Chromosome::paramWord(marker.gene, r)], r.paramFloats * sizeof(float));
    if (open.frame != DeriveScratch::kNoFrame)
        std::memcpy(params + kFrameBase, scratch.frames.data() + open.frame, r.frameFloats * sizeof(float));
    loadPieceMark(g, marker.mark, params);
    runGather(g, r, marker, params, evalStack, scratch);
}

}  // namespace shapevo

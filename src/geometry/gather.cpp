// Running a gather: see geometry/gather.hpp.
#include "geometry/gather.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "geometry/lists/adjacency.hpp"
#include "geometry/lists/aggregate.hpp"
#include "geometry/lists/amount.hpp"
#include "geometry/lists/facing.hpp"
#include "geometry/lists/kmeans.hpp"
#include "geometry/lists/merge.hpp"
#include "geometry/lists/ray_cast.hpp"
#include "grammar/expression.hpp"

namespace shapevo {

namespace {
constexpr std::uint32_t kNone = UINT32_MAX;

/// A count or a position from an expression's value: its floor, 0 for a negative value or NaN.
std::uint64_t wholeCount(float v) {
    if (!(v > 0.0f)) return 0;
    return v >= 4294967296.0f ? (std::uint64_t(1) << 32) : std::uint64_t(std::floor(v));
}

/// One gather's steps on its collection. The list is split into groups (one group until a
/// group by, cluster or unify; back to one after merge or ungroup), each a run of list positions
/// (Collections::starts); every entity has its own copy of the let values (a local frame: one per
/// group once grouped), which the expressions evaluated on it read.
class GatherRun {
public:
    GatherRun(const Grammar& g, const Rule& r, const DeriveScratch::Task& marker, float* params, float* evalStack,
              DeriveScratch& scratch)
        : g_(g), marker_(marker), params_(params), evalStack_(evalStack), scratch_(scratch), cs_(scratch.collections),
          invocation_(scratch.scopes[marker.scope]), parentSize_(scratch.scopes[marker.parent].size),
          frameFloats_(r.frameFloats), list_(&cs_.pool[cs_.open - 1].entities), spare_(&cs_.spare) {
        const std::uint32_t n = list_->size();
        cs_.starts.assign({0, n});
        cs_.frameOf.assign(n, 0);
        cs_.localFrames.assign(params + kFrameBase, params + kFrameBase + frameFloats_);  // frame 0: the gather's
        loaded_ = 0;
    }

    void step(const ListOp* ops, std::uint32_t& i);
    /// The route (the last step): kept / rest per group, then one task per routed entity.
    void route(const ListOp& op);

private:
    std::uint32_t groups() const { return std::uint32_t(cs_.starts.size() - 1); }
    /// The let values of group k (its first entity's; the gather's own for an empty list).
    std::uint32_t groupFrame(std::uint32_t k) const {
        return cs_.starts[k] < cs_.starts[k + 1] ? cs_.frameOf[cs_.starts[k]] : 0;
    }
    void load(std::uint32_t frame) {
        if (frame == loaded_ || frameFloats_ == 0) return;
        std::memcpy(params_ + kFrameBase, cs_.localFrames.data() + std::size_t(frame) * frameFloats_, frameFloats_ * sizeof(float));
        loaded_ = frame;
    }
    float evaluateOn(const ExprRef& e, const Scope& s) {
        writeScopeFrame(s, params_);
        return evaluate(g_, e, params_, &s.size.x, &parentSize_.x, evalStack_);
    }
    /// A new local frame holding a copy of frame `from`'s let values.
    std::uint32_t copyFrame(std::uint32_t from) {
        const auto frame = std::uint32_t(cs_.localFrames.size() / frameFloats_);
        cs_.localFrames.resize(cs_.localFrames.size() + frameFloats_);
        std::copy_n(cs_.localFrames.begin() + std::ptrdiff_t(std::size_t(from) * frameFloats_), frameFloats_,
                    cs_.localFrames.end() - std::ptrdiff_t(frameFloats_));
        return frame;
    }
    /// The carried values of block `block` into params_ (grammars that declare some).
    void loadCarriedBlock(std::uint32_t block) {
        if (block == loadedCarried_) return;
        loadCarried(g_, scratch_.carried, block, params_);
        loadedCarried_ = block;
    }
    /// E on entity i, with its let values and carried values.
    float entityValue(const ExprRef& e, std::uint32_t i) {
        load(cs_.frameOf[i]);
        if (list_->width > 0) loadCarriedBlock(std::uint32_t(list_->values[i]));
        return evaluateOn(e, list_->scopes[i]);
    }
    /// E on the invocation's scope, with group k's let values (N, K, U, T) and the invocation's
    /// carried values.
    float groupValue(const ExprRef& e, std::uint32_t k) {
        load(groupFrame(k));
        if (list_->width > 0) loadCarriedBlock(marker_.mark.carried);
        return evaluateOn(e, invocation_);
    }
    /// The list (and each entity's frame) in the order cs_.order.
    void reorder() {
        lists::selectEntities(*list_, cs_.order, *spare_);
        std::swap(list_, spare_);
        cs_.spareFrameOf.clear();
        for (std::uint32_t p : cs_.order) cs_.spareFrameOf.push_back(cs_.frameOf[p]);
        std::swap(cs_.frameOf, cs_.spareFrameOf);
    }
    /// cs_.order gains group k's positions in the order `part` gives them (positions within it).
    void appendPart(std::uint32_t k) {
        for (std::uint32_t p : cs_.part) cs_.order.push_back(cs_.starts[k] + p);
    }
    void orderBy(const ListOp* keys);
    void aggregate(const ListOp& op);
    /// The list regrouped as cs_.grouping says: each group contiguous, with its own frame.
    void applyGrouping();
    void merge();
    /// raycast / facing: one value per entity, each entity its own copy of the let values.
    void look(const ListOp& op);
    void pushRouted(const ListOp& op, int successor, const std::vector<std::uint32_t>& positions,
                    const std::vector<std::uint32_t>& starts);

    const Grammar& g_;
    const DeriveScratch::Task& marker_;
    float* params_;
    float* evalStack_;
    DeriveScratch& scratch_;
    Collections& cs_;
    const Scope invocation_;
    const glm::vec3 parentSize_;
    const std::uint32_t frameFloats_;
    lists::EntityList* list_;
    lists::EntityList* spare_;
    std::uint32_t loaded_ = kNone;  ///< the local frame params_ holds
    std::uint32_t loadedCarried_ = kNone;  ///< the carried block params_ holds
};

void GatherRun::orderBy(const ListOp* ops) {
    const std::uint32_t keys = ops[0].keys, n = list_->size();
    cs_.keys.resize(std::size_t(n) * keys);
    cs_.directions.clear();
    for (std::uint32_t k = 0; k < keys; ++k)
        cs_.directions.push_back(ops[k].detail ? lists::SortDirection::Descending : lists::SortDirection::Ascending);
    for (std::uint32_t e = 0; e < n; ++e)
        for (std::uint32_t k = 0; k < keys; ++k) cs_.keys[std::size_t(e) * keys + k] = entityValue(ops[k].expr[0], e);
    cs_.order.clear();
    for (std::uint32_t k = 0; k < groups(); ++k) {
        const std::size_t a = cs_.starts[k], b = cs_.starts[k + 1];
        lists::orderBy(std::span<const double>(cs_.keys).subspan(a * keys, (b - a) * keys), cs_.directions, cs_.part);
        appendPart(k);
    }
    reorder();
}

void GatherRun::aggregate(const ListOp& op) {
    const auto kind = lists::Aggregate(op.detail);
    float value[3];
    for (std::uint32_t k = 0; k < groups(); ++k) {
        const std::uint32_t a = cs_.starts[k], b = cs_.starts[k + 1];
        if (op.detail == std::uint8_t(AggregateKind::GroupIndex)) {
            value[0] = float(k);
        } else if (op.dims == 1) {
            cs_.values.clear();
            for (std::uint32_t e = a; e < b; ++e) cs_.values.push_back(entityValue(op.expr[0], e));
            value[0] = float(lists::aggregate(kind, cs_.values));
        } else {
            cs_.points.clear();
            for (std::uint32_t e = a; e < b; ++e)
                cs_.points.emplace_back(entityValue(op.expr[0], e), entityValue(op.expr[1], e), entityValue(op.expr[2], e));
            const glm::dvec3 v = lists::aggregate(kind, cs_.points);
            for (int d = 0; d < 3; ++d) value[d] = float(v[d]);
        }
        auto write = [&](std::uint32_t frame) {
            std::memcpy(cs_.localFrames.data() + std::size_t(frame) * frameFloats_ + (op.slot - kFrameBase), value,
                        op.dims * sizeof(float));
        };
        write(groupFrame(k));
        for (std::uint32_t e = a; e < b; ++e) write(cs_.frameOf[e]);
    }
    loaded_ = kNone;
}

void GatherRun::applyGrouping() {
    const lists::Grouping& grouping = cs_.grouping;
    cs_.order.assign(grouping.members.begin(), grouping.members.end());
    reorder();
    if (grouping.count() == 0) {
        cs_.starts.assign({0, 0});
        return;
    }
    cs_.starts.assign(grouping.starts.begin(), grouping.starts.end());
    if (frameFloats_ == 0) return;
    for (std::uint32_t k = 0; k < groups(); ++k) {  // each group its own copy of its first entity's let values
        const std::uint32_t frame = copyFrame(cs_.frameOf[cs_.starts[k]]);
        for (std::uint32_t e = cs_.starts[k]; e < cs_.starts[k + 1]; ++e) cs_.frameOf[e] = frame;
    }
}

void GatherRun::merge() {
    spare_->clear(list_->width);
    cs_.spareFrameOf.clear();
    for (std::uint32_t k = 0; k < groups(); ++k) {
        const std::uint32_t a = cs_.starts[k], b = cs_.starts[k + 1];
        if (a == b) continue;
        spare_->append(lists::mergeScopes(std::span<const Scope>(list_->scopes).subspan(a, b - a)), list_->attributes(a));
        cs_.spareFrameOf.push_back(cs_.frameOf[a]);
    }
    std::swap(list_, spare_);
    std::swap(cs_.frameOf, cs_.spareFrameOf);
    cs_.starts.assign({0, list_->size()});
}

void GatherRun::look(const ListOp& op) {
    const std::uint32_t n = list_->size();
    std::span<const Scope> targets = list_->scopes;
    if (op.other != kOwnList) targets = cs_.ofGather(op.other)->entities.scopes;  // a later gather's: open, complete
    cs_.values.clear();
    if (op.kind == ListOpKind::RayCast) {
        cs_.hits.resize(n);
        const lists::RayAxis along{std::uint8_t(op.detail & 3), (op.detail & 4) != 0};
        lists::rayCast(list_->scopes, along, targets, cs_.tree, cs_.hits);
        for (const lists::RayHit& h : cs_.hits) cs_.values.push_back(h.hit ? h.distance : -1.0);
    } else {
        lists::FacingOptions options;
        const float degrees = groupValue(op.expr[0], 0);
        options.toleranceDegrees = degrees > 0.0f ? std::min(degrees, 89.9f) : 0.0;
        options.unoccluded = op.detail == 1;
        cs_.streets.clear();
        for (const Scope& s : targets) cs_.streets.push_back(lists::streetOfScope(s));
        cs_.flags.resize(n);
        lists::facing(list_->scopes, cs_.streets, options, cs_.tree, cs_.flags);
        for (std::uint8_t f : cs_.flags) cs_.values.push_back(f);
    }
    for (std::uint32_t e = 0; e < n; ++e) {  // each entity its own frame, its own value
        cs_.frameOf[e] = copyFrame(cs_.frameOf[e]);
        cs_.localFrames[std::size_t(cs_.frameOf[e]) * frameFloats_ + (op.slot - kFrameBase)] = float(cs_.values[e]);
    }
    loaded_ = kNone;
}

void GatherRun::step(const ListOp* ops, std::uint32_t& i) {
    const ListOp& op = ops[i];
    const std::uint32_t n = list_->size();
    switch (op.kind) {
    case ListOpKind::OrderBy:
        orderBy(ops + i);
        i += op.keys - 1;
        break;
    case ListOpKind::Reverse:
        cs_.order.clear();
        for (std::uint32_t k = 0; k < groups(); ++k)
            for (std::uint32_t e = cs_.starts[k + 1]; e-- > cs_.starts[k];) cs_.order.push_back(e);
        reorder();
        break;
    case ListOpKind::Shuffle: {
        cs_.order.clear();
        const std::uint64_t key = std::uint64_t(marker_.mark.key) << 32 | marker_.statement;
        for (std::uint32_t k = 0; k < groups(); ++k) {  // group k > 0 draws with its own key
            const double u = groupValue(op.expr[0], k);
            lists::shuffleOrder(cs_.starts[k + 1] - cs_.starts[k], u, key + k * 0x9E3779B97F4A7C15ull, cs_.part);
            appendPart(k);
        }
        reorder();
        break;
    }
    case ListOpKind::Aggregate:
        aggregate(op);
        break;
    case ListOpKind::GroupBy: {
        const std::uint32_t keys = op.keys;
        cs_.keys.resize(std::size_t(n) * keys);
        for (std::uint32_t e = 0; e < n; ++e)
            for (std::uint32_t k = 0; k < keys; ++k) cs_.keys[std::size_t(e) * keys + k] = entityValue(ops[i + k].expr[0], e);
        lists::groupBy(cs_.keys, keys, cs_.grouping, cs_.workspace);
        applyGrouping();
        i += keys - 1;
        break;
    }
    case ListOpKind::Cluster: {
        const std::uint64_t k = wholeCount(groupValue(op.expr[0], 0));
        cs_.points.clear();
        for (std::uint32_t e = 0; e < n; ++e)
            cs_.points.emplace_back(entityValue(op.expr[1], e), op.dims == 3 ? entityValue(op.expr[2], e) : 0.0f,
                                    op.dims == 3 ? entityValue(op.expr[3], e) : 0.0f);
        const lists::KMeansResult result = lists::clusterKMeans(cs_.points, std::uint32_t(std::min<std::uint64_t>(k, n)),
                                                                kMaxClusterRounds, cs_.clusterOf, cs_.centroids, cs_.workspace);
        lists::groupFromLabels(cs_.clusterOf, result.clusters, cs_.grouping, cs_.workspace);
        applyGrouping();
        break;
    }
    case ListOpKind::Unify: {
        const float tolerance = groupValue(op.expr[0], 0);
        lists::unifyAdjacent(list_->scopes, tolerance > 0.0f ? tolerance : 0.0, cs_.grouping, cs_.workspace);
        applyGrouping();
        break;
    }
    case ListOpKind::Merge:
        merge();
        break;
    case ListOpKind::Ungroup:
        cs_.starts.assign({0, n});
        break;
    case ListOpKind::RayCast:
    case ListOpKind::Facing:
        look(op);
        break;
    case ListOpKind::KeepFirst:
    case ListOpKind::Each:
    case ListOpKind::Where:
        break;  // routes: route()
    }
}

void GatherRun::route(const ListOp& op) {
    cs_.kept.clear();
    cs_.rest.clear();
    cs_.keptStarts.assign(1, 0);
    cs_.restStarts.assign(1, 0);
    for (std::uint32_t k = 0; k < groups(); ++k) {
        const std::uint32_t a = cs_.starts[k], b = cs_.starts[k + 1];
        switch (op.kind) {
        case ListOpKind::KeepFirst: {
            const std::uint64_t from = wholeCount(groupValue(op.expr[1], k)), amount = wholeCount(groupValue(op.expr[0], k));
            lists::amountFilter(b - a, from, amount, cs_.order, cs_.part);
            for (std::uint32_t p : cs_.order) cs_.kept.push_back(a + p);
            for (std::uint32_t p : cs_.part) cs_.rest.push_back(a + p);
            break;
        }
        case ListOpKind::Where:
            for (std::uint32_t e = a; e < b; ++e) {
                const float v = entityValue(op.expr[0], e);
                (v > 0.0f || v < 0.0f ? cs_.kept : cs_.rest).push_back(e);  // 0 and NaN are false
            }
            break;
        default:  // Each
            for (std::uint32_t e = a; e < b; ++e) cs_.kept.push_back(e);
        }
        cs_.keptStarts.push_back(std::uint32_t(cs_.kept.size()));
        cs_.restStarts.push_back(std::uint32_t(cs_.rest.size()));
    }
    cs_.storedFrame.assign(frameFloats_ == 0 ? 0 : cs_.localFrames.size() / frameFloats_, kNone);
    pushRouted(op, 1, cs_.rest, cs_.restStarts);
    pushRouted(op, 0, cs_.kept, cs_.keptStarts);
}

/// One task per entity at `positions` (group k's are [starts[k], starts[k + 1])), running
/// successor `successor` of the route on its scope with its let values, last first so that the
/// first runs first. Its piece.index / piece.count: its place among its group's; its piece key:
/// its place among all of them, for this successor of this gather (so that two gathers of one
/// invocation never give two entities the same `per piece` draws).
void GatherRun::pushRouted(const ListOp& op, int successor, const std::vector<std::uint32_t>& positions,
                           const std::vector<std::uint32_t>& starts) {
    const std::uint32_t begin = op.begin[successor], end = op.end[successor];
    if (begin == end) return;  // nil
    std::uint32_t group = groups();
    for (auto k = std::uint32_t(positions.size()); k-- > 0;) {
        while (k < starts[group - 1]) --group;  // entity k is in group - 1
        const std::uint32_t e = positions[k];
        scratch_.scopes.push_back(list_->scopes[e]);
        const auto at = std::uint32_t(scratch_.scopes.size() - 1);
        PieceMark mark = marker_.mark;
        if (g_.usesPieceKeys) mark.key = pieceKey(marker_.mark.key, 2 * marker_.statement + std::uint32_t(successor), k);
        if (g_.usesPiecePlaces) mark.place = piecePlace(k - starts[group - 1], starts[group] - starts[group - 1]);
        if (list_->width > 0) mark.carried = std::uint32_t(list_->values[e]);
        std::uint32_t frame = DeriveScratch::kNoFrame;
        if (frameFloats_ > 0) {
            std::uint32_t& stored = cs_.storedFrame[cs_.frameOf[e]];
            if (stored == kNone)
                stored = storeFrame(scratch_.frames, cs_.localFrames.data() + std::size_t(cs_.frameOf[e]) * frameFloats_, frameFloats_);
            frame = stored;
        }
        scratch_.stack.push_back({marker_.gene, begin, end, at, marker_.parent, frame, mark});
    }
}
}  // namespace

void runGather(const Grammar& g, const Rule& r, const DeriveScratch::Task& marker, float* params, float* evalStack,
               DeriveScratch& scratch) {
    Collections& cs = scratch.collections;
    const Gather& gather = g.gathers[marker.statement];
    GatherRun run(g, r, marker, params, evalStack, scratch);
    const ListOp* ops = g.listOps.data() + gather.firstOp;
    for (std::uint32_t i = 0; i + 1 < gather.ops; ++i) run.step(ops, i);
    --cs.open;  // closed: its entities stay readable until a collection opens at its depth
    run.route(ops[gather.ops - 1]);
}

void openCollections(const Grammar& g, const Statement& st, const DeriveScratch::Task& task, const Scope& s,
                     std::uint32_t frame, DeriveScratch& scratch) {
    scratch.scopes.push_back(s);
    const auto at = std::uint32_t(scratch.scopes.size() - 1);
    for (std::uint32_t k = st.end; k-- > 0;) {
        const std::uint32_t gather = st.slot + k;
        scratch.collections.push(g.gathers[gather].list, gather, frame, g.carries() ? 1 : 0);
        scratch.stack.push_back({task.gene, gather, DeriveScratch::kGatherMarker, at, task.parent, frame, task.mark});
    }
}

bool sendScope(Collections& collections, const Statement& st, const Scope& s, std::uint32_t carried) {
    Collection* c = collections.innermost(st.slot);
    if (c == nullptr || c->entities.size() >= kMaxListEntities) return false;
    c->entities.scopes.push_back(s);
    if (c->entities.width > 0) c->entities.values.push_back(double(carried));  // attribute 0: its carried block
    return true;
}

void runGatherMarker(const Grammar& g, const Chromosome& c, const DeriveScratch::Task& marker, float* params,
                     float* evalStack, DeriveScratch& scratch) {
    const Rule& r = g.rules[c.rule(marker.gene)];
    const Collection& open = scratch.collections.pool[scratch.collections.open - 1];
    loadGeneAndFrame(r, c, marker.gene, scratch.frames, open.frame, params);
    loadPieceMark(g, marker.mark, params);
    if (g.carries()) loadCarried(g, scratch.carried, marker.mark.carried, params);
    runGather(g, r, marker, params, evalStack, scratch);
}

}  // namespace shapevo

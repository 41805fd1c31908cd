// Matcher: anchored, incremental subgraph matching (matcher.hpp).
#include "graph/matcher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "base/input_error.hpp"
#include "graph/lineage_key.hpp"

namespace shapevo::graph {

namespace {
constexpr std::uint32_t kUnranked = std::numeric_limits<std::uint32_t>::max();
}

Matcher::Matcher(const GraphGrammar& grammar, const HostGraph& graph, const std::vector<Value>& globals, DrawSource& draws,
                 const MatchBudget& budget, bool fixGeometricOrdering)
    : grammar_(grammar), graph_(graph), draws_(draws), budget_(budget), fixGeometricOrdering_(fixGeometricOrdering), keyed_(draws.keyed()) {
    clocks_.assign(grammar.productions.size(), 0.0);
    conditionFrame_.resize(2 + globals.size());
    std::copy(globals.begin(), globals.end(), conditionFrame_.begin() + 2);
    productions_.resize(grammar.productions.size());
    for (std::size_t p = 0; p < productions_.size(); ++p) {
        const Production& production = grammar.productions[p];
        PerProduction& pp = productions_[p];
        pp.vertexCount = production.motherVertices.size();
        pp.edgeCount = production.motherEdges.size();
        // Each mother vertex's rank along x and along y (stable: ties in file order).
        for (int axis = 0; axis < 2; ++axis) {
            auto coordinate = [&](std::size_t i) {
                const Vec2 q = production.motherVertices[i].position;
                return axis == 0 ? q.x : q.y;
            };
            std::vector<std::size_t> order(pp.vertexCount);
            std::iota(order.begin(), order.end(), std::size_t(0));
            std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return coordinate(a) < coordinate(b); });
            pp.axisRanks[std::size_t(axis)].resize(pp.vertexCount);
            for (std::size_t r = 0; r < order.size(); ++r) pp.axisRanks[std::size_t(axis)][order[r]] = std::uint32_t(r);
        }
        if (production.geometricOrdering) {
            EvaluationFrame frame{globals.data(), globals.size(), &grammar.names, &draws};
            try {
                pp.geometric = truthy(production.geometricOrdering->evaluate(frame));
            } catch (const EvaluationError& e) {
                throw InputError(grammar.path, "", "production '" + shortened(production.name) + "', .geometric_ordering: " + e.what());
            }
        }
    }
    buildPlans();
}

void Matcher::buildPlans() {
    for (std::size_t p = 0; p < productions_.size(); ++p) {
        const Production& production = grammar_.productions[p];
        PerProduction& pp = productions_[p];
        const int nv = int(pp.vertexCount), ne = int(pp.edgeCount);
        for (int anchor = 0; anchor < nv + ne; ++anchor) {
            std::vector<char> boundV(std::size_t(nv), 0), boundE(std::size_t(ne), 0);
            std::vector<int> edgeOrder;
            if (anchor < nv) boundV[std::size_t(anchor)] = 1;
            else boundE[std::size_t(anchor - nv)] = 1, edgeOrder.push_back(anchor - nv);
            std::vector<Step> plan;
            for (;;) {
                bool added = false;
                for (int j : edgeOrder) {
                    const MotherEdge& e = production.motherEdges[std::size_t(j)];
                    for (int end = 0; end < 2 && !added; ++end) {
                        const int u = end == 0 ? e.vertex1 : e.vertex2;
                        if (u >= 0 && !boundV[std::size_t(u)]) {
                            plan.push_back({Step::VertexAtEdgeEnd, u, j, end});
                            boundV[std::size_t(u)] = 1;
                            added = true;
                        }
                    }
                    if (added) break;
                }
                if (added) continue;
                for (int j = 0; j < ne && !added; ++j) {
                    if (boundE[std::size_t(j)]) continue;
                    const MotherEdge& e = production.motherEdges[std::size_t(j)];
                    for (int end = 0; end < 2 && !added; ++end) {
                        const int u = end == 0 ? e.vertex1 : e.vertex2;
                        if (u >= 0 && boundV[std::size_t(u)]) {
                            plan.push_back({Step::EdgeAtVertex, j, u, end});
                            boundE[std::size_t(j)] = 1;
                            edgeOrder.push_back(j);
                            added = true;
                        }
                    }
                }
                if (added) continue;
                for (int u = 0; u < nv && !added; ++u)
                    if (!boundV[std::size_t(u)]) {
                        plan.push_back({Step::AnyVertex, u, 0, 0});
                        boundV[std::size_t(u)] = 1;
                        added = true;
                    }
                if (added) continue;
                for (int j = 0; j < ne && !added; ++j)
                    if (!boundE[std::size_t(j)]) {  // both ends dangling (an end that is a vertex is bound by now)
                        plan.push_back({Step::AnyEdge, j, 0, 0});
                        boundE[std::size_t(j)] = 1;
                        edgeOrder.push_back(j);
                        added = true;
                    }
                if (!added) break;
            }
            pp.plans.push_back(std::move(plan));
        }
    }
}

bool Matcher::conditionsHold(const std::vector<MatchCondition>& conditions, const AttrMap& attrs, ElementRef element,
                             const Production& production) {
    for (const MatchCondition& c : conditions) {
        const Value* value = attrs.find(c.key);
        if (!value) return false;  // the host element must have the key
        conditionFrame_[0] = *value;
        conditionFrame_[1] = Value(element);
        const EvaluationFrame frame{conditionFrame_.data(), conditionFrame_.size(), &grammar_.names, &draws_};
        try {
            if (!truthy(c.test.evaluate(frame))) return false;
        } catch (const MissingKeyError&) {
            return false;
        } catch (const EvaluationError& e) {
            throw InputError(grammar_.path, std::to_string(c.place.line) + ":" + std::to_string(c.place.column),
                             "production '" + shortened(production.name) + "', condition on '" + shortened(grammar_.names.name(c.key)) + "': " + e.what());
        }
    }
    return true;
}

void Matcher::countSearchStep(std::size_t p) {
    if (++searchSteps_ > budget_.maxSearchSteps)
        throw InputError(grammar_.path, "", "production '" + shortened(grammar_.productions[p].name) + "': matching tried more than " +
                                                std::to_string(budget_.maxSearchSteps) +
                                                " element bindings in one step, the search budget (a mother graph of many "
                                                "unconstrained vertices matches in combinatorially many ways); give its vertices "
                                                "conditions or edges, or raise the budget");
}

bool Matcher::vertexFits(std::size_t p, int mother, ElementId host) {
    countSearchStep(p);
    const HostVertex& v = graph_.vertex(host);
    if (!v.alive || vertexRank_[host] < currentRank_) return false;  // found from an earlier changed element
    for (ElementId b : boundVertices_)
        if (b == host) return false;
    const MotherVertex& m = grammar_.productions[p].motherVertices[std::size_t(mother)];
    if (keyed_ && !m.conditions.empty()) enterConditionContext(p, v.key, v.seed, v.birth);
    return conditionsHold(m.conditions, v.attrs, ElementRef{&v.attrs, true, v.position}, grammar_.productions[p]);
}

bool Matcher::edgeFits(std::size_t p, int mother, ElementId host, std::uint8_t swapped) {
    countSearchStep(p);
    const HostEdge& h = graph_.edge(host);
    if (!h.alive || edgeRank_[host] < currentRank_) return false;
    const MotherEdge& m = grammar_.productions[p].motherEdges[std::size_t(mother)];
    if (swapped && (m.directed || h.vertex1 == h.vertex2 || (m.vertex1 < 0 && m.vertex2 < 0))) return false;
    for (ElementId b : boundEdges_)
        if (b == host) return false;
    for (int end = 0; end < 2; ++end) {
        const int u = end == 0 ? m.vertex1 : m.vertex2;
        if (u < 0) continue;
        const ElementId hv = (end ^ swapped) == 0 ? h.vertex1 : h.vertex2;
        if (hv == kNoVertex) return false;
        const ElementId bound = boundVertices_[std::size_t(u)];
        if (bound != kNoVertex && bound != hv) return false;
    }
    if (keyed_ && !m.conditions.empty()) enterConditionContext(p, h.key, h.seed, h.birth);
    return conditionsHold(m.conditions, h.attrs, ElementRef{&h.attrs, false, {}}, grammar_.productions[p]);
}

bool Matcher::geometricOrderHolds(std::size_t p) const {
    const PerProduction& pp = productions_[p];
    const std::size_t n = pp.vertexCount;
    for (int axis = 0; axis < 2; ++axis) {
        const std::vector<std::uint32_t>& rank = pp.axisRanks[std::size_t(axis)];
        auto host = [&](std::size_t i) {
            const Vec2 q = graph_.vertex(boundVertices_[i]).position;
            return axis == 0 ? q.x : q.y;
        };
        // Vertices mapped in file order; each compared with the nearest mapped one before it and
        // (the original's quirk) the farthest mapped one after it — or the nearest, when fixed.
        for (std::size_t k = 1; k < n; ++k) {
            std::size_t before = n, after = n;
            for (std::size_t w = 0; w < k; ++w) {
                if (rank[w] < rank[k]) {
                    if (before == n || rank[w] > rank[before]) before = w;
                } else if (after == n || (fixGeometricOrdering_ ? rank[w] < rank[after] : rank[w] > rank[after])) {
                    after = w;
                }
            }
            if (before != n && host(before) > host(k)) return false;
            if (after != n && host(k) > host(after)) return false;
        }
    }
    return true;
}

void Matcher::record(std::size_t p, std::uint32_t rank) {
    PerProduction& pp = productions_[p];
    std::int64_t generations = 0;
    for (ElementId v : boundVertices_) {
        if (vertexRank_[v] < rank) return;  // found from an element that changed earlier
        generations += graph_.vertex(v).generation;
    }
    for (ElementId e : boundEdges_) {
        if (edgeRank_[e] < rank) return;
        generations += graph_.edge(e).generation;
    }
    const Production& production = grammar_.productions[p];
    for (std::size_t j = 0; j < pp.edgeCount; ++j) {  // a mother loop needs a host loop
        const MotherEdge& m = production.motherEdges[j];
        const HostEdge& h = graph_.edge(boundEdges_[j]);
        const ElementId ends[2] = {boundSwapped_[j] ? h.vertex2 : h.vertex1, boundSwapped_[j] ? h.vertex1 : h.vertex2};
        if ((m.vertex1 >= 0 && ends[0] != boundVertices_[std::size_t(m.vertex1)]) ||
            (m.vertex2 >= 0 && ends[1] != boundVertices_[std::size_t(m.vertex2)]))
            return;
    }
    if (pp.geometric && !geometricOrderHolds(p)) return;
    if (pp.all.size() >= budget_.maxMatches)
        throw InputError(grammar_.path, "", "production '" + shortened(production.name) + "' has more than " + std::to_string(budget_.maxMatches) +
                                                " matches at once (a mother graph of unconstrained vertices matches in combinatorially "
                                                "many ways); give its vertices conditions or edges, or raise the budget");
    std::uint32_t slot;
    if (!pp.freeSlots.empty()) {
        slot = pp.freeSlots.back();
        pp.freeSlots.pop_back();
    } else {
        slot = std::uint32_t(pp.stored.size());
        pp.stored.emplace_back();
        pp.images.resize(pp.images.size() + pp.vertexCount + pp.edgeCount);
        pp.swapped.resize(pp.swapped.size() + pp.edgeCount);
    }
    Stored& s = pp.stored[slot];
    s.alive = true;
    ++s.serial;
    s.generationSum = generations;
    ElementId* images = pp.images.data() + std::size_t(slot) * (pp.vertexCount + pp.edgeCount);
    std::copy(boundVertices_.begin(), boundVertices_.end(), images);
    std::copy(boundEdges_.begin(), boundEdges_.end(), images + pp.vertexCount);
    std::copy(boundSwapped_.begin(), boundSwapped_.end(), pp.swapped.begin() + std::ptrdiff_t(std::size_t(slot) * pp.edgeCount));
    if (keyed_) keyMatch(p, s);
    s.positionInAll = std::uint32_t(pp.all.size());
    pp.all.push_back(slot);
    std::vector<std::uint32_t>& bucket = pp.buckets[generations];
    s.positionInBucket = std::uint32_t(bucket.size());
    bucket.push_back(slot);
    const SlotRef ref{std::uint32_t(p), slot, s.serial, kUnranked};
    for (ElementId v : boundVertices_) link(vertexMatches_, v, ref);
    for (ElementId e : boundEdges_) link(edgeMatches_, e, ref);
}

void Matcher::remove(std::size_t p, std::uint32_t slot) {
    PerProduction& pp = productions_[p];
    Stored& s = pp.stored[slot];
    const std::uint32_t last = pp.all.back();
    pp.all[s.positionInAll] = last;
    pp.stored[last].positionInAll = s.positionInAll;
    pp.all.pop_back();
    const auto bucketIt = pp.buckets.find(s.generationSum);
    std::vector<std::uint32_t>& bucket = bucketIt->second;
    const std::uint32_t lastInBucket = bucket.back();
    bucket[s.positionInBucket] = lastInBucket;
    pp.stored[lastInBucket].positionInBucket = s.positionInBucket;
    bucket.pop_back();
    if (bucket.empty()) pp.buckets.erase(bucketIt);
    s.alive = false;
    pp.freeSlots.push_back(slot);
}

void Matcher::link(std::vector<std::uint32_t>& heads, ElementId id, const SlotRef& ref) {
    links_.push_back(ref);
    links_.back().next = heads[id];
    heads[id] = std::uint32_t(links_.size() - 1);
}

void Matcher::dropMatchesOf(std::vector<std::uint32_t>& heads, ElementId id) {
    if (id >= heads.size()) return;
    for (std::uint32_t i = heads[id]; i != kUnranked; i = links_[i].next) {
        const SlotRef& r = links_[i];
        const Stored& s = productions_[r.production].stored[r.slot];
        if (s.alive && s.serial == r.serial) remove(r.production, r.slot);
    }
    heads[id] = kUnranked;
}

bool Matcher::extend(std::size_t p, const std::vector<Step>& plan, std::size_t step, std::uint32_t rank) {
    if (step == plan.size()) {
        record(p, rank);
        return true;
    }
    const Step& s = plan[step];
    switch (s.kind) {
        case Step::VertexAtEdgeEnd: {
            const HostEdge& h = graph_.edge(boundEdges_[std::size_t(s.via)]);
            const ElementId hv = (s.end ^ boundSwapped_[std::size_t(s.via)]) == 0 ? h.vertex1 : h.vertex2;
            if (hv == kNoVertex || !vertexFits(p, s.mother, hv)) return false;
            boundVertices_[std::size_t(s.mother)] = hv;
            extend(p, plan, step + 1, rank);
            boundVertices_[std::size_t(s.mother)] = kNoVertex;
            return true;
        }
        case Step::EdgeAtVertex: {
            const ElementId hv = boundVertices_[std::size_t(s.via)];
            const std::vector<ElementId>& incident = graph_.vertex(hv).edges;
            for (std::size_t i = 0; i < incident.size(); ++i) {
                const ElementId e = incident[i];
                const HostEdge& h = graph_.edge(e);
                for (std::uint8_t swapped = 0; swapped < 2; ++swapped) {
                    const ElementId atEnd = (s.end ^ swapped) == 0 ? h.vertex1 : h.vertex2;
                    if (atEnd != hv || !edgeFits(p, s.mother, e, swapped)) continue;
                    boundEdges_[std::size_t(s.mother)] = e;
                    boundSwapped_[std::size_t(s.mother)] = swapped;
                    extend(p, plan, step + 1, rank);
                    boundEdges_[std::size_t(s.mother)] = kNoVertex;
                }
            }
            return true;
        }
        case Step::AnyVertex: {
            const std::size_t n = graph_.vertices().size();
            for (ElementId v = 0; v < n; ++v) {
                if (!graph_.vertex(v).alive || !vertexFits(p, s.mother, v)) continue;
                boundVertices_[std::size_t(s.mother)] = v;
                extend(p, plan, step + 1, rank);
                boundVertices_[std::size_t(s.mother)] = kNoVertex;
            }
            return true;
        }
        case Step::AnyEdge: {
            const std::size_t n = graph_.edges().size();
            for (ElementId e = 0; e < n; ++e)
                for (std::uint8_t swapped = 0; swapped < 2; ++swapped) {
                    if (!graph_.edge(e).alive || !edgeFits(p, s.mother, e, swapped)) continue;
                    boundEdges_[std::size_t(s.mother)] = e;
                    boundSwapped_[std::size_t(s.mother)] = swapped;
                    extend(p, plan, step + 1, rank);
                    boundEdges_[std::size_t(s.mother)] = kNoVertex;
                }
            return true;
        }
    }
    return false;
}

void Matcher::searchFrom(bool isVertex, ElementId anchor, std::uint32_t rank) {
    currentRank_ = rank;
    for (std::size_t p = 0; p < productions_.size(); ++p) {
        PerProduction& pp = productions_[p];
        if ((isVertex ? pp.vertexCount : pp.edgeCount) == 0) continue;
        boundVertices_.assign(pp.vertexCount, kNoVertex);
        boundEdges_.assign(pp.edgeCount, kNoVertex);
        boundSwapped_.assign(pp.edgeCount, 0);
        if (isVertex) {
            for (std::size_t m = 0; m < pp.vertexCount; ++m) {
                if (!vertexFits(p, int(m), anchor)) continue;
                boundVertices_[m] = anchor;
                extend(p, pp.plans[m], 0, rank);
                boundVertices_[m] = kNoVertex;
            }
        } else {
            for (std::size_t m = 0; m < pp.edgeCount; ++m)
                for (std::uint8_t swapped = 0; swapped < 2; ++swapped) {
                    if (!edgeFits(p, int(m), anchor, swapped)) continue;
                    boundEdges_[m] = anchor;
                    boundSwapped_[m] = swapped;
                    extend(p, pp.plans[pp.vertexCount + m], 0, rank);
                    boundEdges_[m] = kNoVertex;
                }
        }
    }
}

void Matcher::initialize() {
    std::vector<ElementId> vertices, edges;
    for (ElementId v = 0; v < graph_.vertices().size(); ++v)
        if (graph_.vertex(v).alive) vertices.push_back(v);
    for (ElementId e = 0; e < graph_.edges().size(); ++e)
        if (graph_.edge(e).alive) edges.push_back(e);
    update(vertices, edges);
}

void Matcher::update(const std::vector<ElementId>& changedVertices, const std::vector<ElementId>& changedEdges) {
    vertexMatches_.resize(graph_.vertices().size(), kUnranked);
    edgeMatches_.resize(graph_.edges().size(), kUnranked);
    vertexRank_.resize(graph_.vertices().size(), kUnranked);
    edgeRank_.resize(graph_.edges().size(), kUnranked);
    for (ElementId v : changedVertices) dropMatchesOf(vertexMatches_, v);
    for (ElementId e : changedEdges) dropMatchesOf(edgeMatches_, e);
    // Ranks: vertices first, then edges, each in the order given (first occurrence).
    std::uint32_t rank = 0;
    for (ElementId v : changedVertices)
        if (vertexRank_[v] == kUnranked) vertexRank_[v] = rank++;
    for (ElementId e : changedEdges)
        if (edgeRank_[e] == kUnranked) edgeRank_[e] = rank++;
    searchSteps_ = 0;
    for (ElementId v : changedVertices)
        if (graph_.vertex(v).alive && vertexRank_[v] != kUnranked) searchFrom(true, v, vertexRank_[v]);
    for (ElementId e : changedEdges)
        if (graph_.edge(e).alive && edgeRank_[e] != kUnranked) searchFrom(false, e, edgeRank_[e]);
    for (ElementId v : changedVertices) vertexRank_[v] = kUnranked;
    for (ElementId e : changedEdges) edgeRank_[e] = kUnranked;
}

void Matcher::enterConditionContext(std::size_t p, std::uint64_t elementKey, std::uint64_t seed, std::uint32_t birth) {
    draws_.enterContext(mixKey(mixKey(key_tag::kCondition, elementKey), p), DrawContext{seed, birth});
}

void Matcher::keyMatch(std::size_t p, Stored& s) {
    // The key names the production, what each mother element maps to and how each edge lies.
    // The match belongs to its youngest element's event (the first of the youngest on ties).
    std::uint64_t key = mixKey(key_tag::kMatch, p);
    std::uint64_t seed = 0;
    std::uint32_t birth = 0;
    bool first = true;
    auto take = [&](std::uint64_t elementKey, std::uint64_t elementSeed, std::uint32_t elementBirth) {
        key = mixKey(key, elementKey);
        if (first || elementBirth > birth) seed = elementSeed, birth = elementBirth;
        first = false;
    };
    for (ElementId v : boundVertices_) take(graph_.vertex(v).key, graph_.vertex(v).seed, graph_.vertex(v).birth);
    for (std::size_t j = 0; j < boundEdges_.size(); ++j) {
        const HostEdge& e = graph_.edge(boundEdges_[j]);
        take(e.key, e.seed, e.birth);
        key = mixKey(key, boundSwapped_[j]);
    }
    if (first) seed = draws_.rootSeed();  // an empty mother graph
    s.key = key;
    const std::uint64_t w = draws_.word(mixKey(mixKey(key, firings(key)), key_tag::kFire), DrawContext{seed, birth}, DrawPurpose::Match);
    s.level = clocks_[p] - std::log1p(-wordUniform(w));  // an exponential draw of mean 1
}

std::uint32_t Matcher::earliest(std::size_t p) const {
    const PerProduction& pp = productions_[p];
    std::uint32_t best = pp.all.front();
    for (std::uint32_t slot : pp.all) {
        const Stored& a = pp.stored[slot];
        const Stored& b = pp.stored[best];
        if (a.level < b.level || (a.level == b.level && (a.key < b.key || (a.key == b.key && slot < best)))) best = slot;
    }
    return best;
}

MatchView Matcher::view(std::size_t p, std::uint32_t slot) const {
    const PerProduction& pp = productions_[p];
    const ElementId* images = pp.images.data() + std::size_t(slot) * (pp.vertexCount + pp.edgeCount);
    return MatchView{images, images + pp.vertexCount, pp.swapped.data() + std::size_t(slot) * pp.edgeCount, pp.stored[slot].generationSum};
}

MatchView Matcher::match(std::size_t p, std::size_t i) const { return view(p, productions_[p].all[i]); }

std::size_t Matcher::oldestCount(std::size_t p) const {
    const PerProduction& pp = productions_[p];
    return pp.buckets.empty() ? 0 : pp.buckets.begin()->second.size();
}

MatchView Matcher::oldest(std::size_t p, std::size_t i) const { return view(p, productions_[p].buckets.begin()->second[i]); }

}  // namespace shapevo::graph

// group by and ungroup (grouping.hpp): a sort of positions by key (ties by position), one sweep for
// the runs of equal keys, then groups numbered by their first position. No hashing, no unordered
// container: the groups' order is the list's.
#include "geometry/lists/grouping.hpp"

#include <algorithm>
#include <cmath>

namespace shapevo::lists {
namespace {

/// Key order for grouping: numbers ascending, -0 == +0, NaN after numbers and equal to NaN.
int compareGroupKey(double a, double b) {
    const bool nanA = std::isnan(a), nanB = std::isnan(b);
    if (nanA || nanB) return nanA == nanB ? 0 : (nanA ? 1 : -1);
    return a < b ? -1 : (b < a ? 1 : 0);
}

}  // namespace

void groupFromLabels(std::span<const std::uint32_t> labels, std::uint32_t groupCount, Grouping& out, ListWorkspace& ws) {
    const std::uint32_t n = std::uint32_t(labels.size());
    constexpr std::uint32_t kUnset = ~0u;
    // Relabel in order of first appearance.
    ws.counts.assign(groupCount, kUnset);
    std::uint32_t next = 0;
    out.groupOf.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        std::uint32_t& id = ws.counts[labels[i]];
        if (id == kUnset) id = next++;
        out.groupOf[i] = id;
    }
    // Counting sort by group, positions ascending within each.
    out.starts.assign(next + 1, 0);
    for (std::uint32_t i = 0; i < n; ++i) ++out.starts[out.groupOf[i] + 1];
    for (std::uint32_t g = 0; g < next; ++g) out.starts[g + 1] += out.starts[g];
    ws.indices2.assign(out.starts.begin(), out.starts.end() - (next ? 1 : 0));
    out.members.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) out.members[ws.indices2[out.groupOf[i]]++] = i;
}

void groupBy(std::span<const double> keys, std::uint32_t keyCount, Grouping& out, ListWorkspace& ws) {
    const std::uint32_t n = keyCount == 0 ? 0 : std::uint32_t(keys.size() / keyCount);
    auto compare = [&](std::uint32_t a, std::uint32_t b) {
        for (std::uint32_t k = 0; k < keyCount; ++k)
            if (const int c = compareGroupKey(keys[std::size_t(a) * keyCount + k], keys[std::size_t(b) * keyCount + k])) return c;
        return 0;
    };
    ws.indices.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) ws.indices[i] = i;
    std::sort(ws.indices.begin(), ws.indices.end(), [&](std::uint32_t a, std::uint32_t b) {
        const int c = compare(a, b);
        return c != 0 ? c < 0 : a < b;
    });
    // Runs of equal keys get labels (in key order; groupFromLabels renumbers by first appearance).
    ws.labels.resize(n);
    std::uint32_t runs = 0;
    for (std::uint32_t j = 0; j < n; ++j) {
        if (j > 0 && compare(ws.indices[j - 1], ws.indices[j]) != 0) ++runs;
        ws.labels[ws.indices[j]] = runs;
    }
    groupFromLabels(ws.labels, n == 0 ? 0 : runs + 1, out, ws);
}

void ungroupEntities(const EntityList& grouped, const Grouping& grouping, EntityList& out) {
    const std::uint32_t n = grouped.size();
    out.width = grouped.width;
    out.scopes.resize(n);
    out.values.resize(std::size_t(n) * grouped.width);
    for (std::uint32_t j = 0; j < n; ++j) {
        const std::uint32_t position = grouping.members[j];
        out.scopes[position] = grouped.scopes[j];
        const std::span<const double> from = grouped.attributes(j);
        std::copy(from.begin(), from.end(), out.attributes(position).begin());
    }
}

}  // namespace shapevo::lists

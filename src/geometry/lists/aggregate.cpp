// min / max / avg / sum, left to right (aggregate.hpp). One accumulator per kind, fed in list order.
#include "geometry/lists/aggregate.hpp"

#include <cmath>
#include <limits>

namespace shapevo::lists {
namespace {

/// One scalar aggregate, fed value by value in list order.
struct ScalarAccumulator {
    Aggregate kind;
    double value = kind == Aggregate::Sum || kind == Aggregate::Avg ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    std::uint64_t n = 0;

    void add(double v) {
        ++n;
        switch (kind) {
        case Aggregate::Sum:
        case Aggregate::Avg: value = value + v; break;
        case Aggregate::Min: if (!std::isnan(v) && (std::isnan(value) || v < value)) value = v; break;
        case Aggregate::Max: if (!std::isnan(v) && (std::isnan(value) || v > value)) value = v; break;
        }
    }
    double result() const {
        if (kind != Aggregate::Avg) return value;
        return n == 0 ? std::numeric_limits<double>::quiet_NaN() : value / double(n);
    }
};

template <class Values, class Index>
double aggregateScalar(Aggregate kind, const Values& values, std::size_t n, Index at) {
    ScalarAccumulator acc{kind};
    for (std::size_t j = 0; j < n; ++j) acc.add(values[at(j)]);
    return acc.result();
}

template <class Index>
glm::dvec3 aggregateVector(Aggregate kind, std::span<const glm::dvec3> values, std::size_t n, Index at) {
    ScalarAccumulator x{kind}, y{kind}, z{kind};
    for (std::size_t j = 0; j < n; ++j) {
        const glm::dvec3& v = values[at(j)];
        x.add(v.x);
        y.add(v.y);
        z.add(v.z);
    }
    return {x.result(), y.result(), z.result()};
}

}  // namespace

double aggregate(Aggregate kind, std::span<const double> values) {
    return aggregateScalar(kind, values, values.size(), [](std::size_t j) { return j; });
}

glm::dvec3 aggregate(Aggregate kind, std::span<const glm::dvec3> values) {
    return aggregateVector(kind, values, values.size(), [](std::size_t j) { return j; });
}

void aggregateGroups(Aggregate kind, std::span<const double> values, const Grouping& groups, std::span<double> out) {
    for (std::uint32_t g = 0; g < groups.count(); ++g) {
        const std::span<const std::uint32_t> m = groups.group(g);
        out[g] = aggregateScalar(kind, values, m.size(), [&](std::size_t j) { return m[j]; });
    }
}

void aggregateGroups(Aggregate kind, std::span<const glm::dvec3> values, const Grouping& groups, std::span<glm::dvec3> out) {
    for (std::uint32_t g = 0; g < groups.count(); ++g) {
        const std::span<const std::uint32_t> m = groups.group(g);
        out[g] = aggregateVector(kind, values, m.size(), [&](std::size_t j) { return m[j]; });
    }
}

}  // namespace shapevo::lists

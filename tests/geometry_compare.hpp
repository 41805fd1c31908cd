// identical(a, b): two derived geometries hold the same primitives and looks bit for bit (for the
// derive tests: a memo, a scratch reused or a second derivation must change nothing); and
// deriveComplete(g, c), a whole derivation that must be Complete; startParam(g, c, name), a
// parameter of the start gene by name.
#pragma once
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "geometry/derive.hpp"

namespace shapevo::test {

/// Bit-identical primitives and looks, field by field (the struct has padding bytes; the kind's
/// parameter block is compared as bytes).
/// The value of the start gene's parameter `name` in `c` (a test failure and 0 if there is none).
inline float startParam(const Grammar& g, const Chromosome& c, const std::string& name) {
    const Rule& r = g.rules[g.start];
    for (const Param& p : r.params)
        if (p.name == name) return c.param(0, r, p.first);
    ADD_FAILURE() << "no param " << name;
    return 0.0f;
}

/// `c` derived whole with a fresh scratch; the derivation must be Complete.
inline Geometry deriveComplete(const Grammar& g, const Chromosome& c) {
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
    return geo;
}

inline ::testing::AssertionResult identical(const Geometry& a, const Geometry& b) {
    if (a.primitives.size() != b.primitives.size())
        return ::testing::AssertionFailure() << a.primitives.size() << " primitives against " << b.primitives.size();
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        const Primitive &p = a.primitives[i], &q = b.primitives[i];
        if (p.kind != q.kind || !(p.params == q.params) || std::memcmp(&p.centre, &q.centre, sizeof p.centre) != 0 ||
            std::memcmp(&p.axes, &q.axes, sizeof p.axes) != 0 || std::memcmp(&p.half, &q.half, sizeof p.half) != 0)
            return ::testing::AssertionFailure() << "primitive " << i << " differs";
    }
    if (!(a.appearance == b.appearance)) return ::testing::AssertionFailure() << "looks differ";
    return ::testing::AssertionSuccess();
}

}  // namespace shapevo::test

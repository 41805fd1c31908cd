// identical(a, b): two derived geometries hold the same primitives and looks bit for bit (for the
// derive tests: a memo, a scratch reused or a second derivation must change nothing); and
// deriveComplete(g, c), a whole derivation that must be Complete.
#pragma once
#include <gtest/gtest.h>

#include <cstring>

#include "geometry/derive.hpp"

namespace shapevo::test {

/// Bit-identical primitives and looks, field by field (the struct has padding bytes; the kind's
/// parameter block is compared as bytes).
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

// What the gather tests share (tests/geometry/gather_*_test.cpp): a grammar whose start rule
// makes n boxes side by side, each of its own random height and depth, sends them to a list and
// gathers it; the reference grammar that emits every box instead; and brute-force helpers that
// compare the boxes.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "../geometry_compare.hpp"
#include "base/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo::gather_test {

/// Rule S makes n boxes side by side, each of its own random height (a `per piece` parameter);
/// ITEM is what each piece does, GATHER what S does after (the text of a gather or nothing).
inline std::string items(const std::string& item, const std::string& gather) {
    return "start S\n"
           "rule S {\n"
           "  param n = int(0, 24)\n"
           "  param k = int(0, 12)\n"
           "  param t = uniform(0.5, 4)\n"
           "  param u = uniform(0, 1)\n"
           "  size (30, 1, 1)\n"
           "  repeat x count n Item\n" +
           gather +
           "}\n"
           "rule Item {\n"
           "  param h = uniform(0.1, 5) per piece\n"
           "  param d = int(1, 3) per piece\n"
           "  size (scope.size.x, h, d)\n" +
           item + "\n}\n";
}

inline Geometry deriveOne(const Grammar& g, const Chromosome& c) { return test::deriveComplete(g, c); }

/// The genome's parameter value `index` of the start gene.
inline float param(const Grammar& g, const Chromosome& c, int index) {
    return c.param(0, g.rules[g.start], std::uint16_t(index));
}

/// For `seeds` random genomes: the reference boxes (every item emits its box) and the gathered
/// model's boxes, handed to `check`.
template <class Check>
void forRandomGenomes(const std::string& gather, const std::string& route, int seeds, Check check) {
    const Grammar reference = parseGrammar(items("box", ""), "reference.grammar");
    const Grammar gathered = parseGrammar(items("send items", "  gather items {\n" + gather + "\n" + route + "\n  }\n"), "gathered.grammar");
    ASSERT_EQ(reference.rules[reference.start].geneWords(), gathered.rules[gathered.start].geneWords());
    for (int seed = 1; seed <= seeds; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(gathered, c, rng, 10));
        const Geometry all = deriveOne(reference, c), out = deriveOne(gathered, c);
        check(gathered, c, all.primitives, out.primitives, seed);
    }
}

inline bool sameBox(const Primitive& a, const Primitive& b) {
    Geometry x, y;
    x.primitives = {a};
    y.primitives = {b};
    return test::identical(x, y);
}

inline void expectBoxes(const std::vector<Primitive>& expected, const std::vector<Primitive>& got, int seed) {
    ASSERT_EQ(got.size(), expected.size()) << "seed " << seed;
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(sameBox(expected[i], got[i])) << "seed " << seed << " box " << i;
}

/// Stable order by (key 0 asc or desc, then key 1 ...), by brute force: insertion sort.
inline std::vector<Primitive> sortedBy(std::vector<Primitive> v, const std::vector<std::pair<float (*)(const Primitive&), bool>>& keys) {
    for (std::size_t i = 1; i < v.size(); ++i)
        for (std::size_t j = i; j > 0; --j) {
            int cmp = 0;
            for (const auto& [key, descending] : keys) {
                const float a = key(v[j - 1]), b = key(v[j]);
                if (a != b) {
                    cmp = (a < b) != descending ? -1 : 1;
                    break;
                }
            }
            if (cmp <= 0) break;
            std::swap(v[j - 1], v[j]);
        }
    return v;
}

inline float height(const Primitive& p) { return p.half.y * 2.0f; }
inline float depth(const Primitive& p) { return p.half.z * 2.0f; }
inline float x(const Primitive& p) { return p.centre.x; }

}  // namespace shapevo::gather_test

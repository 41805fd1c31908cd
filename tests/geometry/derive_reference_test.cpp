// Fast derive vs. the plain one: a straightforward derivation (every task carries its two scopes,
// every expression runs on the stack machine) is kept here, and derive must give the same
// primitives bit for bit on thousands of random chromosomes of every shipped grammar and of
// grammars with mirrors, terminal blocks, cones with `top`, roofs of every form, paraboloids,
// meshes and unusual expressions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/expression.hpp"
#include "grammar/front_ends.hpp"
#include "shape/kinds.hpp"

namespace shapevo {
namespace {

glm::mat3 referenceRotation(int axis, float degrees) {
    const float r = degrees * float(M_PI / 180.0), c = std::cos(r), s = std::sin(r);
    switch (axis) {
    case 0: return glm::mat3(1, 0, 0, 0, c, s, 0, -s, c);
    case 1: return glm::mat3(c, 0, -s, 0, 1, 0, s, 0, c);
    default: return glm::mat3(c, s, 0, -s, c, 0, 0, 0, 1);
    }
}

/// Every number of `p` finite and within kMaxCoordinate (axes too: with finite rotation angles
/// they always are), written plainly.
bool referenceBounded(const Primitive& p) {
    const float numbers[] = {p.centre.x, p.centre.y, p.centre.z, p.half.x, p.half.y, p.half.z,
                             p.axes[0].x, p.axes[0].y, p.axes[0].z, p.axes[1].x, p.axes[1].y, p.axes[1].z,
                             p.axes[2].x, p.axes[2].y, p.axes[2].z};
    for (float v : numbers)
        if (!std::isfinite(v) || std::fabs(v) > kMaxCoordinate) return false;
    return true;
}

/// The semantics of derive, written as plainly as possible.
DeriveStatus referenceDerive(const Grammar& g, const Chromosome& c, std::vector<Primitive>& out, std::size_t maxPrimitives) {
    struct Task {
        std::uint32_t gene, statement;
        Scope scope, parent;
    };
    out.clear();
    if (c.empty()) return DeriveStatus::Complete;
    std::vector<Task> stack{{0, 0, Scope{}, Scope{}}};
    std::vector<float> params(256);
    float evalStack[kMaxExpressionStack];
    std::size_t tasks = 0;
    while (!stack.empty()) {
        if (++tasks > 4 * maxPrimitives + 1024) return DeriveStatus::Truncated;
        const Task task = stack.back();
        stack.pop_back();
        const Rule& r = g.rules[c.rule(task.gene)];
        for (std::uint32_t i = 0; i < r.paramFloats; ++i) params[i] = c.param(task.gene, r, i);
        Scope s = task.scope, beforeTerminal;
        auto eval = [&](const ExprRef& e) {
            return evaluateProgram(g, e, params.data(), &s.size.x, &task.parent.size.x, evalStack);
        };
        for (std::uint32_t i = task.statement; i < r.statements.size(); ++i) {
            const Statement& st = r.statements[i];
            const auto vec = [&] { return glm::vec3(eval(st.expr[0]), eval(st.expr[1]), eval(st.expr[2])); };
            switch (st.kind) {
            case StatementKind::Scale: s.size *= vec(); break;
            case StatementKind::Size: s.size = vec(); break;
            case StatementKind::Translate: s.origin += s.axes * vec(); break;
            case StatementKind::Rotate: {
                const float degrees = eval(st.expr[0]);
                if (!std::isfinite(degrees)) return DeriveStatus::NonFinite;  // axes would not be finite
                s.axes = s.axes * referenceRotation(st.axis, degrees);
                break;
            }
            case StatementKind::Mirror: {
                Task mirrored{task.gene, i + 1, s, task.parent};
                mirrored.scope.axes[st.axis] = -mirrored.scope.axes[st.axis];
                stack.push_back(mirrored);
                break;
            }
            case StatementKind::TerminalBegin: {
                bool children = false;
                for (std::uint32_t k = 0; k < r.childOffsets; ++k) children |= c.child(task.gene, k) > 0;
                if (children) i = st.end;
                else beforeTerminal = s;
                break;
            }
            case StatementKind::TerminalEnd: s = beforeTerminal; break;
            case StatementKind::Child: {
                const Slot& slot = r.slots[st.slot];
                for (std::uint32_t k = slot.maxCount; k-- > 0;) {
                    const std::int32_t off = c.child(task.gene, slot.firstChild + k);
                    if (off > 0) stack.push_back({task.gene + std::uint32_t(off), 0, s, s});
                }
                break;
            }
            default: {
                if (out.size() >= maxPrimitives) return DeriveStatus::Truncated;
                Primitive p{st.primitive, {}, s.origin, s.axes, glm::abs(s.size) * 0.5f};
                if (st.primitive == PrimitiveKind::Cone) {
                    const float top = eval(st.expr[0]);
                    setParams<ConeKind>(p, {top >= 0.0f ? std::min(top, 1.0f) : 0.0f});
                } else if (st.primitive == PrimitiveKind::Mesh) {
                    setParams<MeshKind>(p, {st.slot});
                } else if (st.primitive == PrimitiveKind::Roof) {
                    // slot: 0 gable, 1 hip, 2 pyramid, 3 top (x, z); the ridge runs along the
                    // longer horizontal half extent, along x on a tie
                    const float hx = p.half.x, hz = p.half.z;
                    float tx = 0.0f, tz = 0.0f;
                    if (st.slot == 3) {
                        tx = eval(st.expr[0]);
                        tz = eval(st.expr[1]);
                    } else if (st.slot == 0) {
                        (hx >= hz ? tx : tz) = 1.0f;
                    } else if (st.slot == 1) {
                        if (hx >= hz) tx = 1.0f - hz / hx;
                        else tz = 1.0f - hx / hz;
                    }
                    setParams<RoofKind>(p, {std::isnan(tx) ? 0.0f : std::clamp(tx, 0.0f, 1.0f),
                                            std::isnan(tz) ? 0.0f : std::clamp(tz, 0.0f, 1.0f)});
                }
                if (!referenceBounded(p)) return DeriveStatus::NonFinite;
                out.push_back(p);
            }
            }
        }
    }
    return DeriveStatus::Complete;
}

/// Index of the first primitive that differs in any bit of any field, or -1 if none does.
long firstDifference(const std::vector<Primitive>& a, const std::vector<Primitive>& b) {
    for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
        if (i >= a.size() || i >= b.size()) return long(i);
        const Primitive &p = a[i], &q = b[i];
        if (p.kind != q.kind || !(p.params == q.params) || std::memcmp(&p.centre, &q.centre, sizeof p.centre) != 0 ||
            std::memcmp(&p.axes, &q.axes, sizeof p.axes) != 0 || std::memcmp(&p.half, &q.half, sizeof p.half) != 0)
            return long(i);
    }
    return -1;
}

/// Grow, alter and cut random chromosomes of `g` and compare derive with the reference on each.
void expectSameAsReference(const Grammar& g, int chromosomes, std::uint32_t maxGenes, std::uint64_t seed,
                           std::size_t maxPrimitives = 1u << 18) {
    Rng rng(seed);
    DeriveScratch scratch;  // reused: no stale state may leak between chromosomes
    GenomeScratch genomeScratch;
    Geometry fast;
    std::vector<Primitive> slow;
    std::size_t compared = 0;
    for (int n = 0; n < chromosomes; ++n) {
        Chromosome c;
        const std::uint32_t genes = 1 + std::uint32_t(rng.uniform() * double(maxGenes - 1));
        const GenomeLimits limits{genes};
        while (c.genes < genes && grow(g, c, rng, limits)) {
        }
        if (n % 3 == 1) alter(g, c, rng);
        if (n % 5 == 2) cut(g, c, rng, genomeScratch);
        const DeriveStatus a = derive(g, c, fast, scratch, maxPrimitives);
        const DeriveStatus b = referenceDerive(g, c, slow, maxPrimitives);
        ASSERT_EQ(a, b) << g.path << " chromosome " << n;
        ASSERT_EQ(firstDifference(fast.primitives, slow), -1) << g.path << " chromosome " << n << " of "
                                                               << c.genes << " genes";
        compared += slow.size();
    }
    EXPECT_GT(compared, std::size_t(chromosomes));  // the chromosomes did make geometry
}

TEST(DeriveReference, EveryShippedGrammarGivesTheReferenceGeometryBitForBit) {
    for (const char* name : {"tree", "coral", "spaceship", "city", "city-filling"}) {
        const Grammar g = loadGrammar(test::sourcePath(std::string("grammars/") + name + ".grammar"));
        expectSameAsReference(g, 1500, 120, 7);
    }
}

TEST(DeriveReference, MirrorsMeshesConesAndOddExpressionsGiveTheReferenceGeometry) {
    // mirrors before and after children and terminal blocks (nested by recursion),
    // cones with and without `top`, a mesh, negated numbers, parent sizes, min/max, division and
    // expressions too big for the small shapes (abs, sin, sqrt, floor, long sums).
    const std::string text = R"(
start A
attr k = 0.75
rule A {
  param a = uniform(-2, 2)
  param v = uniform((-1, 0.2, -1), (1, 2, 1))
  size (1, 2, 0.5)
  child B max 2
  mirror x
  translate (a, -0.25, v.z)
  rotate z a * 40
  cone top a
  child B prob 0.5 max 2
  mirror z
  child C prob 0.7
  terminal {
    scale v
    sphere
  }
  mirror y
  box
}
rule B {
  param t = uniform(-90, 270)
  param u = uniform(0.2, 1.5)
  rotate x t
  rotate y -t
  scale (u, parent.size.y * (u - 0.5), min(u, k))
  translate (0, (parent.size.y + scope.size.y) * 0.5, -scope.size.z / u)
  cylinder
  cone
  mirror x
  child A prob 0.3
  child B prob 0.4 max 2
  terminal {
    size (abs(t) * 0.01 + u, sin(t) * 2, sqrt(u) + floor(t / 100) - -1)
    mesh "meshes/leaf.obj"
    box
  }
}
rule C {
  param w = uniform(0.1, 2)
  size max(w, parent.size.x) / 2
  translate (-k, w - parent.size.x * k, 1 / (w + k))
  rotate y 30
  box
  child C prob 0.5
}
)";
    const Grammar g = parseGrammar(text, test::sourcePath("grammars/derive-reference.grammar"));
    ASSERT_EQ(g.meshes.size(), 1u);
    expectSameAsReference(g, 1500, 60, 11);
    expectSameAsReference(g, 300, 60, 12, 50);  // also where the primitive cap stops derivation
}

TEST(DeriveReference, RoofsOfEveryFormAndParaboloidsGiveTheReferenceGeometry) {
    // every roof form on scopes whose longer horizontal axis is x, z or neither, fractions from
    // parameters (out of range too), under mirrors and rotations
    const std::string text = R"(
start A
rule A {
  param w = uniform(0.2, 3)
  param d = choice(0.5, 1, 2)
  param t = uniform(-0.5, 1.5)
  size (w, 1, d)
  roof
  mirror x
  translate (w, 0, 0)
  roof hip
  rotate y t * 50
  roof top (t, 1 - t)
  child B prob 0.6 max 2
}
rule B {
  param s = uniform(0.3, 1.2)
  scale (s, 0.5, 1 / s)
  translate (0, parent.size.y, 0)
  roof gable
  paraboloid
  roof pyramid
  terminal {
    roof top (s * 0.5, s)
  }
  child A prob 0.3
}
)";
    const Grammar g = parseGrammar(text, "roofs.grammar");
    expectSameAsReference(g, 1000, 40, 13);
}

}  // namespace
}  // namespace shapevo

// derive: an explicit stack over (gene, statement, scope); `child` pushes the expressed children
// with the current scope, `mirror` pushes the rest of the rule again with one axis flipped.
#include "geometry/derive.hpp"

#include <algorithm>
#include <cmath>

#include "grammar/expression.hpp"

namespace shapevo {

namespace {
glm::mat3 axisRotation(int axis, float degrees) {
    const float r = degrees * float(M_PI / 180.0), c = std::cos(r), s = std::sin(r);
    switch (axis) {
    case 0: return glm::mat3(1, 0, 0, 0, c, s, 0, -s, c);
    case 1: return glm::mat3(c, 0, -s, 0, 1, 0, s, 0, c);
    default: return glm::mat3(c, s, 0, -s, c, 0, 0, 0, 1);
    }
}
PrimitiveKind primitiveKind(StatementKind k) {
    switch (k) {
    case StatementKind::Cylinder: return PrimitiveKind::Cylinder;
    case StatementKind::Cone: return PrimitiveKind::Cone;
    case StatementKind::Sphere: return PrimitiveKind::Sphere;
    case StatementKind::Mesh: return PrimitiveKind::Mesh;
    default: return PrimitiveKind::Box;
    }
}

bool hasChildren(const Chromosome& c, std::uint32_t gene, const Rule& r) {
    for (std::uint32_t k = 0; k < r.childOffsets; ++k)
        if (c.child(gene, k) > 0) return true;
    return false;
}
}  // namespace

bool derive(const Grammar& g, const Chromosome& c, Geometry& out, DeriveScratch& scratch, std::size_t maxPrimitives) {
    out.clear();
    out.meshes = &g.meshes;
    if (c.empty()) return true;
    auto& stack = scratch.stack;
    stack.clear();
    scratch.params.resize(256);
    float* params = scratch.params.data();
    float evalStack[kMaxExpressionStack];
    stack.push_back({0, 0, Scope{}, Scope{}});
    std::size_t tasks = 0;
    while (!stack.empty()) {
        if (++tasks > 4 * maxPrimitives + 1024) return false;  // mirrors without boxes multiply too
        const DeriveScratch::Task task = stack.back();
        stack.pop_back();
        const Rule& r = g.rules[c.rule(task.gene)];
        for (std::uint32_t i = 0; i < r.paramFloats; ++i) params[i] = c.param(task.gene, r, i);
        Scope s = task.scope, beforeTerminal;
        const float* parentSize = &task.parent.size.x;
        auto eval = [&](ExprRef e) { return evaluate(g, e, params, &s.size.x, parentSize, evalStack); };
        for (std::uint32_t i = task.statement; i < r.statements.size(); ++i) {
            const Statement& st = r.statements[i];
            switch (st.kind) {
            case StatementKind::Scale: {
                const glm::vec3 v(eval(st.expr[0]), eval(st.expr[1]), eval(st.expr[2]));
                s.size *= v;
                break;
            }
            case StatementKind::Size: {
                const glm::vec3 v(eval(st.expr[0]), eval(st.expr[1]), eval(st.expr[2]));
                s.size = v;
                break;
            }
            case StatementKind::Translate: {
                const glm::vec3 v(eval(st.expr[0]), eval(st.expr[1]), eval(st.expr[2]));
                s.origin += s.axes * v;
                break;
            }
            case StatementKind::Rotate: s.axes = s.axes * axisRotation(st.axis, eval(st.expr[0])); break;
            case StatementKind::Mirror: {
                DeriveScratch::Task mirrored{task.gene, i + 1, s, task.parent};
                mirrored.scope.axes[st.axis] = -mirrored.scope.axes[st.axis];
                stack.push_back(mirrored);
                break;
            }
            case StatementKind::Box:
            case StatementKind::Cylinder:
            case StatementKind::Cone:
            case StatementKind::Sphere:
            case StatementKind::Mesh: {
                // A cap, so that mirrors inside recursion (2^depth copies) cannot run away.
                if (out.primitives.size() >= maxPrimitives) return false;
                Primitive p{primitiveKind(st.kind), 0, 1.0f, s.origin, s.axes, glm::abs(s.size) * 0.5f};
                if (st.kind == StatementKind::Cone) {
                    const float top = eval(st.expr[0]);
                    p.taper = top >= 0.0f ? std::min(top, 1.0f) : 0.0f;  // NaN -> 0 as well
                } else if (st.kind == StatementKind::Mesh) {
                    p.mesh = st.slot;
                }
                out.primitives.push_back(p);
                break;
            }
            case StatementKind::TerminalBegin:
                if (hasChildren(c, task.gene, r)) {
                    i = st.end;  // the loop's ++i steps past the TerminalEnd
                } else {
                    beforeTerminal = s;
                }
                break;
            case StatementKind::TerminalEnd: s = beforeTerminal; break;
            case StatementKind::Child: {
                const Slot& slot = r.slots[st.slot];
                for (std::uint32_t k = slot.maxCount; k-- > 0;) {
                    const std::int32_t off = c.child(task.gene, slot.firstChild + k);
                    if (off > 0) stack.push_back({task.gene + std::uint32_t(off), 0, s, s});
                }
                break;
            }
            }
        }
    }
    return true;
}

}  // namespace shapevo

// libFuzzer target: arbitrary bytes -> compileExpression (graph/expression.hpp) against fixed
// names (self_, attr, attrs, A, v1, arg0, old, t), then, when it compiles, evaluation with sample
// values and a seeded DrawSource. Promises checked: compiling never crashes and throws only
// ExpressionError with an offset within the text; compiling twice gives the same outcome; an
// evaluation throws only EvaluationError (MissingKeyError included) and gives the same result
// twice from the same seed; slotsRead() is ascending and within the slots; a constant expression
// draws nothing.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "graph/expression.hpp"

namespace {

using namespace shapevo::graph;

struct FuzzScene {
    NameSlots slots;
    AttrMap vertexAttrs, edgeAttrs;
    std::vector<Value> values;

    explicit FuzzScene(AttrNames& names) {
        for (const char* n : {"self_", "attr", "attrs", "A", "v1", "arg0", "old", "t"}) slots.add(n);
        vertexAttrs.set(names.intern("size"), Value("2.5"));
        vertexAttrs.set(names.intern(".generation"), Value(3));
        vertexAttrs.set(names.intern("label"), Value("Branch"));
        edgeAttrs.set(names.intern("length"), Value(-4.5));
        const ElementRef vertex{&vertexAttrs, true, Vec2{1.0, 2.0}};
        const ElementRef edge{&edgeAttrs, false, Vec2{}};
        auto tuple = std::make_shared<const std::vector<Value>>(std::vector<Value>{Value(1), Value(2.5), Value("x")});
        values = {Value(vertex), Value("7"), Value(vertex), Value(std::int64_t(-9)), Value(Vec2{3.0, 4.0}),
                  Value(edge), Value(), Value(Tuple(tuple))};
    }
};

[[noreturn]] void broken(const char* what) {
    __builtin_printf("fuzz_graph_expression: %s\n", what);
    std::abort();
}

// "ok:<str of the value>" or "error:<message>".
std::string evaluateOnce(const CompiledExpression& e, const FuzzScene& scene, const AttrNames& names, int& draws) {
    struct Counting final : DrawSource {
        SeededDraws seeded{41};
        int count = 0;
        double uniform(DrawPurpose p) override { return ++count, seeded.uniform(p); }
        std::uint64_t below(std::uint64_t n, DrawPurpose p) override { return ++count, seeded.below(n, p); }
    } source;
    std::string outcome;
    try {
        const Value v = e.evaluate(EvaluationFrame{scene.values.data(), scene.values.size(), &names, &source});
        outcome = "ok:" + toText(v);
    } catch (const EvaluationError& error) {
        outcome = std::string("error:") + error.what();
    }
    draws = source.count;
    return outcome;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    AttrNames names;
    const FuzzScene scene(names);
    std::string first, second;
    CompiledExpression compiled;
    bool ok = false;
    try {
        compiled = compileExpression(text, scene.slots, names);
        ok = true;
    } catch (const ExpressionError& e) {
        if (e.offset() > text.size()) broken("an error offset beyond the text");
        first = e.what();
    }
    try {
        AttrNames again;
        const FuzzScene other(again);
        compileExpression(text, other.slots, again);
        if (!ok) broken("a text compiled the second time only");
    } catch (const ExpressionError& e) {
        if (ok || first != e.what()) broken("compiling twice gave two outcomes");
    }
    if (!ok) return 0;
    const std::vector<int>& slots = compiled.slotsRead();
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (slots[i] < 0 || std::size_t(slots[i]) >= scene.values.size() || (i && slots[i - 1] >= slots[i]))
            broken("slotsRead() out of range or not ascending");
    int drawsA = 0, drawsB = 0;
    const std::string a = evaluateOnce(compiled, scene, names, drawsA);
    const std::string b = evaluateOnce(compiled, scene, names, drawsB);
    // nan prints the same, so text comparison is exact even for nan results.
    if (a != b || drawsA != drawsB) broken("one seed gave two results");
    if (drawsA > 0 && !compiled.drawsRandomly()) broken("drew without drawsRandomly()");
    if (compiled.isConstant() && (drawsA > 0 || !slots.empty())) broken("a constant read a name or drew");
    return 0;
}

// libFuzzer target: arbitrary bytes -> parseGraphGrammar (graph/read_graph_grammar.hpp: YAML,
// ids, every expression compiled), then, when the file reads, deriveGraph from each of its first
// two host graphs with small limits (50 steps, 5,000 elements, a small match budget) and a seeded
// DrawSource. Promises checked: only InputError escapes (anything else terminates: a crash); a
// reading error names the file and a line:column inside the text, then a message on one line;
// a derivation error names the file; reading twice gives the same outcome; one seed gives one
// derivation (same steps, elements and fired counts, or the same error); a derivation that ends
// holds at most the element limit and at most the step limit of steps.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "base/input_error.hpp"
#include "graph/derive.hpp"
#include "graph/read_graph_grammar.hpp"

namespace {

using namespace shapevo;
using namespace shapevo::graph;

const std::string kPath = "fuzz.yml";

[[noreturn]] void broken(const char* what, const std::string& detail = "") {
    std::fprintf(stderr, "fuzz_graph_grammar: %s %s\n", what, detail.c_str());
    std::abort();
}

/// "fuzz.yml:LINE:COL: message" with LINE:COL inside `text` (columns count characters, so at
/// most the line's bytes + 1) and a message of one line.
void checkLocated(const InputError& e, const std::string& text) {
    const std::string what = e.what();
    if (e.file() != kPath || what.rfind(kPath + ":", 0) != 0) broken("an error not naming the file:", what);
    int line = 0, column = 0, consumed = 0;
    if (std::sscanf(what.c_str() + kPath.size() + 1, "%d:%d: %n", &line, &column, &consumed) != 2 || consumed == 0)
        broken("a reading error without line:column:", what);
    if (e.message().empty() || e.message().find('\n') != std::string::npos) broken("an empty or multi-line message:", what);
    int l = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < text.size() && l < line; ++i)
        if (text[i] == '\n') ++l, lineStart = i + 1;
    if (line < 1 || l != line) broken("a line outside the text:", what);
    std::size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    if (column < 1 || std::size_t(column) > lineEnd - lineStart + 1) broken("a column outside its line:", what);
}

struct Outcome {
    std::string error;  // empty: derived
    std::int64_t steps = 0;
    std::size_t elements = 0;
    std::vector<std::int64_t> fired;
    bool operator==(const Outcome&) const = default;
};

Outcome deriveOnce(const GraphGrammar& g, std::size_t host) {
    DeriveLimits limits;
    limits.maxSteps = 50;
    limits.maxElements = 5000;
    limits.maxMatches = 1'000;
    limits.maxSearchSteps = 10'000;
    SeededDraws draws(41);
    Outcome o;
    try {
        const DeriveResult r = deriveGraph(g, host, draws, limits);
        o.steps = r.steps;
        o.elements = r.graph.elements();
        o.fired = r.fired;
        if (o.steps > 50 || o.elements > limits.maxElements) broken("a derivation beyond its limits");
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (e.file() != kPath || what.rfind(kPath + ":", 0) != 0 || e.message().empty()) broken("a derivation error not naming the file:", what);
        o.error = what;
    }
    return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::string first;
    GraphGrammar g;
    bool ok = false;
    try {
        g = parseGraphGrammar(text, kPath);
        ok = true;
    } catch (const InputError& e) {
        checkLocated(e, text);
        first = e.what();
    }
    try {
        parseGraphGrammar(text, kPath);
        if (!ok) broken("a file read the second time only");
    } catch (const InputError& e) {
        if (ok || first != e.what()) broken("reading twice gave two outcomes");
    }
    static const bool verbose = std::getenv("SHAPEVO_FUZZ_VERBOSE") != nullptr;  // what each input did
    if (verbose) std::fprintf(stderr, "read: %s\n", ok ? "ok" : first.c_str());
    if (!ok) return 0;
    if (g.hosts.empty()) broken("a grammar without a host graph");
    for (std::size_t host = 0; host < g.hosts.size() && host < 2; ++host)
    {
        const Outcome a = deriveOnce(g, host);
        if (verbose) std::fprintf(stderr, "host %zu: %s steps %lld elements %zu\n", host, a.error.c_str(), (long long)a.steps, a.elements);
        if (!(a == deriveOnce(g, host))) broken("one seed gave two derivations");
    }
    return 0;
}

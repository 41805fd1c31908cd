// libFuzzer target: arbitrary bytes -> parseGrammar as a procedural content graph (.pcg,
// src/grammar/pcg/), read from this target's own scratch folder, where a few graph files exist
// for includes to find (part.pcg, loop.pcg, and sides.pcg whose collective nodes gather per
// entity; the dictionary pcg.dict names them) and nothing else
// resolves. A located InputError is the expected way to reject input: located inside the input,
// or inside the other file it names (an included graph file); any other exception, a sanitizer
// report, or a broken invariant of an accepted grammar (grammar_invariants.hpp, shared with
// fuzz_grammar_parser) is a crash.
#include <cstdint>
#include <string>

#include "grammar_file_target.hpp"

namespace {

using namespace shapevo;

/// The scratch folder with its files, made once.
const std::string& folder() {
    static const std::string dir = [] {
        const std::string d = fuzz::scratchFolder("fuzz_pcg_parser");
        fuzz::putFile(d + "/part.pcg", "graph Part\nparam h = uniform(1, 2)\nin base : volume\nout top : volume\n"
                                       "node s = size(1, h, 1)\nnode b = box()\nbase -> s\ns -> b\nb -> top\n");
        fuzz::putFile(d + "/sides.pcg", "graph Sides\nin lot : volume\nout rest : flat\nnode f = comp()\nnode o = order_by(scope.size.x desc)\n"
                                        "node a = amount_filter(count: 1)\nnode e = extrude(0.2)\nnode b = box()\nnode g = color(0.5, 0.5, 0.5)\n"
                                        "lot -> f\nf.side -> o\no -> a\na.first -> e\ne -> b\na.rest -> g\ng -> rest\n");
        fuzz::putFile(d + "/loop.pcg", "graph Loop\nin base : volume\nnode l = include \"loop.pcg\"\nbase -> l\n");
        return d;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string path = folder() + "/fuzz.pcg";
    fuzz::checkGrammarFile(text, path);
    return 0;
}

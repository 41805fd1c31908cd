// libFuzzer target: arbitrary bytes -> parseGrammar as a CastleMaker rule file (.rule,
// src/grammar/crl/), read from this target's own scratch folder, where a few files exist for
// includes, inserts and textures to find (part.rule, loop.rule, window.obj, stone.png; the
// dictionary rule.dict names them) and nothing else resolves. A located InputError is the
// expected way to reject input: located inside the input, or inside the other file it names
// (an included rule file); any other exception, a sanitizer report, or a broken invariant of an
// accepted grammar (grammar_invariants.hpp, shared with fuzz_grammar_parser) is a crash.
#include <cstdint>
#include <string>

#include "grammar_file_target.hpp"

namespace {

using namespace shapevo;

/// The scratch folder with its files, made once.
const std::string& folder() {
    static const std::string dir = [] {
        const std::string d = fuzz::scratchFolder("fuzz_rule_parser");
        fuzz::putFile(d + "/part.rule", "attr w = 2;\nP = rect(0, 0, 1, 2);\nP -> extrude(w) {Q};\nQ -> insert_volume(1, 1, 1, 0, 0, 1);\n");
        fuzz::putFile(d + "/loop.rule", "include \"loop.rule\";\nP = rect(0, 0, 1, 1);\n");
        fuzz::putFile(d + "/window.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");  // closed
        fuzz::putFile(d + "/stone.png", "not really a png");
        return d;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string path = folder() + "/fuzz.rule";
    fuzz::checkGrammarFile(text, path);
    return 0;
}

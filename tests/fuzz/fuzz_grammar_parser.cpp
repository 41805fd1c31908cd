// libFuzzer target: arbitrary bytes -> parseGrammar. A located InputError is the expected way
// to reject input; any other exception, a sanitizer report, or a broken invariant of an accepted
// grammar is a crash (grammar_invariants.hpp). See grammars/README.md ("Fuzzing") for how to
// build and run it.
#include <cstdint>
#include <string>

#include "grammar_invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shapevo;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const Grammar g = parseGrammar(text, "fuzz.grammar");
        fuzz::checkAccepted(g);
    } catch (const InputError& e) {
        fuzz::checkLocated(e, text, "fuzz.grammar");
    }
    return 0;
}

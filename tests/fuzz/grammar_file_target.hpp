// What the fuzz targets that read a grammar *file* share (fuzz_rule_parser, fuzz_pcg_parser):
// writing the other files their scratch folder holds for includes to find, and the check of one
// input: parsed as the file at `path`, an accepted grammar keeps every invariant
// (grammar_invariants.hpp); a rejected one throws an InputError located inside the input, or
// inside another file it names, which must be a file that exists there. Anything else crashes.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "grammar_invariants.hpp"
#include "scratch_folder.hpp"

namespace shapevo::fuzz {

/// Writes `text` to `path` (aborting if it cannot).
inline void putFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) {
        std::perror(path.c_str());
        std::abort();
    }
}

inline std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// One input: `text` parsed as the grammar file at `path`.
inline void checkGrammarFile(const std::string& text, const std::string& path) {
    try {
        const Grammar g = parseGrammar(text, path);
        checkAccepted(g);
        FUZZ_CHECK(g.source == text);
    } catch (const InputError& e) {
        if (e.file() == path) {
            checkLocated(e, text, path);
        } else {  // another file's place: it must be a file that was read
            std::error_code ec;
            FUZZ_CHECK(!e.file().empty() && std::filesystem::is_regular_file(e.file(), ec));
            checkLocated(e, fileText(e.file()), e.file());
        }
    }
}

}  // namespace shapevo::fuzz

// wordList: names joined the way messages and --help list choices: "a", "a or b", "a, b or c".
// Every table of a plug-in family (search methods, front ends, target kinds, output formats)
// lists its members through it, so all such lists read alike.
#pragma once
#include <cstddef>
#include <string>

namespace shapevo {

/// word(0), ..., word(count - 1) joined by ", " and a last " or " ("" for none). `word(i)`
/// returns what to write for the i-th (anything std::string += takes).
template <class Word>
std::string wordList(std::size_t count, Word&& word) {
    std::string out;
    for (std::size_t i = 0; i < count; ++i) {
        if (i) out += i + 1 == count ? " or " : ", ";
        out += word(i);
    }
    return out;
}

}  // namespace shapevo

// InputError: the one exception type for bad user input (grammar, config, mesh, VDB, PNG).
// It names the file and the place inside it; the CLI prints what() and exits with code 2.
// Messages stay short whatever the input: a value quoted from the input goes through
// shortened() (80 characters and "…"), and the message itself caps each of its parts
// (file 256, place 80, text 2048 bytes), so a 50 MB bad string is never echoed whole.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace shapevo {

/// `s` cut to at most `max` bytes (never inside a UTF-8 character) followed by "…" if it was
/// longer, with control characters (a newline, a tab, binary garbage) shown as '?'. For
/// quoting input (a value, a key, a name, a library's message about a damaged file);
/// `controls` = true keeps them.
inline std::string shortened(std::string_view s, std::size_t max = 80, bool controls = false) {
    std::size_t n = s.size();
    if (n > max) {
        n = max;
        while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;  // s[n] continues a character
    }
    std::string out(s.substr(0, n));
    if (!controls)
        for (char& c : out)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    if (n < s.size()) out += "\u2026";
    return out;
}

class InputError : public std::runtime_error {
public:
    /// @param file  path of the offending file (or a description such as "--set")
    /// @param where place inside it, e.g. "12:5" or "[ga] population"; may be empty
    /// @param what  what was wrong and, where it helps, what was expected
    InputError(const std::string& file, const std::string& where, const std::string& what)
        : std::runtime_error(compose(file, where, what)), file_(file), where_(where), message_(what) {}
    const std::string& file() const { return file_; }
    const std::string& where() const { return where_; }
    /// The `what` given, without file and place.
    const std::string& message() const { return message_; }

private:
    static std::string compose(const std::string& file, const std::string& where, const std::string& what) {
        std::string m = shortened(file, 256);
        if (!where.empty()) {
            m += ':';
            m += shortened(where);
        }
        m += ": ";
        m += shortened(what, 2048, /*controls=*/true);  // a message may span lines
        return m;
    }
    std::string file_, where_, message_;
};

}  // namespace shapevo

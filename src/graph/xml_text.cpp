// isXmlName and appendEscaped (xml_text.hpp).
#include "graph/xml_text.hpp"

namespace shapevo::graph {

bool isXmlName(std::string_view n) {
    if (n.empty()) return false;
    auto start = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':'; };
    if (!start(n[0])) return false;
    for (char c : n)
        if (!start(c) && !(c >= '0' && c <= '9') && c != '-' && c != '.') return false;
    return true;
}

void appendEscaped(std::string& out, std::string_view text) {
    // Runs of plain characters are appended whole (most values have nothing to escape).
    auto plain = [](char c) {
        return c != '&' && c != '<' && c != '>' && c != '"' && static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
    };
    std::size_t i = 0;
    while (i < text.size()) {
        std::size_t j = i;
        while (j < text.size() && plain(text[j])) ++j;
        out.append(text.data() + i, j - i);
        if (j == text.size()) return;
        const char c = text[j];
        i = j + 1;
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\t': out += "&#9;"; break;
        case '\n': out += "&#10;"; break;
        case '\r': out += "&#13;"; break;
        default:
            out += "\xEF\xBF\xBD";  // another control character
        }
    }
}

}  // namespace shapevo::graph

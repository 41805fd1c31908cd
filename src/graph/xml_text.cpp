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
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\t': out += "&#9;"; break;
        case '\n': out += "&#10;"; break;
        case '\r': out += "&#13;"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) out += "\xEF\xBF\xBD";
            else out += c;
        }
    }
}

}  // namespace shapevo::graph

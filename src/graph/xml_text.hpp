// XML text for the SVG writer and the drawing's attribute checks: which strings are XML names
// (an attribute or element name written as given must be one, or the file would not parse) and
// attribute values escaped so that any text, quotes and markup included, stays one value.
#pragma once
#include <string>
#include <string_view>

namespace shapevo::graph {

/// An XML name in the ASCII range shapevo writes: [A-Za-z_:][A-Za-z0-9_:.-]*.
bool isXmlName(std::string_view name);

/// `text` as an attribute value between double quotes: & < > " escaped, tab, newline and
/// carriage return as character references (kept by a parser), other control characters
/// (not allowed in XML 1.0) as U+FFFD.
void appendEscaped(std::string& out, std::string_view text);

}  // namespace shapevo::graph

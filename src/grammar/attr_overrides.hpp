// Attr overrides: the values a config's [grammar.attr] table or the command line (--set
// grammar.attr.NAME=V, --attr NAME=V) give a grammar's attrs. Every front end takes them.
#pragma once
#include <map>
#include <string>

namespace shapevo {

/// Values that replace attrs' definitions. Naming an attr the grammar does not define is an error.
using AttrOverrides = std::map<std::string, double>;

}  // namespace shapevo

// A translation: what a front end that translates (a CastleMaker rule file, grammar/crl/) makes
// of a file: text in the shapevo grammar language plus, per line of it, the place in the user's
// own files it came from. Compiling one parses the text and reports any problem at that place,
// so errors stay located in the file the user wrote.
#pragma once
#include <string>
#include <vector>

#include "grammar/attr_overrides.hpp"
#include "grammar/grammar.hpp"

namespace shapevo {

/// A place in a user's file.
struct Location {
    std::string file;  ///< as shown in messages (the path the file was read from)
    int line = 0, column = 0;
};

/// The shapevo-language text of a file and where each of its lines came from.
struct Translation {
    std::string text;
    std::vector<Location> origin;     ///< per line of `text`
    std::vector<std::string> files;   ///< every other file read (includes, inserted models), relative to the main file's folder
};

/// The Grammar of the file `path` (its text `source`) from its translation `t`: Grammar::source
/// is `source`, Grammar::includes `t.files`.
/// @throw InputError a problem of the translated text, at the place in `t.origin` its line came
///        from, with the offending translated line quoted.
Grammar compileTranslation(const Translation& t, const std::string& source, const std::string& path, const AttrOverrides& overrides);

/// What `shapevo translate` prints: a header naming `path`, then `t.text`, each rule that starts
/// at a new place marked "# FILE:LINE".
std::string translationListing(const Translation& t, const std::string& path);

}  // namespace shapevo

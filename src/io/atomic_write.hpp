// writeAtomically: an output file appears whole or not at all. The content is written to a
// temporary file next to the destination (same directory, so the rename cannot cross file
// systems), flushed to disk and then renamed over the destination.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace shapevo {

/// Calls `write(tempPath)` to create the temporary file, then publishes it as `path`. If
/// `write` throws, the temporary file is removed and the exception propagates.
/// @throw InputError naming `path` when the file cannot be created or renamed.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tempPath)>& write);

/// The same for stream writers: `write` fills a binary std::ofstream opened on the temporary file.
void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write);

}  // namespace shapevo

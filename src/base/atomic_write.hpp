// writeAtomically: an output file appears whole or not at all. The content is written to a
// temporary file next to the destination (same directory, so the rename cannot cross file
// systems), flushed to disk and then renamed over the destination; then the folder is flushed
// too, so the new name survives a power cut. Every writer of a user-visible file goes through here.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace shapevo {

/// fsync of a file or folder (a folder on a file system without folder fsync, EINVAL, passes).
/// @throw std::runtime_error naming `path` when it cannot be opened or flushed (disk full, I/O error).
void syncToDisk(const std::string& path);

/// Calls `write(tempPath)` to create the temporary file, then publishes it as `path`. If
/// `write` throws, the temporary file is removed and the exception propagates.
/// @throw InputError naming `path` when the file cannot be created or renamed.
/// With Replace::Never an existing `path` (even one that appears while writing) is not replaced:
/// the temporary file is hard-linked into place (atomic, refuses an existing name) and an
/// InputError says the file exists.
enum class Replace { Always, Never };
void writeAtomically(const std::string& path, const std::function<void(const std::string& tempPath)>& write,
                     Replace replace = Replace::Always);

/// The same for stream writers: `write` fills a binary std::ofstream opened on the temporary file.
void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write,
                           Replace replace = Replace::Always);

}  // namespace shapevo

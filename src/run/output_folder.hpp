// Output folders: pick or check a run's folder so that nothing already written is overwritten,
// and the rule for run.name, which names the default folder runs/<name>.
#pragma once
#include <cstddef>
#include <string>

namespace shapevo {

/// Longest run.name accepted.
inline constexpr std::size_t kMaxRunNameLength = 128;

/// Why `name` cannot be a run name, or "" if it can. A run name is a plain folder name: 1 to
/// kMaxRunNameLength bytes, no '/' or backslash, no control character, not starting with '.' or '-'
/// (so never "", ".", "..", a path, a hidden folder or an option-like word: runs/<name> always
/// lies inside runs/).
std::string runNameProblem(const std::string& name);

/// `requested` non-empty: it must not exist yet (InputError otherwise). Empty: runs/<name>, or
/// runs/<name>-2, -3, ... if taken; `name` must pass runNameProblem (InputError otherwise). The
/// folder is created.
std::string claimOutputFolder(const std::string& requested, const std::string& name);

}  // namespace shapevo

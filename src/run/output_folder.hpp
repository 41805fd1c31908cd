// Output folders: pick or check a run's folder so that nothing already written is overwritten.
#pragma once
#include <string>

namespace shapevo {

/// `requested` non-empty: it must not exist yet (InputError otherwise). Empty: runs/<name>, or
/// runs/<name>-2, -3, ... if taken. The folder is created.
std::string claimOutputFolder(const std::string& requested, const std::string& name);

}  // namespace shapevo

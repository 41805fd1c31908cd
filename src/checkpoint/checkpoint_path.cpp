// resolveCheckpointPath: a run folder, checkpoint folder or checkpoint file -> checkpoint folder.
#include "checkpoint/checkpoint_path.hpp"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <vector>

#include "base/input_error.hpp"
#include "checkpoint/checkpoint_file.hpp"

namespace shapevo {

namespace {

namespace fs = std::filesystem;

constexpr const char* kAccepted =
    "expected a run folder, a checkpoint folder (checkpoint-NNNNNN) or a checkpoint's run.h5 or island-NNNN.h5";

bool allDigits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// "island-" + four or more digits + ".h5", as islandFileName writes them.
bool isIslandFileName(std::string_view name) {
    constexpr std::string_view prefix = "island-", suffix = ".h5";
    if (!name.starts_with(prefix) || !name.ends_with(suffix)) return false;
    const std::string_view digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    return digits.size() >= 4 && allDigits(digits);
}

bool isCheckpointFolder(const fs::path& p) {
    std::error_code ec;
    const std::string name = p.filename().string();
    return fs::exists(p / "MANIFEST", ec) || fs::exists(p / "run.h5", ec) ||
           (name.starts_with("checkpoint-") && allDigits(std::string_view(name).substr(11)));
}

/// run.h5 or island-NNNN.h5 -> the checkpoint folder that holds it.
std::string folderOfCheckpointFile(const std::string& path, const fs::path& p) {
    const std::string name = p.filename().string();
    if (name != "run.h5" && !isIslandFileName(name))
        throw InputError(path, "", std::string("is not a checkpoint file; ") + kAccepted);
    const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::current_path();
    if (!isCheckpointFolder(folder))
        throw InputError(path, "", "is not inside a checkpoint folder (" + folder.string() + " holds no MANIFEST); " + kAccepted);
    if (name != "run.h5") {
        std::vector<ManifestEntry> listed;
        try {
            listed = readManifest(folder.string());
        } catch (const InputError&) {
            return folder.string();  // incomplete: the checkpoint reader says why
        }
        if (std::none_of(listed.begin(), listed.end(), [&](const ManifestEntry& e) { return e.name == name; }))
            throw InputError(path, "", "is not one of the islands of its checkpoint (" + folder.string() +
                                           "/MANIFEST does not list it)");
    }
    return folder.string();
}

}  // namespace

std::string resolveCheckpointPath(const std::string& path) {
    fs::path p(path);
    if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();  // "run/checkpoint-000050/"
    std::error_code ec;
    const fs::file_status status = fs::status(p, ec);
    if (!fs::exists(status)) throw InputError(path, "", std::string("does not exist; ") + kAccepted);
    if (!fs::is_directory(status)) return folderOfCheckpointFile(path, p);
    if (isCheckpointFolder(p)) return p.string();
    const std::vector<std::string> checkpoints = listCheckpoints(p.string());
    if (checkpoints.empty())
        throw InputError(path, "", std::string("is a folder without checkpoints (no checkpoint-NNNNNN inside); ") + kAccepted);
    for (const std::string& c : checkpoints)
        if (verifyCheckpoint(c).empty()) return c;
    throw InputError(path, "", "is a run folder without a complete checkpoint (the newest, " + checkpoints.front() +
                                   ": " + verifyCheckpoint(checkpoints.front()) + ")");
}

}  // namespace shapevo

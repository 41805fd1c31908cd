// Output folder claiming: create_directory is atomic, so two runs never share a folder.
#include "run/output_folder.hpp"

#include <filesystem>

#include "base/input_error.hpp"

namespace shapevo {

std::string runNameProblem(const std::string& name) {
    if (name.empty()) return "is empty";
    if (name.size() > kMaxRunNameLength)
        return "is " + std::to_string(name.size()) + " bytes long (at most " + std::to_string(kMaxRunNameLength) + ")";
    if (name[0] == '.' || name[0] == '-') return std::string("starts with '") + name[0] + "'";
    for (const char c : name) {
        if (c == '/' || c == '\\') return "contains a path separator";
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "contains a control character";
    }
    return "";
}

std::string claimOutputFolder(const std::string& requested, const std::string& name) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!requested.empty()) {
        if (fs::exists(requested))
            throw InputError(requested, "", "output folder already exists; choose another --out or move it away "
                                            "(shapevo never overwrites a run)");
        const fs::path parent = fs::path(requested).parent_path();
        if (!parent.empty()) fs::create_directories(parent, ec);
        if (!fs::create_directory(requested, ec))
            throw InputError(requested, "", "cannot create output folder: " + (ec ? ec.message() : "it exists"));
        return requested;
    }
    if (const std::string problem = runNameProblem(name); !problem.empty())
        throw InputError("run.name", "", "\"" + shortened(name) + "\" " + problem + "; it must be a plain folder name");
    fs::create_directories("runs", ec);
    for (int n = 1; n < 100000; ++n) {
        std::string candidate = "runs/";
        candidate += name;
        if (n > 1) {
            candidate += '-';
            candidate += std::to_string(n);
        }
        if (fs::create_directory(candidate, ec)) return candidate;
        if (ec) throw InputError(candidate, "", "cannot create output folder: " + ec.message());
    }
    throw InputError("runs/" + name, "", "no free output folder name");
}

}  // namespace shapevo

// Output folder claiming: create_directory is atomic, so two runs never share a folder.
#include "run/output_folder.hpp"

#include <filesystem>

#include "base/input_error.hpp"

namespace shapevo {

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

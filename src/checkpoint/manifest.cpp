// MANIFEST: the last file written into a checkpoint folder, and the proof that it is complete.
//
//   run.h5 20480 8f1c0a9e23b4d5f6
//   island-0000.h5 53248 0123456789abcdef
//   end
//
// One line per file: plain name, size in bytes (decimal), XXH3-64 of its bytes (16 lowercase
// hex digits); then "end". verifyCheckpoint checks sizes and hashes by reading bytes only, so a
// truncated or altered file is reported by name before any of it reaches libhdf5's parser.

#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "checkpoint/checkpoint_file.hpp"
#include "base/atomic_write.hpp"
#include "base/hash.hpp"
#include "base/input_error.hpp"

namespace shapevo {

namespace {

namespace fs = std::filesystem;

constexpr const char* kManifest = "MANIFEST";
constexpr std::uintmax_t kMaxManifestBytes = 1 << 20;

bool plainName(const std::string& name) {
    if (name.empty() || name == "." || name == ".." || name == kManifest || name.size() > 255) return false;
    for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) return false;
    return true;
}

/// A size: decimal digits, no sign, no leading zeros, fits in u64.
bool parseDecimal(const std::string& s, std::uint64_t& out) {
    if (s.empty() || s.size() > 20 || (s.size() > 1 && s[0] == '0')) return false;
    out = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return false;
        const std::uint64_t digit = std::uint64_t(c - '0');
        if (out > (UINT64_MAX - digit) / 10) return false;
        out = out * 10 + digit;
    }
    return true;
}

bool parseHex16(const std::string& s, std::uint64_t& out) {
    if (s.size() != 16) return false;
    out = 0;
    for (char c : s) {
        int v;
        if (c >= '0' && c <= '9') v = c - '0';
        else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
        else return false;
        out = out << 4 | std::uint64_t(v);
    }
    return true;
}

}  // namespace

void writeManifest(const std::string& folder, const std::vector<std::string>& files) {
    std::string text;
    for (const std::string& name : files) {
        if (!plainName(name)) throw std::runtime_error(folder + ": not a plain file name for MANIFEST: \"" + name + "\"");
        const FileHash d = hashFile((fs::path(folder) / name).string());
        if (!d.ok) throw std::runtime_error(folder + "/" + name + ": cannot read to write MANIFEST");
        text += name + " " + std::to_string(d.size) + " " + hashHex(d.hash) + "\n";
    }
    text += "end\n";
    writeStreamAtomically(folder + "/" + kManifest, [&](std::ostream& out) { out.write(text.data(), std::streamsize(text.size())); });
}

namespace {

/// What is wrong with a MANIFEST, and where ("line 3" or empty).
struct ManifestProblem {
    std::string where, what;
};

std::vector<ManifestEntry> parseManifest(const std::string& folder) {
    const std::string path = (fs::path(folder) / kManifest).string();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw ManifestProblem{"", "missing (the checkpoint was never finished)"};
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec || size > kMaxManifestBytes) throw ManifestProblem{"", "unreadable or larger than 1 MiB"};
    std::ifstream in(path, std::ios::binary);
    std::string text(std::size_t(size), '\0');
    if (!in.read(text.data(), std::streamsize(size))) throw ManifestProblem{"", "cannot read"};

    std::vector<ManifestEntry> entries;
    std::set<std::string> names;
    std::size_t at = 0;
    for (int line = 1;; ++line) {
        const std::string where = "line " + std::to_string(line);
        const std::size_t end = text.find('\n', at);
        if (end == std::string::npos) throw ManifestProblem{where, "ends without the final \"end\" line (truncated)"};
        const std::string s = text.substr(at, end - at);
        at = end + 1;
        if (s == "end") {
            if (at != text.size()) throw ManifestProblem{"line " + std::to_string(line + 1), "text after \"end\""};
            break;
        }
        const std::size_t a = s.find(' '), b = a == std::string::npos ? a : s.find(' ', a + 1);
        if (b == std::string::npos || s.find(' ', b + 1) != std::string::npos)
            throw ManifestProblem{where, "expected \"name size xxh3-64-hex\""};
        ManifestEntry e;
        e.name = s.substr(0, a);
        if (!plainName(e.name)) throw ManifestProblem{where, "\"" + e.name + "\" is not a plain file name"};
        if (!parseDecimal(s.substr(a + 1, b - a - 1), e.size)) throw ManifestProblem{where, "size is not a decimal number"};
        if (!parseHex16(s.substr(b + 1), e.xxh3_64)) throw ManifestProblem{where, "hash is not 16 lowercase hex digits"};
        if (!names.insert(e.name).second) throw ManifestProblem{where, e.name + " is listed twice"};
        entries.push_back(std::move(e));
    }
    if (!names.count("run.h5")) throw ManifestProblem{"", "does not list run.h5"};
    if (!names.count(islandFileName(0))) throw ManifestProblem{"", "does not list " + islandFileName(0)};
    // Islands are numbered from 0 without gaps: if island k is listed, so is island k-1.
    for (const std::string& name : names) {
        if (!name.starts_with("island-") || !name.ends_with(".h5")) continue;
        const std::string digits = name.substr(7, name.size() - 10);
        int rank = 0;
        bool ok = digits.size() >= 4 && digits.size() <= 9;
        for (char c : digits) {
            ok = ok && c >= '0' && c <= '9';
            if (ok) rank = rank * 10 + (c - '0');
        }
        if (!ok || name != islandFileName(rank))
            throw ManifestProblem{"", "\"" + name + "\" is not an island file name like island-0003.h5"};
        if (rank > 0 && !names.count(islandFileName(rank - 1)))
            throw ManifestProblem{"", "lists " + name + " but not " + islandFileName(rank - 1)};
    }
    return entries;
}

}  // namespace

std::vector<ManifestEntry> readManifest(const std::string& folder) {
    try {
        return parseManifest(folder);
    } catch (const ManifestProblem& p) {
        throw InputError((fs::path(folder) / kManifest).string(), p.where, p.what);
    }
}

namespace {
/// Empty if the file `e` names in `folder` has the listed size and hash, else why not.
std::string verifyListed(const std::string& folder, const ManifestEntry& e) {
    const fs::path path = fs::path(folder) / e.name;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return e.name + ": missing";
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) return e.name + ": cannot read its size";
    if (size != e.size)
        return e.name + ": " + std::to_string(size) + " bytes but MANIFEST lists " + std::to_string(e.size) +
               (size < e.size ? " (truncated)" : " (altered)");
    const FileHash d = hashFile(path.string());
    if (!d.ok) return e.name + ": cannot read";
    if (d.size != e.size || d.hash != e.xxh3_64)
        return e.name + ": content hashes to " + hashHex(d.hash) + " but MANIFEST lists " + hashHex(e.xxh3_64) +
               " (altered or damaged)";
    return "";
}
}  // namespace

bool listedFileIsIntact(const std::string& folder, const std::string& name) {
    try {
        for (const ManifestEntry& e : parseManifest(folder))
            if (e.name == name) return verifyListed(folder, e).empty();
    } catch (const ManifestProblem&) {
    }
    return false;
}

std::string verifyCheckpoint(const std::string& folder) {
    std::vector<ManifestEntry> entries;
    try {
        entries = parseManifest(folder);
    } catch (const ManifestProblem& p) {
        return std::string(kManifest) + (p.where.empty() ? "" : ":" + p.where) + ": " + p.what;
    }
    for (const ManifestEntry& e : entries) {
        std::string problem = verifyListed(folder, e);
        if (!problem.empty()) return problem;
    }
    // Every file in the folder must be listed: an unlisted one would reach libhdf5 unchecked.
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name == kManifest) continue;
        bool listed = false;
        for (const ManifestEntry& e : entries) listed = listed || e.name == name;
        if (!listed) return name + ": in the folder but not in MANIFEST";
    }
    if (ec) return "cannot list the folder: " + ec.message();
    return "";
}

}  // namespace shapevo

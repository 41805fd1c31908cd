// Genome files: write raw words behind a small header; read with every check.
#include "genome/genome_file.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "base/atomic_write.hpp"
#include "base/hash.hpp"
#include "base/input_error.hpp"

namespace shapevo {

namespace {
constexpr char kMagic[8] = {'S', 'V', 'G', 'E', 'N', 'O', 'M', 'E'};
struct Header {
    char magic[8];
    std::uint32_t version, genes, words, reserved;
    std::uint64_t grammarHash;
};
static_assert(sizeof(Header) == 32);
}  // namespace

void writeGenome(const GenomeFamily& family, const Chromosome& c, const std::string& path) {
    Header h{};
    std::memcpy(h.magic, kMagic, 8);
    h.version = kGenomeFileVersion;
    h.genes = c.genes;
    h.words = c.size();
    h.grammarHash = hash64(family.sourceText());
    writeStreamAtomically(path, [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(&h), sizeof h);
        out.write(reinterpret_cast<const char*>(c.words.data()), std::streamsize(c.words.size() * 4));
    });
}

Chromosome readGenome(const GenomeFamily& family, const std::string& grammarPath, const GenomeLimits& limits,
                      const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path)) throw InputError(path, "", "cannot open genome file");
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || size > (std::uintmax_t(1) << 30)) throw InputError(path, "", "not a genome file (unreadable size or over 1 GiB)");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Header h{};
    if (bytes.size() < sizeof h) throw InputError(path, "byte 0", "too short for a genome file header");
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, 8) != 0) throw InputError(path, "byte 0", "not a shapevo genome file (bad magic)");
    if (h.version != kGenomeFileVersion)
        throw InputError(path, "byte 8", "genome file version " + std::to_string(h.version) +
                                             " is not supported (this shapevo reads version " +
                                             std::to_string(kGenomeFileVersion) + ")");
    if (bytes.size() != sizeof h + std::size_t(h.words) * 4)
        throw InputError(path, "byte 32", "expected " + std::to_string(h.words) + " words, file holds " +
                                              std::to_string((bytes.size() - sizeof h) / 4));
    if (h.grammarHash != hash64(family.sourceText()))
        throw InputError(path, "", "genome was made with a different grammar than " + grammarPath);
    if (h.genes == 0) throw InputError(path, "byte 12", "holds no genes");
    Chromosome c;
    c.genes = h.genes;
    c.words.resize(h.words);
    std::memcpy(c.words.data(), bytes.data() + sizeof h, std::size_t(h.words) * 4);
    const std::string problem = family.check(c, limits);
    if (!problem.empty()) throw InputError(path, "", "invalid chromosome: " + problem);
    return c;
}

}  // namespace shapevo

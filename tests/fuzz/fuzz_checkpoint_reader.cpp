// libFuzzer target: the checkpoint reader. An InputError is the expected way to reject input;
// any other exception, a sanitizer report, or a broken invariant of an accepted island is a crash.
//
// Three modes, chosen by the first input byte (mod 4):
//  0     "files": [mode][u16 LE manifest length M][u32 LE run.h5 length R][M bytes MANIFEST]
//        [R bytes run.h5][rest: island-0000.h5]. The three files are written into a temporary
//        checkpoint folder and verifyCheckpoint runs; only if it passes do readRunMetadata,
//        readIslandFile and describeCheckpoint run. This fuzzes the MANIFEST parser and the
//        size/hash gate. libhdf5's own file-format parser is NOT fuzzed here: it is protected by
//        that gate (no byte reaches H5Fopen before its size and XXH3-64 hash match the MANIFEST,
//        which only our writer produces), and fuzzing it would be fuzzing libhdf5, not shapevo.
//  2     "attributes": [mode][u8 file: even run.h5, odd island-0000.h5][u8 attribute index][rest:
//        the attribute's new bytes, repeated to its size]. A valid checkpoint is written, one
//        root attribute of one file is overwritten through libhdf5 (so the file stays valid
//        HDF5), and the MANIFEST is rebuilt to match, so the change passes the size/hash gate:
//        the reader must then refuse the file (the attribute checksum, or the schema check)
//        whenever the bytes changed, and accept it when they did not.
//  1, 3  "decoder": [mode][i32 rank][u32 generation][u64 evaluations][u64 individuals]
//        [5 x u32 LE lengths of genes, offsets, gene_counts, fitness, rng][those bytes][rest:
//        curve], fed straight to decodeIsland, the HDF5-free part of readIslandFile that
//        validates shapes, offsets, every chromosome (spaceship grammar) and values. So the
//        validation logic is fuzzed past the checksum gate.
// An accepted island must satisfy the invariants and re-encode to the same bytes.
//
// Build, seed and run (seeds are real checkpoint files, written by the same writer the tests use):
//   cmake -S . -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
//         -DSHAPEVO_FUZZ=ON -DSHAPEVO_BUILD_TESTS=OFF -DSHAPEVO_BUILD_BENCH=OFF
//   ninja -C build-fuzz fuzz_checkpoint_reader
//   SHAPEVO_FUZZ_WRITE_SEEDS=/tmp/checkpoint-corpus build-fuzz/tests/fuzz/fuzz_checkpoint_reader
//   build-fuzz/tests/fuzz/fuzz_checkpoint_reader -max_total_time=600 /tmp/checkpoint-corpus
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <hdf5.h>

#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/island_codec.hpp"
#include "genome/operators.hpp"
#include "genome/validate.hpp"
#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "base/input_error.hpp"

namespace {

using namespace shapevo;
namespace fs = std::filesystem;

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz_checkpoint_reader: invariant broken: %s\n", what);
    std::abort();
}
#define CHECK(cond) \
    do {            \
        if (!(cond)) broken(#cond); \
    } while (0)

constexpr GenomeLimits kLimits{60};
const Grammar* grammar = nullptr;
const TreeFamily* family = nullptr;  // the spaceship grammar's genome
std::string folder;  // this process's temporary checkpoint folder

/// Reads little-endian numbers and byte ranges off the front of the input; short reads give 0s
/// and empty ranges.
struct Input {
    const std::uint8_t* p;
    std::size_t left;
    template <class T>
    T number() {
        T v{};
        if (left >= sizeof v) {
            std::memcpy(&v, p, sizeof v);
            p += sizeof v;
            left -= sizeof v;
        }
        return v;
    }
    std::span<const std::uint8_t> bytes(std::size_t n) {
        n = std::min(n, left);
        std::span<const std::uint8_t> s(p, n);
        p += n;
        left -= n;
        return s;
    }
};

void writeBytes(const std::string& path, std::span<const std::uint8_t> b) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f || std::fwrite(b.data(), 1, b.size(), f) != b.size() || std::fclose(f) != 0) {
        std::perror(path.c_str());
        std::abort();
    }
}

void checkAccepted(const IslandState& s, const IslandBytesView& in) {
    CHECK(s.population.individuals.size() == s.population.fitness.size());
    CHECK(s.population.size() == in.individuals);
    for (std::size_t i = 0; i < s.population.size(); ++i) {
        CHECK(validateChromosome(*grammar, s.population.individuals[i], kLimits).empty());
        CHECK(std::isfinite(s.population.fitness[i]));
    }
    // Decoding is exact: re-encoding gives back the input bytes (the curve up to the sign of a
    // zero in its integer columns), and decoding that again gives the same bytes once more.
    const IslandBytes again = encodeIsland(s);
    auto same = [](std::span<const std::uint8_t> a, const std::vector<std::uint8_t>& b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
    };
    CHECK(same(in.genes, again.genes));
    CHECK(same(in.offsets, again.offsets));
    CHECK(same(in.geneCounts, again.geneCounts));
    CHECK(same(in.fitness, again.fitness));
    CHECK(same(in.rng, again.rng));
    CHECK(in.curve.size() == again.curve.size());
    const IslandBytes third = encodeIsland(decodeIsland(again.view(), *family, kLimits, "again"));
    CHECK(third.curve == again.curve && third.genes == again.genes);
}

void fuzzDecoder(Input in) {
    IslandBytesView v;
    v.rank = in.number<std::int32_t>();
    v.generation = in.number<std::uint32_t>();
    v.evaluations = in.number<std::uint64_t>();
    v.individuals = in.number<std::uint64_t>();
    std::uint32_t lengths[5];
    for (std::uint32_t& n : lengths) n = in.number<std::uint32_t>();
    v.genes = in.bytes(lengths[0]);
    v.offsets = in.bytes(lengths[1]);
    v.geneCounts = in.bytes(lengths[2]);
    v.fitness = in.bytes(lengths[3]);
    v.rng = in.bytes(lengths[4]);
    v.curve = in.bytes(in.left);
    try {
        checkAccepted(decodeIsland(v, *family, kLimits, "fuzz"), v);
    } catch (const InputError&) {
    }
}

void fuzzFiles(Input in) {
    const std::size_t manifestLength = in.number<std::uint16_t>();
    const std::size_t runLength = in.number<std::uint32_t>();
    writeBytes(folder + "/MANIFEST", in.bytes(manifestLength));
    writeBytes(folder + "/run.h5", in.bytes(runLength));
    writeBytes(folder + "/island-0000.h5", in.bytes(in.left));
    if (!verifyCheckpoint(folder).empty()) return;
    try {
        readRunMetadata(folder + "/run.h5");
        const IslandState s = readIslandFile(folder + "/island-0000.h5", *family, kLimits);
        for (const Chromosome& c : s.population.individuals) CHECK(validateChromosome(*grammar, c, kLimits).empty());
        CHECK(!describeCheckpoint(folder, true).empty());
    } catch (const InputError&) {
    }
}

// --- attributes mode -------------------------------------------------------------------------

std::vector<std::uint8_t> baseRun, baseIsland;  // a valid checkpoint's two files

void fuzzAttributes(Input in) {
    const bool island = in.number<std::uint8_t>() % 2 == 1;
    const unsigned index = in.number<std::uint8_t>();
    const std::span<const std::uint8_t> value = in.bytes(in.left);
    writeBytes(folder + "/run.h5", baseRun);
    writeBytes(folder + "/island-0000.h5", baseIsland);
    const std::string path = folder + (island ? "/island-0000.h5" : "/run.h5");
    bool changed = false;
    {
        const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
        CHECK(f >= 0);
        H5O_info_t info;
        CHECK(H5Oget_info2(f, &info, H5O_INFO_NUM_ATTRS) >= 0 && info.num_attrs > 0);
        const hid_t a = H5Aopen_by_idx(f, ".", H5_INDEX_NAME, H5_ITER_INC, hsize_t(index % info.num_attrs), H5P_DEFAULT,
                                       H5P_DEFAULT);
        CHECK(a >= 0);
        const hid_t type = H5Aget_type(a);
        const std::size_t size = H5Tget_size(type);
        std::vector<std::uint8_t> old(size), now(size, 0);
        CHECK(H5Aread(a, type, old.data()) >= 0);
        for (std::size_t i = 0; i < size && !value.empty(); ++i) now[i] = value[i % value.size()];
        changed = now != old;
        CHECK(H5Awrite(a, type, now.data()) >= 0);
        H5Tclose(type);
        H5Aclose(a);
        CHECK(H5Fclose(f) >= 0);
    }
    writeManifest(folder, {"run.h5", "island-0000.h5"});
    CHECK(verifyCheckpoint(folder).empty());
    bool refused = false;
    try {
        if (island) readIslandFile(path, *family, kLimits);
        else readRunMetadata(path);
    } catch (const InputError&) {
        refused = true;
    }
    CHECK(refused == changed);  // an altered attribute is never accepted; an unaltered file always is
}

// --- seeds -----------------------------------------------------------------------------------

void appendLE(std::vector<std::uint8_t>& out, const void* v, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(v);
    out.insert(out.end(), b, b + n);  // x86-64 and arm64 are little-endian, as the format is
}

std::vector<std::uint8_t> readAll(const std::string& path) {
    std::vector<std::uint8_t> b(fs::file_size(path));
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f || std::fread(b.data(), 1, b.size(), f) != b.size()) std::abort();
    std::fclose(f);
    return b;
}

/// Write seeds into `dir`: real checkpoints (files mode) and their decoder-mode equivalents.
void writeSeeds(const std::string& dir) {
    fs::create_directories(dir);
    Rng rng(2024);
    for (int seed = 0; seed < 4; ++seed) {
        IslandState s;
        s.generation = std::uint32_t(seed);
        s.evaluations = 100u * std::uint32_t(seed);
        for (int i = 0; i < seed + 1; ++i) {
            Chromosome c;
            const std::uint32_t genes = 1 + rng.below(seed == 3 ? 40 : 6);
            while (c.genes < genes && grow(*grammar, c, rng, kLimits)) {
            }
            s.population.individuals.push_back(c);
            s.population.fitness.push_back(rng.uniform() - 0.5);
        }
        for (int r = 0; r < seed; ++r) s.curve.push_back({std::uint32_t(r), 0.25 * r, 10u * std::uint32_t(r), 0.5, 0.25, 0.125});
        s.rng = rng.state();
        RunMetadata m;
        m.seed = std::uint64_t(seed);
        m.generation = s.generation;
        m.grammarText = grammar->source;
        m.grammarPath = "spaceship.grammar";
        m.configText = "[ga]\npopulation = " + std::to_string(seed + 1) + "\n";
        m.curve = s.curve;

        writeIslandFile(folder + "/island-0000.h5", s);
        writeRunMetadata(folder + "/run.h5", m);
        writeManifest(folder, {"run.h5", "island-0000.h5"});
        const auto manifest = readAll(folder + "/MANIFEST"), run = readAll(folder + "/run.h5"),
                   island = readAll(folder + "/island-0000.h5");
        std::vector<std::uint8_t> files{0};
        const std::uint16_t m16 = std::uint16_t(manifest.size());
        const std::uint32_t r32 = std::uint32_t(run.size());
        appendLE(files, &m16, 2);
        appendLE(files, &r32, 4);
        files.insert(files.end(), manifest.begin(), manifest.end());
        files.insert(files.end(), run.begin(), run.end());
        files.insert(files.end(), island.begin(), island.end());
        writeBytes(dir + "/files-" + std::to_string(seed), files);

        const IslandBytes b = encodeIsland(s);
        std::vector<std::uint8_t> dec{1};
        appendLE(dec, &b.rank, 4);
        appendLE(dec, &b.generation, 4);
        appendLE(dec, &b.evaluations, 8);
        appendLE(dec, &b.individuals, 8);
        for (const auto* part : {&b.genes, &b.offsets, &b.geneCounts, &b.fitness, &b.rng}) {
            const std::uint32_t n = std::uint32_t(part->size());
            appendLE(dec, &n, 4);
        }
        for (const auto* part : {&b.genes, &b.offsets, &b.geneCounts, &b.fitness, &b.rng, &b.curve})
            dec.insert(dec.end(), part->begin(), part->end());
        writeBytes(dir + "/decoder-" + std::to_string(seed), dec);

        const std::uint8_t attributes[] = {2, std::uint8_t(seed), std::uint8_t(3 * seed + 1), 0x5a, 0x00, 0x01};
        writeBytes(dir + "/attributes-" + std::to_string(seed), attributes);
    }
    std::printf("wrote 12 seeds to %s\n", dir.c_str());
}

void removeFolder() {
    std::error_code ec;
    fs::remove_all(folder, ec);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    static const Grammar g = loadGrammar(std::string(SHAPEVO_SOURCE_DIR) + "/grammars/spaceship.grammar");
    grammar = &g;
    static const TreeFamily tree(g);
    family = &tree;
    const char* tmp = std::getenv("TMPDIR");  // .ci/fuzz points it into its own work folder
    std::string name = std::string(tmp && *tmp ? tmp : "/tmp") + "/fuzz_checkpoint_reader.XXXXXX";
    if (!mkdtemp(name.data())) {
        std::perror("mkdtemp");
        std::abort();
    }
    folder = name;
    std::atexit(removeFolder);
    {  // the attributes mode's valid checkpoint: one island of two random chromosomes
        Rng rng(7);
        IslandState s;
        s.runId = "0123456789abcdef0123456789abcdef";
        s.generation = 3;
        for (int i = 0; i < 2; ++i) {
            Chromosome c;
            while (c.genes < 4 && grow(*grammar, c, rng, kLimits)) {
            }
            s.population.individuals.push_back(c);
            s.population.fitness.push_back(0.25 * i);
        }
        s.rng = rng.state();
        RunMetadata m;
        m.runId = s.runId;
        m.generation = s.generation;
        m.grammarText = grammar->source;
        m.grammarPath = "spaceship.grammar";
        writeIslandFile(folder + "/island-0000.h5", s);
        writeRunMetadata(folder + "/run.h5", m);
        baseIsland = readAll(folder + "/island-0000.h5");
        baseRun = readAll(folder + "/run.h5");
    }
    if (const char* seeds = std::getenv("SHAPEVO_FUZZ_WRITE_SEEDS")) {
        writeSeeds(seeds);
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    Input in{data + 1, size - 1};
    switch (data[0] % 4) {
    case 0: fuzzFiles(in); break;
    case 2: fuzzAttributes(in); break;
    default: fuzzDecoder(in); break;
    }
    return 0;
}

// Helpers for the checkpoint tests: a real island state (random spaceship chromosomes grown by
// the genome operators), run metadata, a whole checkpoint folder, and byte-level file surgery.
#pragma once
#include <hdf5.h>
#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "checkpoint/checkpoint_file.hpp"
#include "genome/families/tree_family.hpp"
#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "../test_support.hpp"

namespace shapevo::test {

inline const Grammar& spaceship() {
    static const Grammar g = loadGrammar(sourcePath("grammars/spaceship.grammar"));
    return g;
}

/// The spaceship grammar's genome, as readIslandFile and decodeIsland check it.
inline const TreeFamily& spaceshipFamily() {
    static const TreeFamily family(spaceship());
    return family;
}

inline constexpr GenomeLimits kLimits{60};

/// `individuals` random spaceships of 1..60 genes, distinct fitness values (including negative
/// and subnormal ones, so "bit-identical" means something), a curve of `rows` rows.
inline IslandState makeIsland(int rank, std::size_t individuals = 24, std::size_t rows = 5, std::uint64_t seed = 17) {
    Rng rng(seed + std::uint64_t(rank));
    IslandState s;
    s.rank = rank;
    s.generation = std::uint32_t(rows);
    s.evaluations = 1234567 + std::uint64_t(rank);
    for (std::size_t i = 0; i < individuals; ++i) {
        Chromosome c;
        const std::uint32_t target = 1 + rng.below(kLimits.maxGenes);
        while (c.genes < target && grow(spaceship(), c, rng, kLimits)) {
        }
        s.population.individuals.push_back(std::move(c));
        s.population.fitness.push_back(i == 3 ? 4.9e-324 : (rng.uniform() - 0.3) * 1e3);
    }
    for (std::size_t r = 0; r < rows; ++r)
        s.curve.push_back({std::uint32_t(r + 1), 0.1 * double(r) + 1.0 / 3.0, (r + 1) * 200ULL, 0.9 - 1.0 / double(r + 7),
                           0.5 + std::sqrt(double(r)), 1.0 / double(r + 3),
                           r == 1 ? std::numeric_limits<double>::quiet_NaN() : 1.0 / double(r + 2)});  // iou; one not measured
    rng.next();
    s.rng = rng.state();
    return s;
}

/// The run id of makeRun's run (any 32 hex digits).
inline const std::string kRunId = "00112233445566778899aabbccddeeff";

inline RunMetadata makeRun(int ranks, std::uint32_t generation = 5, const std::string& runId = kRunId) {
    RunMetadata m;
    m.runId = runId;
    m.inputs = {{"grammar", sourcePath("grammars/spaceship.grammar"), 0x1234}};
    m.seed = 0xfeedface12345678ULL;
    m.generation = generation;
    m.ranks = ranks;
    m.wallSeconds = 12.75;
    m.targetHash = 0x0123456789abcdefULL;
    m.name = "spaceship-test";
    m.configPath = "configs/spaceship.toml";
    m.configText = "[run]\nname = \"spaceship-test\"\n\n[ga]\npopulation = 24\n";
    m.grammarPath = sourcePath("grammars/spaceship.grammar");
    m.grammarText = spaceship().source;
    for (std::uint32_t r = 1; r <= generation; ++r) m.curve.push_back({r, r * 0.5, r * 48ULL, 0.1 * r, 0.05 * r, 0.01, 0.02 * r});
    return m;
}

/// A complete checkpoint folder `dir/checkpoint-NNNNNN` with `ranks` islands, as a run makes it
/// (written into a partial folder, MANIFEST last, then published). Returns its path.
inline std::string writeCheckpoint(const std::filesystem::path& dir, std::uint32_t generation, int ranks = 1,
                                   const std::string& runId = kRunId) {
    const std::string partial = (dir / ("." + checkpointName(generation) + ".partial")).string();
    std::filesystem::create_directories(partial);
    std::vector<std::string> files{"run.h5"};
    const RunMetadata run = makeRun(ranks, generation, runId);
    writeRunMetadata(partial + "/run.h5", run);
    for (int r = 0; r < ranks; ++r) {
        IslandState island = makeIsland(r);
        island.runId = run.runId;
        island.seed = run.seed;
        island.ranks = ranks;
        island.generation = generation;
        writeIslandFile(partial + "/" + islandFileName(r), island);
        files.push_back(islandFileName(r));
    }
    writeManifest(partial, files);
    const std::string final = (dir / checkpointName(generation)).string();
    publishCheckpoint(partial, final, runId);
    return final;
}

inline std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void setFileBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

/// Rewrites a u32 root attribute in place, through libhdf5 (so the file stays a valid HDF5 file
/// and only the attribute checksum can tell).
inline void setRootU32Attribute(const std::string& path, const char* name, std::uint32_t value) {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t a = H5Aopen(f, name, H5P_DEFAULT);
    ASSERT_GE(a, 0);
    ASSERT_GE(H5Awrite(a, H5T_NATIVE_UINT32, &value), 0);
    H5Aclose(a);
    H5Fclose(f);
}

inline void flipByte(const std::string& path, std::size_t at) {
    std::string b = fileBytes(path);
    b.at(at) = char(b.at(at) ^ 0x5a);
    setFileBytes(path, b);
}

}  // namespace shapevo::test

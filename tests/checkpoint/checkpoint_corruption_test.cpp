// Damaged checkpoints are reported by name: the MANIFEST catches truncated and altered files
// before libhdf5 sees them, the per-dataset checksums catch altered data even when the MANIFEST
// was rewritten to match, and the content checks catch invalid chromosomes with valid checksums.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>
#include <hdf5.h>

#include "checkpoint_test_util.hpp"
#include "checkpoint/island_codec.hpp"
#include "base/input_error.hpp"

namespace shapevo {
namespace {

using test::spaceshipFamily;

/// File offset of a contiguous dataset's data.
haddr_t dataOffset(const std::string& file, const char* dataset) {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t d = H5Dopen2(f, dataset, H5P_DEFAULT);
    const haddr_t at = H5Dget_offset(d);
    H5Dclose(d);
    H5Fclose(f);
    return at;
}

/// The InputError readIslandFile throws, or a failure.
InputError readError(const std::string& path) {
    try {
        readIslandFile(path, spaceshipFamily(), test::kLimits);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "readIslandFile accepted " << path;
    return InputError(path, "", "");
}

TEST(CheckpointCorruption, CompleteCheckpointVerifies) {
    test::TempDir dir;
    EXPECT_EQ(verifyCheckpoint(test::writeCheckpoint(dir.path(), 5, 2)), "");
}

TEST(CheckpointCorruption, TruncatedIslandFileIsRejectedByNameBeforeHdf5) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 5, 2);
    const std::string island = cp + "/island-0001.h5";
    std::filesystem::resize_file(island, std::filesystem::file_size(island) / 2);
    const std::string why = verifyCheckpoint(cp);
    EXPECT_NE(why.find("island-0001.h5"), std::string::npos) << why;
    EXPECT_NE(why.find("truncated"), std::string::npos) << why;
    // Read directly anyway, libhdf5 fails cleanly and the error names the file.
    EXPECT_EQ(readError(island).file(), island);
}

TEST(CheckpointCorruption, OneFlippedByteIsRejectedByName) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 5, 2);
    test::flipByte(cp + "/island-0000.h5", std::filesystem::file_size(cp + "/island-0000.h5") / 3);
    const std::string why = verifyCheckpoint(cp);
    EXPECT_NE(why.find("island-0000.h5"), std::string::npos) << why;
}

TEST(CheckpointCorruption, MissingOrTruncatedManifestMeansIncomplete) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 5);
    const std::string manifest = test::fileBytes(cp + "/MANIFEST");
    test::setFileBytes(cp + "/MANIFEST", manifest.substr(0, manifest.size() - 4));
    EXPECT_NE(verifyCheckpoint(cp).find("MANIFEST"), std::string::npos);
    std::filesystem::remove(cp + "/MANIFEST");
    EXPECT_NE(verifyCheckpoint(cp).find("MANIFEST"), std::string::npos);
    EXPECT_THROW(readManifest(cp), InputError);
}

TEST(CheckpointCorruption, ManifestMustListRunAndIslandsWithoutGaps) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 5, 3);
    writeManifest(cp, {"run.h5", "island-0000.h5", "island-0002.h5"});
    EXPECT_NE(verifyCheckpoint(cp).find("island-0001.h5"), std::string::npos) << verifyCheckpoint(cp);
    writeManifest(cp, {"island-0000.h5"});
    EXPECT_NE(verifyCheckpoint(cp).find("run.h5"), std::string::npos) << verifyCheckpoint(cp);
    EXPECT_THROW(writeManifest(cp, {"../run.h5"}), std::runtime_error);
}

TEST(CheckpointCorruption, FlippedDatasetByteBehindRewrittenManifestIsCaughtByDatasetChecksum) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 5, 1);
    const std::string island = cp + "/island-0000.h5";
    for (const char* dataset : {"/population/fitness", "/population/genes", "/rng/state"}) {
        const std::string original = test::fileBytes(island);
        test::flipByte(island, dataOffset(island, dataset) + 5);
        writeManifest(cp, {"run.h5", "island-0000.h5"});
        ASSERT_EQ(verifyCheckpoint(cp), "");  // the manifest matches the altered file
        const InputError e = readError(island);
        EXPECT_EQ(e.where(), dataset) << e.what();
        EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
        test::setFileBytes(island, original);
    }
}

TEST(CheckpointCorruption, FlippedConfigTextIsCaughtByItsChecksum) {
    test::TempDir dir;
    const std::string path = dir.file("run.h5");
    writeRunMetadata(path, test::makeRun(1));
    test::flipByte(path, dataOffset(path, "/config/text") + 2);
    try {
        readRunMetadata(path);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), "/config/text") << e.what();
    }
}

TEST(CheckpointCorruption, InvalidChromosomeWithValidChecksumIsRejectedNamingGenes) {
    test::TempDir dir;
    IslandState s = test::makeIsland(0, 6);
    s.population.individuals[4].words[0] = 999;  // an unknown rule id; the checksum covers it
    writeIslandFile(dir.file("island-0000.h5"), s);
    const InputError e = readError(dir.file("island-0000.h5"));
    EXPECT_EQ(e.where(), "/population/genes") << e.what();
    EXPECT_NE(std::string(e.what()).find("individual 4"), std::string::npos) << e.what();
}

TEST(CheckpointCorruption, ChromosomeOverTheGenomeLimitIsRejectedNamingGeneCounts) {
    test::TempDir dir;
    writeIslandFile(dir.file("island-0000.h5"), test::makeIsland(0, 10));
    try {
        readIslandFile(dir.file("island-0000.h5"), spaceshipFamily(), GenomeLimits{1});
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), "/population/gene_counts") << e.what();
    }
}

// The decoder's shape checks, on bytes encodeIsland made and then broke.
class CheckpointDecoder : public ::testing::Test {
protected:
    IslandBytes bytes = encodeIsland(test::makeIsland(0, 5));
    std::string whereDecodeFails() {
        try {
            decodeIsland(bytes.view(), spaceshipFamily(), test::kLimits, "mem");
        } catch (const InputError& e) {
            return e.where();
        }
        return "(accepted)";
    }
};

TEST_F(CheckpointDecoder, AcceptsWhatEncodeMade) { EXPECT_EQ(whereDecodeFails(), "(accepted)"); }

TEST_F(CheckpointDecoder, OffsetsThatDecreaseAreRejected) {
    std::swap_ranges(bytes.offsets.begin() + 8, bytes.offsets.begin() + 16, bytes.offsets.begin() + 16);
    EXPECT_EQ(whereDecodeFails(), "/population/offsets");
}

TEST_F(CheckpointDecoder, LastOffsetMustBeTheNumberOfWords) {
    bytes.genes.resize(bytes.genes.size() - 4);
    EXPECT_EQ(whereDecodeFails(), "/population/offsets");
}

TEST_F(CheckpointDecoder, CountsMustMatchTheIndividualsAttribute) {
    bytes.individuals = 4;
    EXPECT_EQ(whereDecodeFails(), "/population/offsets");
    bytes = encodeIsland(test::makeIsland(0, 5));
    bytes.geneCounts.resize(16);
    EXPECT_EQ(whereDecodeFails(), "/population/gene_counts");
    bytes = encodeIsland(test::makeIsland(0, 5));
    bytes.fitness.push_back(0);
    EXPECT_EQ(whereDecodeFails(), "/population/fitness");
    bytes = encodeIsland(test::makeIsland(0, 5));
    bytes.rng.resize(24);
    EXPECT_EQ(whereDecodeFails(), "/rng/state");
}

TEST_F(CheckpointDecoder, NonFiniteFitnessIsRejected) {
    for (int k = 0; k < 8; ++k) bytes.fitness[8 + k] = 0xff;  // individual 1 = NaN
    EXPECT_EQ(whereDecodeFails(), "/population/fitness");
}

TEST_F(CheckpointDecoder, CurveIntegerColumnsMustBeWholeAndInRange) {
    bytes.curve[7] = 0xc0;  // row 0, generation: a negative number
    EXPECT_EQ(whereDecodeFails(), "/curve");
    bytes = encodeIsland(test::makeIsland(0, 5));
    bytes.curve.resize(bytes.curve.size() - 8);
    EXPECT_EQ(whereDecodeFails(), "/curve");
}

}  // namespace
}  // namespace shapevo

// writeAtomically: the file appears whole or not at all, no temporary stays behind, a failing
// writer leaves the old content, and Replace::Never never replaces an existing file.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "../test_support.hpp"
#include "base/atomic_write.hpp"
#include "base/input_error.hpp"

namespace shapevo {
namespace {

std::size_t entries(const std::filesystem::path& dir) {
    return std::size_t(std::distance(std::filesystem::directory_iterator(dir), {}));
}

TEST(AtomicWrite, WritesTheWholeFileAndLeavesNoTemporary) {
    test::TempDir dir;
    const std::string path = dir.file("out.txt");
    writeStreamAtomically(path, [](std::ostream& out) { out << "first"; });
    writeStreamAtomically(path, [](std::ostream& out) { out << "second"; });
    EXPECT_EQ(test::readFile(path), "second");
    EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicWrite, AFailingWriterKeepsTheOldContentAndRemovesItsTemporary) {
    test::TempDir dir;
    const std::string path = dir.file("out.txt");
    writeStreamAtomically(path, [](std::ostream& out) { out << "kept"; });
    EXPECT_THROW(writeStreamAtomically(path,
                                       [](std::ostream& out) {
                                           out << "half";
                                           throw std::runtime_error("writer failed");
                                       }),
                 std::runtime_error);
    EXPECT_EQ(test::readFile(path), "kept");
    EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicWrite, ReplaceNeverRefusesAnExistingFileAndKeepsIt) {
    test::TempDir dir;
    const std::string path = dir.file("target.vdb");
    auto write = [](const char* text) {
        return [text](const std::string& temp) { test::writeFile(temp, text); };
    };
    writeAtomically(path, write("one"), Replace::Never);
    EXPECT_EQ(test::readFile(path), "one");
    EXPECT_THROW(writeAtomically(path, write("two"), Replace::Never), InputError);
    EXPECT_EQ(test::readFile(path), "one");
    EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicWrite, AMissingFolderIsAnErrorNamingTheFile) {
    test::TempDir dir;
    const std::string path = dir.file("no/such/folder/out.txt");
    try {
        writeStreamAtomically(path, [](std::ostream& out) { out << "x"; });
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

TEST(SyncToDisk, AMissingPathThrows) {
    test::TempDir dir;
    EXPECT_THROW(syncToDisk(dir.file("missing")), std::runtime_error);
    EXPECT_NO_THROW(syncToDisk(dir.path().string()));
}

}  // namespace
}  // namespace shapevo

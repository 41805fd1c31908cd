// Every attribute of a checkpoint file is covered by the root attribute attributes_xxh3_64:
// an altered value (a forged generation, rank or seed) is refused when the file is opened,
// before any value can be used; a file without the checksum is refused too.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint_test_util.hpp"

namespace shapevo {
namespace {

void expectAttributeChecksumError(const std::function<void()>& read) {
    try {
        read();
        FAIL() << "an altered attribute was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("attributes_xxh3_64"), std::string::npos) << e.what();
    }
}

TEST(AttributeChecksum, AForgedIslandGenerationIsRefused) {
    test::TempDir dir;
    const std::string path = dir.file("island-0000.h5");
    writeIslandFile(path, test::makeIsland(0));
    EXPECT_NO_THROW(readIslandFile(path, test::spaceshipFamily(), test::kLimits));
    test::setRootU32Attribute(path, "generation", 1515870824u);
    expectAttributeChecksumError([&] { readIslandFile(path, test::spaceshipFamily(), test::kLimits); });
}

TEST(AttributeChecksum, AForgedRunGenerationIsRefused) {
    test::TempDir dir;
    const std::string path = dir.file("run.h5");
    writeRunMetadata(path, test::makeRun(2));
    test::setRootU32Attribute(path, "generation", 99);
    expectAttributeChecksumError([&] { readRunMetadata(path); });
}

TEST(AttributeChecksum, AFileWithoutTheChecksumIsRefused) {
    test::TempDir dir;
    const std::string path = dir.file("run.h5");
    writeRunMetadata(path, test::makeRun(2));
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    ASSERT_GE(H5Adelete(f, "attributes_xxh3_64"), 0);
    H5Fclose(f);
    expectAttributeChecksumError([&] { readRunMetadata(path); });
}

}  // namespace
}  // namespace shapevo

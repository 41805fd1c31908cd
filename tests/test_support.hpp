// Helpers shared by the tests: paths into the source tree and a temporary folder per test.
#pragma once
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace shapevo::test {

inline std::string sourcePath(const std::string& relative) { return std::string(SHAPEVO_SOURCE_DIR) + "/" + relative; }

/// A fresh empty directory under the system temp dir, removed when the object goes away.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string("shapevo-") + (info ? std::string(info->test_suite_name()) + "-" + info->name() : "t");
        for (char& c : name)
            if (c == '/') c = '_';
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() { std::filesystem::remove_all(path_); }
    const std::filesystem::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

}  // namespace shapevo::test

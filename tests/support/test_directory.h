// test_directory.h — a fixture whose every test writes into its own fresh directory, since
// CTest may run tests of one binary in parallel processes.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace vkpt::test {

// The bytes of a file a test wrote (empty when it cannot be read), for comparing outputs bit
// for bit.
inline std::vector<char> bytesOf(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class TestDirectory : public ::testing::Test {
protected:
    // <temp>/<prefix>_<test name>_<pid>, created empty and removed after the test.
    explicit TestDirectory(std::string prefix) : prefix_(std::move(prefix)) {}

    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               (prefix_ + "_" + std::string(info->name()) + "_" + std::to_string(getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    std::filesystem::path dir_;

private:
    std::string prefix_;
};

} // namespace vkpt::test

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Shared by the command-line tests (tests/cli_test.cpp for `mcadsw`,
// tests/rtl/sim_cli_test.cpp for `mcadsw_sim`): run a binary, and a fixture
// with a scratch directory that checks a failure left no output behind.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace mcadsw::test {

struct CliRun {
  int status;
  std::string output;  // stdout and stderr
};

inline CliRun run_command(const std::string& binary, const std::string& args) {
  const std::string cmd = binary + " " + args + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), int(buf.size()), pipe.get())) out += buf.data();
  const int status = pclose(pipe.release());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("mcadsw_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    out_ = (dir_ / "out.png").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // Non-zero exit, `message` in the output, and nothing written.
  void expect_failure(const CliRun& r, const std::string& message) {
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out_));
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out_color.png"));
  }
  std::filesystem::path dir_;
  std::string out_;
};

}  // namespace mcadsw::test

// Commands run as processes, the way the command-line tests run `vplab`: through the shell, in a
// directory of the test's own, with stdout, stderr and the exit code captured.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace vplab::test {

/// `s` in single quotes for the shell: one word, whatever characters it holds.
std::string shellQuoted(const std::string& s);

struct ProcessResult {
  int exitCode = -1;  // -1 when the process did not exit normally (a signal)
  std::string out, err;
};

/// A fixture whose tests each get a fresh directory, removed afterwards unless the test failed:
/// what a failed command left behind is then there to look at.
class ProcessTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  /// Runs `command` with sh in the test's directory.
  ProcessResult sh(const std::string& command);

  std::filesystem::path dir_;
};

}  // namespace vplab::test

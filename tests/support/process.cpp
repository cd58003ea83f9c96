#include "tests/support/process.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "tests/support/files.h"

namespace vplab::test {

namespace fs = std::filesystem;

std::string shellQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void ProcessTest::SetUp() {
  // Named after the test, so that a directory left by a failure says whose it is.
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name =
      std::string(info->test_suite_name()) + "-" + info->name() + "-" + std::to_string(getpid());
  std::replace(name.begin(), name.end(), '/', '_');  // parameterized tests' names have slashes
  dir_ = fs::temp_directory_path() / ("vplab-" + name);
  fs::remove_all(dir_);
  fs::create_directories(dir_);
}

void ProcessTest::TearDown() {
  if (!HasFailure())
    fs::remove_all(dir_);
  else
    std::cout << "left for inspection: " << dir_.string() << "\n";
}

ProcessResult ProcessTest::sh(const std::string& command) {
  const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
  const std::string full = "cd " + shellQuoted(dir_.string()) + " && " + command + " >" +
                           shellQuoted(out.string()) + " 2>" + shellQuoted(err.string());
  const int status = std::system(full.c_str());
  ProcessResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(out), readFile(err)};
  fs::remove(out);
  fs::remove(err);
  return r;
}

}  // namespace vplab::test

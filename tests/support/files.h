// Real files for the tests that need them: a directory of the test's own and a file's contents.
// One copy for every suite (tests/CMakeLists.txt links vplab_test_support into the binaries that use it).
#pragma once

#include <filesystem>
#include <string>

namespace vplab::test {

/// A fresh directory under the system's temporary directory, removed with everything in it at the
/// end of the test. mkdtemp names it, so tests running at the same time never share one.
struct TempDir {
  std::filesystem::path path;

  TempDir();
  ~TempDir();
  // Two owners would remove the directory twice.
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// Writes `text` to the file `name` in the directory and returns the file's path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;
};

/// The file's bytes; empty when it cannot be read, so that the comparison the test makes fails.
std::string readFile(const std::filesystem::path& file);

}  // namespace vplab::test

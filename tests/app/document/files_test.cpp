// Files the viewer writes without a window (app/document/atomic_file.h, app/document/autosave.h): a failed
// save leaves the old file whole and keeps its mode, and the autosave's directory and recovery offers
// (the viewer's autosave in a session: tests/app/ui/runtime_test.cpp).
#include "app/document/atomic_file.h"
#include "app/document/autosave.h"
#include "io/scene_io.h"
#include "base/error.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::readFile;
using test::TempDir;

TEST(AtomicSave, AFailedWriteLeavesTheOldFileWhole) {
  TempDir dir;
  const fs::path file = dir.path / "scene.json";
  const std::string old = sceneToJson(defaultScene());
  writeFileAtomically(file, old);
  ASSERT_EQ(readFile(file), old);
  // The disk fills up half-way: the file-size limit makes write(2) fail with EFBIG (SIGXFSZ ignored).
  const std::string big(200000, 'x');
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 100000;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    writeFileAtomically(file, big);
  } catch (const Error& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, oldHandler);
  EXPECT_THAT(message, HasSubstr("scene.json"));
  EXPECT_THAT(message, HasSubstr("unchanged"));
  EXPECT_EQ(readFile(file), old);
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path)) ++files;
  EXPECT_EQ(files, 1u) << "a temporary file was left behind";
}

TEST(AtomicSave, KeepsTheModeOfTheFileItReplaces) {
  TempDir dir;
  const fs::path file = dir.path / "scene.json";
  std::ofstream(file) << "old";
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  writeFileAtomically(file, "new");
  EXPECT_EQ(readFile(file), "new");
  EXPECT_EQ(fs::status(file).permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(Autosave, TheFileOfARunningSessionIsNotOffered) {
  TempDir dir;
  Document doc(defaultScene());
  doc.scene().camera.front = 0.5;
  doc.endFrame(false);
  Autosave a(dir.path, 0);
  ASSERT_TRUE(a.writeNow(doc));
  EXPECT_FALSE(Autosave::find(dir.path).has_value());  // our own process runs
}

TEST(Autosave, DefaultDirectoryFollowsXdgStateHome) {
  const char* old = std::getenv("XDG_STATE_HOME");
  const std::string keep = old ? old : "";
  ::setenv("XDG_STATE_HOME", "/tmp/xdg-state", 1);
  EXPECT_EQ(Autosave::defaultDirectory(), fs::path("/tmp/xdg-state/vplab"));
  ::unsetenv("XDG_STATE_HOME");
  if (const char* home = std::getenv("HOME")) {
    EXPECT_EQ(Autosave::defaultDirectory(), fs::path(home) / ".local/state/vplab");
  }
  if (old) ::setenv("XDG_STATE_HOME", keep.c_str(), 1);
}

}  // namespace
}  // namespace vplab

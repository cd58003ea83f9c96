#include "app/document/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "base/error.h"

namespace vplab {

namespace {

std::string reason() { return std::strerror(errno); }

/// The mode a newly created file gets (0666 less the umask), always readable and writable by its
/// owner: emscripten's file system (the browser build) reports a umask of 0777, which would leave
/// a saved scene unreadable. umask can only be read by setting it, so it is set back at once; the
/// viewer has a single thread writing files.
mode_t newFileMode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return (0666 & ~mask) | S_IRUSR | S_IWUSR;
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& file, std::string_view text) {
  const std::filesystem::path dir = file.parent_path().empty() ? "." : file.parent_path();
  std::string pattern = (dir / ("." + file.filename().string() + ".XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw Error(file.string() + ": cannot write the file: " + reason());
  const std::string tmp(name.data());
  auto fail = [&](const std::string& what) {
    const std::string why = reason();
    ::close(fd);
    ::unlink(tmp.c_str());  // the target is untouched; leave no partial temporary file behind
    throw Error(file.string() + ": " + what + ": " + why + " (the file is unchanged)");
  };
  struct stat old {};
  ::fchmod(fd, ::stat(file.c_str(), &old) == 0 ? (old.st_mode & 07777) : newFileMode());
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("writing failed");
    done += size_t(n);
  }
  if (::fsync(fd) != 0) fail("flushing to the disk failed");
  if (::close(fd) != 0) {
    const std::string why = reason();
    ::unlink(tmp.c_str());
    throw Error(file.string() + ": writing failed: " + why + " (the file is unchanged)");
  }
  if (::rename(tmp.c_str(), file.c_str()) != 0) {
    const std::string why = reason();
    ::unlink(tmp.c_str());
    throw Error(file.string() + ": cannot replace the file: " + why + " (the file is unchanged)");
  }
  // Make the rename itself durable; a failure here loses nothing already written.
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace vplab

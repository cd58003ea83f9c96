// Writing a file so that a crash, a full disk or a killed process never leaves it truncated: the
// text goes to a temporary file in the same directory, is flushed to the disk (fsync), and only
// then renamed over the target (rename(2) replaces a directory entry atomically on POSIX file
// systems). Readers see the old file or the new one, never a mixture.
#pragma once

#include <filesystem>
#include <string_view>

namespace vplab {

/// Replaces `file` by `text` atomically. Throws vplab::Error naming the file and the system's reason;
/// then `file` is unchanged and no temporary file is left behind. A new file gets mode 0666 less the
/// umask, an existing one keeps its mode.
void writeFileAtomically(const std::filesystem::path& file, std::string_view text);

}  // namespace vplab

// Reading a whole input file (a scene or an OBJ mesh) under a size limit: only regular files are
// read, so /dev/zero, a FIFO or a directory is a clear error instead of endless memory growth.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace vplab {

/// The bytes of `file`, which must be a regular file (symbolic links followed) of at most `maxBytes`.
/// `what` names the kind of file in messages ("scene file", "OBJ file"). Throws vplab::Error
/// "FILE: what is wrong", naming the limit and the size when it is too large.
std::string readRegularFile(const std::filesystem::path& file, std::uintmax_t maxBytes, std::string_view what);

/// "8 MiB (8388608 bytes)": a limit in bytes for messages.
std::string formatBytes(std::uintmax_t bytes);

}  // namespace vplab

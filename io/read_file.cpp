#include "io/read_file.h"

#include "base/error.h"

#include <fstream>

namespace vplab {

namespace {

std::string_view kindOf(std::filesystem::file_type t) {
  using T = std::filesystem::file_type;
  switch (t) {
    case T::directory: return "a directory";
    case T::fifo: return "a FIFO (named pipe)";
    case T::character: return "a character device";
    case T::block: return "a block device";
    case T::socket: return "a socket";
    default: return "not a regular file";
  }
}

}  // namespace

std::string formatBytes(std::uintmax_t bytes) {
  std::string exact = std::to_string(bytes) + " bytes";
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB (" + exact + ")";
  return exact;
}

std::string readRegularFile(const std::filesystem::path& file, std::uintmax_t maxBytes, std::string_view what) {
  const std::string name = file.string();
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);  // follows symbolic links
  if (ec || !std::filesystem::exists(status))
    throw Error(name + ": cannot open the " + std::string(what) + (ec ? ": " + ec.message() : ": no such file"));
  if (!std::filesystem::is_regular_file(status))
    throw Error(name + ": is " + std::string(kindOf(status.type())) + "; " +
                (std::string_view("aeiouAEIOU").find(what.front()) != std::string_view::npos ? "an " : "a ") +
                std::string(what) + " must be a regular file");
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > maxBytes)
    throw Error(name + ": the " + std::string(what) + " has " + std::to_string(size) + " bytes; the limit is " +
                formatBytes(maxBytes));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(name + ": cannot open the " + std::string(what));
  // Read at most one byte past the limit: a file that grows while it is read is still bounded.
  std::string text(size_t(std::min<std::uintmax_t>(ec ? 0 : size, maxBytes)), '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(size_t(in.gcount()));
  char chunk[65536];
  while (in && text.size() <= maxBytes) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, size_t(in.gcount()));
  }
  if (in.bad()) throw Error(name + ": reading the " + std::string(what) + " failed");
  if (text.size() > maxBytes)
    throw Error(name + ": the " + std::string(what) + " has more than " + std::to_string(maxBytes) +
                " bytes; the limit is " + formatBytes(maxBytes));
  return text;
}

}  // namespace vplab

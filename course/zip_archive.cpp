#include "course/zip_archive.h"

#include "base/error.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>

namespace vplab {

namespace {

void put16(std::string& out, uint32_t v) {
  out += char(v & 0xFF);
  out += char((v >> 8) & 0xFF);
}
void put32(std::string& out, uint32_t v) {
  put16(out, v & 0xFFFF);
  put16(out, v >> 16);
}

void checkName(const std::string& name) {
  bool bad = name.empty() || name.size() > 0xFFFF || name[0] == '/' || name.find('\\') != std::string::npos ||
             name.find('\0') != std::string::npos;
  size_t at = 0;
  while (!bad && at <= name.size()) {
    const size_t end = std::min(name.find('/', at), name.size());
    const std::string part = name.substr(at, end - at);
    bad = part == "." || part == ".." || (part.empty() && end != name.size());
    at = end + 1;
  }
  if (bad) throw Error("zip: entry name \"" + name + "\" is not a plain relative path");
}

constexpr uint32_t kDosTime = 0, kDosDate = (1 << 5) | 1;  // 1980-01-01 00:00: the same bytes on every run

}  // namespace

std::string storedZip(const std::vector<std::pair<std::string, std::string>>& entries) {
  if (entries.size() > 0xFFFF) throw Error("zip: " + std::to_string(entries.size()) + " entries exceed 65535");
  std::string out, central;
  for (const auto& [name, data] : entries) {
    checkName(name);
    if (data.size() >= 0xFFFFFFFFu || out.size() + data.size() + name.size() + 30 >= 0xFFFFFFFFu)
      throw Error("zip: " + name + ": the archive would exceed 4 GiB");
    const uint32_t crc = uint32_t(crc32(0L, reinterpret_cast<const Bytef*>(data.data()), uInt(data.size())));
    const uint32_t offset = uint32_t(out.size());
    // Local file header (APPNOTE 4.3.7).
    put32(out, 0x04034b50);
    put16(out, 20), put16(out, 1 << 11), put16(out, 0), put16(out, kDosTime), put16(out, kDosDate);
    put32(out, crc), put32(out, uint32_t(data.size())), put32(out, uint32_t(data.size()));
    put16(out, uint32_t(name.size())), put16(out, 0);
    out += name;
    out += data;
    // Central directory header (4.3.12).
    put32(central, 0x02014b50);
    put16(central, 20), put16(central, 20), put16(central, 1 << 11), put16(central, 0);
    put16(central, kDosTime), put16(central, kDosDate);
    put32(central, crc), put32(central, uint32_t(data.size())), put32(central, uint32_t(data.size()));
    put16(central, uint32_t(name.size())), put16(central, 0), put16(central, 0), put16(central, 0), put16(central, 0);
    put32(central, 0), put32(central, offset);
    central += name;
  }
  const uint32_t centralOffset = uint32_t(out.size());
  out += central;
  // End of central directory record (4.3.16).
  put32(out, 0x06054b50);
  put16(out, 0), put16(out, 0), put16(out, uint32_t(entries.size())), put16(out, uint32_t(entries.size()));
  put32(out, uint32_t(central.size())), put32(out, centralOffset);
  put16(out, 0);
  return out;
}

}  // namespace vplab

namespace vplab {

namespace {

uint32_t get(std::string_view s, size_t at, int bytes) {
  uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(s[at + size_t(i)]);
  return v;
}

std::string inflateRaw(std::string_view in, size_t size, const std::string& where) {
  if (size == 0) return {};
  std::string out(size, '\0');
  z_stream z{};
  if (inflateInit2(&z, -MAX_WBITS) != Z_OK) throw Error(where + ": cannot start inflating");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = uInt(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  const int rc = inflate(&z, Z_FINISH);
  const size_t produced = z.total_out;
  inflateEnd(&z);
  // Z_BUF_ERROR with no room left: more data than the header said (a bomb or a lie).
  if (rc != Z_STREAM_END || produced != size) throw Error(where + ": damaged compressed data (or more than its header says)");
  return out;
}

}  // namespace

std::vector<ZipEntry> readZip(std::string_view zip, std::string_view source, size_t maxEntryBytes,
                              const std::function<bool(const std::string&)>& keep) {
  const std::string src(source);
  if (zip.size() < 22) throw Error(src + ": not a zip archive (too short)");
  // The end record: within the last 22 + 65535 bytes (its comment's length at most).
  size_t end = std::string_view::npos;
  for (size_t at = zip.size() - 22;; --at) {
    if (get(zip, at, 4) == 0x06054b50) {
      end = at;
      break;
    }
    if (at == 0 || zip.size() - at > 22 + 0xFFFF) break;
  }
  if (end == std::string_view::npos) throw Error(src + ": not a zip archive (no end of central directory)");
  const size_t count = get(zip, end + 10, 2), dirSize = get(zip, end + 12, 4), dirAt = get(zip, end + 16, 4);
  if (count == 0xFFFF || dirAt == 0xFFFFFFFFu) throw Error(src + ": ZIP64 archives are not read");
  if (dirAt > end || dirSize > end - dirAt) throw Error(src + ": damaged central directory");
  std::vector<ZipEntry> entries;
  size_t at = dirAt;
  for (size_t i = 0; i < count; ++i) {
    if (at + 46 > end || get(zip, at, 4) != 0x02014b50) throw Error(src + ": damaged central directory (entry " + std::to_string(i + 1) + ")");
    const uint32_t flags = get(zip, at + 8, 2), method = get(zip, at + 10, 2), crc = get(zip, at + 16, 4);
    const size_t packed = get(zip, at + 20, 4), size = get(zip, at + 24, 4), nameLen = get(zip, at + 28, 2),
                 extraLen = get(zip, at + 30, 2), commentLen = get(zip, at + 32, 2), local = get(zip, at + 42, 4);
    if (at + 46 + nameLen > end) throw Error(src + ": damaged central directory (entry " + std::to_string(i + 1) + ")");
    ZipEntry e{std::string(zip.substr(at + 46, nameLen)), {}};
    at += 46 + nameLen + extraLen + commentLen;
    const std::string where = src + ": " + e.name;
    if (keep && keep(e.name) && e.name.back() != '/') {
      if (flags & 1) throw Error(where + ": encrypted");
      if (method != 0 && method != 8) throw Error(where + ": compression method " + std::to_string(method) + " (stored or deflated expected)");
      if (size > maxEntryBytes)
        throw Error(where + ": " + std::to_string(size) + " bytes exceed the limit of " + std::to_string(maxEntryBytes));
      if (local + 30 > zip.size() || get(zip, local, 4) != 0x04034b50) throw Error(where + ": damaged local header");
      const size_t dataAt = local + 30 + get(zip, local + 26, 2) + get(zip, local + 28, 2);
      if (dataAt > zip.size() || packed > zip.size() - dataAt) throw Error(where + ": its data run past the archive's end");
      const std::string_view data = zip.substr(dataAt, packed);
      if (method == 0) {
        if (packed != size) throw Error(where + ": stored sizes differ");
        e.data = std::string(data);
      } else {
        e.data = inflateRaw(data, size, where);
      }
      if (uint32_t(crc32(0L, reinterpret_cast<const Bytef*>(e.data.data()), uInt(e.data.size()))) != crc)
        throw Error(where + ": CRC-32 mismatch (damaged)");
    }
    entries.push_back(std::move(e));
  }
  return entries;
}

}  // namespace vplab

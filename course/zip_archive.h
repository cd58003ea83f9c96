// A zip archive of stored (uncompressed) entries, for Moodle's "Upload multiple feedback files in a
// zip" (issue 38): PKWARE's APPNOTE.TXT 4.3 (local file headers, the central directory, its end
// record), version 2.0, no compression (method 0), no ZIP64 (each entry and the whole archive below
// 4 GiB, at most 65535 entries: checked), names in UTF-8 (general purpose bit 11). The CRC-32 is
// zlib's crc32 (the same polynomial as the zip format's).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vplab {

/// The archive of `entries` (name → bytes), in their order. A name is a relative path with '/'
/// separators: no leading '/', no "." or ".." component, no backslash (checked: vplab::Error).
std::string storedZip(const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace vplab

namespace vplab {

/// One file of a zip archive read by readZip.
struct ZipEntry {
  std::string name;  // as stored ('/' separators); a folder's entry ends in '/'
  std::string data;
};

/// The entries of a zip archive (stored or deflated: methods 0 and 8, as Moodle's downloads are),
/// read through the central directory, each checked against its CRC-32. `maxEntryBytes` bounds each
/// entry's uncompressed size (checked against the header before anything is allocated, and while
/// inflating); `keep(name)` selects the entries whose data are wanted (the others are listed with
/// empty data). Throws vplab::Error "SOURCE: …" for a damaged archive, an encrypted entry, ZIP64, an
/// unknown method or an entry beyond the limit.
std::vector<ZipEntry> readZip(std::string_view zip, std::string_view source, size_t maxEntryBytes,
                              const std::function<bool(const std::string&)>& keep);

}  // namespace vplab

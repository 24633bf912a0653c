#pragma once
// Issue 86: an ODB++ job arrives as a folder, a .tgz or a .zip, and KiCad
// zips its IPC-2581 files: their files, unpacked in memory (zlib inflates;
// the tar and zip containers are read here). A folder is read as the tar of
// its files (pack_tar), so every reader sees one shape: named entries.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace formats {

struct ArchiveEntry {
  std::string path;   // as the archive names it, '/' between folders, no leading "./"
  std::string bytes;  // the file's content
};

enum class ArchiveKind { None, Gzip, Zip, Tar };

// What the bytes are, by their magic numbers: gzip 1F 8B, zip "PK\3\4"
// (or an empty zip's "PK\5\6"), tar "ustar" at offset 257.
ArchiveKind archive_kind(std::string_view data);

// The regular files of a tar, .tar.gz (.tgz) or zip (stored or deflated), in
// archive order; a gzip that holds no tar is one entry named `path` without
// its ".gz". More than `max_bytes` unpacked in all, a damaged or truncated
// archive, a zip64 or encrypted entry: formats::InputError naming `path`
// (and the entry).
std::vector<ArchiveEntry> unpack_archive(const std::string& path, std::string_view data,
                                         std::size_t max_bytes = std::size_t{1} << 31);

// A ustar archive of the entries, for a folder given where an archive may be.
std::string pack_tar(const std::vector<ArchiveEntry>& entries);

}  // namespace formats

// Issue 86: tar, gzip and zip, unpacked in memory. zlib (Debian's zlib1g)
// inflates; the two containers are simple enough to read here: a tar is
// 512-byte headers each followed by its file, a zip a central directory at
// its end that points at each entry.
#include "formats/archive.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "formats/error.h"

namespace formats {

namespace {

constexpr std::size_t kBlock = 512;

// Inflates `in` (raw deflate when `window_bits` < 0, gzip when 16 + 15) into
// at most `limit` bytes; `what` names the data in messages.
std::string inflate_bytes(const std::string& path, std::string_view in, int window_bits, std::size_t limit,
                          std::size_t size_hint) {
  z_stream z{};
  if (inflateInit2(&z, window_bits) != Z_OK) throw InputError(path, 0, "zlib could not start");
  std::string out;
  out.reserve(std::min(size_hint, limit));
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  std::size_t in_left = in.size();
  char buf[1 << 16];
  int rc = Z_OK;
  for (;;) {
    if (z.avail_in == 0 && in_left > 0) {
      const auto chunk = static_cast<uInt>(std::min<std::size_t>(in_left, 1u << 30));
      z.avail_in = chunk;
      in_left -= chunk;
    }
    z.next_out = reinterpret_cast<Bytef*>(buf);
    z.avail_out = sizeof buf;
    rc = inflate(&z, Z_NO_FLUSH);
    out.append(buf, sizeof buf - z.avail_out);
    if (out.size() > limit) {
      inflateEnd(&z);
      throw InputError(path, 0, "unpacks to more than " + std::to_string(limit >> 20) + " MiB; not read");
    }
    if (rc == Z_STREAM_END) {
      // gzip allows several members one after the other (a file appended with cat).
      if (window_bits > 0 && (z.avail_in > 0 || in_left > 0) && inflateReset(&z) == Z_OK) continue;
      break;
    }
    if (rc == Z_BUF_ERROR && z.avail_in == 0 && in_left == 0) {
      inflateEnd(&z);
      throw InputError(path, 0, "the compressed data ends early (a truncated file?)");
    }
    if (rc != Z_OK && rc != Z_BUF_ERROR) {
      const std::string why = z.msg ? z.msg : "damaged";
      inflateEnd(&z);
      throw InputError(path, 0, "compressed data is damaged (" + why + ")");
    }
  }
  inflateEnd(&z);
  return out;
}

std::uint32_t le16(std::string_view d, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(d[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(d[at + 1])) << 8;
}
std::uint32_t le32(std::string_view d, std::size_t at) { return le16(d, at) | le16(d, at + 2) << 16; }

std::string clean_path(std::string p) {
  std::replace(p.begin(), p.end(), '\\', '/');
  while (p.rfind("./", 0) == 0) p.erase(0, 2);
  while (!p.empty() && p.front() == '/') p.erase(0, 1);
  return p;
}

// A tar header's NUL-terminated (or full-width) text field.
std::string field(std::string_view header, std::size_t at, std::size_t width) {
  std::string_view f = header.substr(at, width);
  return std::string(f.substr(0, std::min(f.find('\0'), f.size())));
}

bool is_tar(std::string_view data) { return data.size() >= kBlock && data.substr(257, 5) == "ustar"; }

std::vector<ArchiveEntry> read_tar(const std::string& path, std::string_view data, std::size_t limit) {
  std::vector<ArchiveEntry> out;
  std::size_t at = 0, total = 0;
  std::string long_name;  // from a GNU 'L' or a pax 'x' header, for the next entry
  while (at + kBlock <= data.size()) {
    std::string_view header = data.substr(at, kBlock);
    if (header.find_first_not_of('\0') == std::string_view::npos) break;  // the end: zero blocks
    std::uint64_t size = 0;
    for (char c : field(header, 124, 12)) {
      if (c == ' ') continue;
      if (c < '0' || c > '7') throw InputError(path, 0, "tar header at byte " + std::to_string(at) + " is damaged");
      size = size * 8 + static_cast<std::uint64_t>(c - '0');
    }
    const char type = header[156];
    at += kBlock;
    if (size > data.size() - at) throw InputError(path, 0, "the tar archive ends inside " + field(header, 0, 100) + " (a truncated file?)");
    std::string_view body = data.substr(at, static_cast<std::size_t>(size));
    at += (static_cast<std::size_t>(size) + kBlock - 1) / kBlock * kBlock;
    if (type == 'L') {
      long_name = std::string(body.substr(0, std::min(body.find('\0'), body.size())));
      continue;
    }
    if (type == 'x') {
      // pax records: "LEN path=VALUE\n"
      for (std::size_t p = 0; p < body.size();) {
        const std::size_t space = body.find(' ', p);
        if (space == std::string_view::npos) break;
        const std::size_t len = std::strtoul(std::string(body.substr(p, space - p)).c_str(), nullptr, 10);
        if (len == 0 || p + len > body.size()) break;
        std::string_view record = body.substr(space + 1, p + len - space - 2);
        if (record.rfind("path=", 0) == 0) long_name = std::string(record.substr(5));
        p += len;
      }
      continue;
    }
    std::string name = long_name.empty() ? field(header, 0, 100) : long_name;
    if (long_name.empty() && header.substr(257, 5) == "ustar") {
      const std::string prefix = field(header, 345, 155);
      if (!prefix.empty()) name = prefix + "/" + name;
    }
    long_name.clear();
    if (type != '0' && type != '\0' && type != '7') continue;  // folders, links, devices
    total += body.size();
    if (total > limit) throw InputError(path, 0, "unpacks to more than " + std::to_string(limit >> 20) + " MiB; not read");
    out.push_back({clean_path(name), std::string(body)});
  }
  return out;
}

std::vector<ArchiveEntry> read_zip(const std::string& path, std::string_view data, std::size_t limit) {
  // The end of central directory record: 22 bytes and a comment of up to 64 KiB.
  std::size_t eocd = std::string_view::npos;
  for (std::size_t back = 22; back <= std::min<std::size_t>(data.size(), 22 + 65535); ++back) {
    if (le32(data, data.size() - back) == 0x06054b50u) {
      eocd = data.size() - back;
      break;
    }
  }
  if (eocd == std::string_view::npos) throw InputError(path, 0, "a zip archive without its directory (a truncated file?)");
  const std::size_t count = le16(data, eocd + 10);
  std::size_t at = le32(data, eocd + 16);
  if (count == 0xFFFF || at == 0xFFFFFFFFu) throw InputError(path, 0, "a zip64 archive; acodrill reads plain zip (under 4 GiB)");
  std::vector<ArchiveEntry> out;
  std::size_t total = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (at + 46 > data.size() || le32(data, at) != 0x02014b50u) throw InputError(path, 0, "the zip's directory is damaged");
    const std::uint32_t flags = le16(data, at + 8), method = le16(data, at + 10);
    const std::size_t packed = le32(data, at + 20), size = le32(data, at + 24);
    const std::size_t name_len = le16(data, at + 28), extra_len = le16(data, at + 30), comment_len = le16(data, at + 32);
    const std::size_t local = le32(data, at + 42);
    if (at + 46 + name_len > data.size()) throw InputError(path, 0, "the zip's directory is damaged");
    const std::string name = clean_path(std::string(data.substr(at + 46, name_len)));
    at += 46 + name_len + extra_len + comment_len;
    if (name.empty() || name.back() == '/') continue;  // a folder
    const std::string where = path + ":" + name;
    if (flags & 1u) throw InputError(where, 0, "an encrypted zip entry; unpack it first");
    if (packed == 0xFFFFFFFFu || size == 0xFFFFFFFFu || local == 0xFFFFFFFFu) {
      throw InputError(where, 0, "a zip64 entry; acodrill reads plain zip (under 4 GiB)");
    }
    if (local + 30 > data.size() || le32(data, local) != 0x04034b50u) throw InputError(where, 0, "the zip entry is damaged");
    const std::size_t start = local + 30 + le16(data, local + 26) + le16(data, local + 28);
    if (start > data.size() || packed > data.size() - start) throw InputError(where, 0, "the zip entry ends early (a truncated file?)");
    std::string_view body = data.substr(start, packed);
    std::string bytes;
    if (method == 0) bytes = std::string(body);
    else if (method == 8) bytes = inflate_bytes(where, body, -15, limit - total, size);
    else throw InputError(where, 0, "compressed by zip method " + std::to_string(method) + "; acodrill reads stored and deflated entries");
    total += bytes.size();
    if (total > limit) throw InputError(path, 0, "unpacks to more than " + std::to_string(limit >> 20) + " MiB; not read");
    out.push_back({name, std::move(bytes)});
  }
  return out;
}

}  // namespace

ArchiveKind archive_kind(std::string_view data) {
  if (data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1F && static_cast<unsigned char>(data[1]) == 0x8B) {
    return ArchiveKind::Gzip;
  }
  if (data.size() >= 4 && (data.substr(0, 4) == std::string_view("PK\3\4", 4) || data.substr(0, 4) == std::string_view("PK\5\6", 4))) {
    return ArchiveKind::Zip;
  }
  if (is_tar(data)) return ArchiveKind::Tar;
  return ArchiveKind::None;
}

std::vector<ArchiveEntry> unpack_archive(const std::string& path, std::string_view data, std::size_t max_bytes) {
  switch (archive_kind(data)) {
    case ArchiveKind::Zip: return read_zip(path, data, max_bytes);
    case ArchiveKind::Tar: return read_tar(path, data, max_bytes);
    case ArchiveKind::Gzip: {
      const std::string inner = inflate_bytes(path, data, 16 + 15, max_bytes, data.size() * 4);
      if (is_tar(inner)) return read_tar(path, inner, max_bytes);
      std::string name = path.substr(path.find_last_of("/\\") == std::string::npos ? 0 : path.find_last_of("/\\") + 1);
      if (name.size() > 3 && name.compare(name.size() - 3, 3, ".gz") == 0) name.resize(name.size() - 3);
      return {{name, inner}};
    }
    case ArchiveKind::None: break;
  }
  throw InputError(path, 0, "not an archive (tar, gzip or zip)");
}

std::string pack_tar(const std::vector<ArchiveEntry>& entries) {
  std::string out;
  auto header = [&](const std::string& name, std::size_t size, char type) {
    char h[kBlock] = {};
    std::memcpy(h, name.data(), std::min<std::size_t>(name.size(), 99));
    std::snprintf(h + 100, 8, "%07o", 0644u);
    std::snprintf(h + 108, 8, "%07o", 0u);
    std::snprintf(h + 116, 8, "%07o", 0u);
    std::snprintf(h + 124, 12, "%011llo", static_cast<unsigned long long>(size));
    std::snprintf(h + 136, 12, "%011o", 0u);
    h[156] = type;
    std::memcpy(h + 257, "ustar", 6);
    std::memcpy(h + 263, "00", 2);
    std::memset(h + 148, ' ', 8);
    unsigned sum = 0;
    for (unsigned char c : h) sum += c;
    std::snprintf(h + 148, 8, "%06o", sum);
    out.append(h, kBlock);
  };
  auto body = [&](std::string_view bytes) {
    out.append(bytes);
    out.append((kBlock - bytes.size() % kBlock) % kBlock, '\0');
  };
  for (const ArchiveEntry& e : entries) {
    if (e.path.size() > 99) {
      // GNU's long name: an 'L' entry holding the path, then the file.
      header("././@LongLink", e.path.size() + 1, 'L');
      body(std::string_view(e.path.c_str(), e.path.size() + 1));
    }
    header(e.path, e.bytes.size(), '0');
    body(e.bytes);
  }
  out.append(2 * kBlock, '\0');
  return out;
}

}  // namespace formats

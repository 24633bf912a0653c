#include "tag_reader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include "aco/charconv.h"

namespace dxf {

std::string_view trim(std::string_view s) {
  std::size_t b = 0;
  std::size_t e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

static std::string_view trim_right(std::string_view s) {
  std::size_t e = s.size();
  while (e > 0 && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(0, e);
}

static std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40)) {
    auto u = static_cast<unsigned char>(c);
    out += (u >= 32 && u < 127) ? c : '?';
  }
  if (s.size() > 40) out += "...";
  return out;
}

TagReader::TagReader(std::string_view text) : text_(text) {
  // A UTF-8 byte-order mark is harmless; skip it.
  if (text_.size() >= 3 && std::memcmp(text_.data(), "\xEF\xBB\xBF", 3) == 0) pos_ = 3;
}

bool TagReader::getline(std::string_view& out) {
  if (pos_ >= text_.size()) return false;
  std::size_t nl = text_.find('\n', pos_);
  if (nl == std::string_view::npos) nl = text_.size();
  out = text_.substr(pos_, nl - pos_);
  pos_ = nl + 1;
  ++line_;
  return true;
}

bool TagReader::next(Tag& tag) {
  for (;;) {
    std::string_view code_line;
    if (!getline(code_line)) return false;
    const std::uint32_t code_line_no = line_;
    std::string_view code_text = trim(code_line);
    if (code_text.empty() && pos_ >= text_.size()) return false;  // trailing blank line
    int code = 0;
    auto [ptr, ec] = aco::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (ec != std::errc() || ptr != code_text.data() + code_text.size() || code < 0) {
      throw ReadError(code_line_no, "invalid group code \"" + printable(code_text) + "\"");
    }
    std::string_view value;
    if (!getline(value)) {
      throw ReadError(code_line_no, "file ends after group code " + std::to_string(code) +
                                        " with no value (truncated file?)");
    }
    if (code == 999) continue;  // comment
    tag.code = code;
    tag.value = trim_right(value);
    tag.line = code_line_no;
    return true;
  }
}

double parse_double(const Tag& tag) {
  std::string_view s = trim(tag.value);
  double v = 0.0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;
  auto [ptr, ec] = aco::from_chars(first, last, v);
  // Name the value's own line (the one after its group code): that is where the bad text is.
  if (ec != std::errc() || ptr != last || s.empty()) {
    throw ReadError(tag.line + 1, "group code " + std::to_string(tag.code) + ": \"" + printable(s) +
                                  "\" is not a number");
  }
  if (!std::isfinite(v)) {
    throw ReadError(tag.line + 1, "group code " + std::to_string(tag.code) + ": \"" + printable(s) +
                                  "\" is not a finite number");
  }
  return v;
}

int parse_int(const Tag& tag, std::vector<Diagnostic>& diagnostics) {
  std::string_view s = trim(tag.value);
  int v = 0;
  auto [ptr, ec] = aco::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc() && ptr == s.data() + s.size() && !s.empty()) return v;
  double d = parse_double(tag);
  if (d != std::floor(d) || std::fabs(d) > 2147483647.0) {
    throw ReadError(tag.line + 1, "group code " + std::to_string(tag.code) + ": \"" + printable(s) +
                                  "\" is not an integer");
  }
  diagnostics.push_back({Severity::Warning, tag.line + 1,
                         "integer group code " + std::to_string(tag.code) + " written as a float"});
  return static_cast<int>(d);
}

// --- Binary DXF -------------------------------------------------------------
// Layout (DXF reference, "Binary DXF Files"): a 22-byte sentinel, then tags.
// R12 files use a 1-byte group code (255 escapes a 2-byte one); R13 and later a
// 2-byte little-endian code. The value's width follows from its group code.

namespace {

enum class BinType { String, Double, Int16, Int32, Int64, Byte, Chunk };

BinType binary_type(int code) {
  auto in = [code](int lo, int hi) { return code >= lo && code <= hi; };
  if (in(310, 319) || code == 1004) return BinType::Chunk;
  if (in(290, 299)) return BinType::Byte;
  if (in(60, 79) || in(170, 179) || in(270, 289) || in(370, 389) || in(400, 409) || in(1060, 1070))
    return BinType::Int16;
  if (in(90, 99) || in(420, 429) || in(440, 459) || code == 1071) return BinType::Int32;
  if (in(160, 169)) return BinType::Int64;
  if (in(10, 59) || in(110, 149) || in(210, 239) || in(460, 469) || in(1010, 1059)) return BinType::Double;
  return BinType::String;
}

class ByteCursor {
 public:
  explicit ByteCursor(std::string_view d) : d_(d) {}
  bool done() const { return pos_ >= d_.size(); }
  std::size_t pos() const { return pos_; }
  std::uint64_t take(std::size_t n) {
    if (d_.size() - pos_ < n) {
      throw ReadError(0, "binary DXF ends in the middle of a value at byte " + std::to_string(pos_));
    }
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i) v |= std::uint64_t(static_cast<unsigned char>(d_[pos_ + i])) << (8 * i);
    pos_ += n;
    return v;
  }
  std::string_view cstring() {
    std::size_t end = d_.find('\0', pos_);
    if (end == std::string_view::npos) {
      throw ReadError(0, "binary DXF ends inside a string at byte " + std::to_string(pos_));
    }
    std::string_view s = d_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return s;
  }

 private:
  std::string_view d_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string binary_to_text(std::string_view data) {
  constexpr std::size_t kSentinel = 22;
  // R13+ writes the first code 0 as two zero bytes; R12 as one, followed by "SECTION".
  const bool two_byte_codes = data.size() > kSentinel + 1 && data[kSentinel] == 0 && data[kSentinel + 1] == 0;
  ByteCursor in(data.substr(kSentinel));
  std::string out;
  out.reserve(data.size() * 2);
  char buf[64];
  while (!in.done()) {
    int code = 0;
    if (two_byte_codes) {
      code = static_cast<int>(in.take(2));
    } else {
      code = static_cast<int>(in.take(1));
      if (code == 255) code = static_cast<int>(in.take(2));
    }
    out += std::to_string(code);
    out += '\n';
    switch (binary_type(code)) {
      case BinType::Chunk: {
        std::size_t n = static_cast<std::size_t>(in.take(1));
        for (std::size_t i = 0; i < n; ++i) in.take(1);
        out += "0";
        break;
      }
      case BinType::Byte: out += std::to_string(in.take(1)); break;
      case BinType::Int16: out += std::to_string(static_cast<std::int16_t>(in.take(2))); break;
      case BinType::Int32: out += std::to_string(static_cast<std::int32_t>(in.take(4))); break;
      case BinType::Int64: out += std::to_string(static_cast<std::int64_t>(in.take(8))); break;
      case BinType::Double: {
        std::uint64_t bits = in.take(8);
        double v = 0.0;
        std::memcpy(&v, &bits, sizeof v);
        auto res = aco::to_chars(buf, buf + sizeof buf, v);  // shortest form that reads back exactly
        out.append(buf, res.ptr);
        break;
      }
      case BinType::String: {
        std::string_view s = in.cstring();
        for (char c : s) out += (c == '\n' || c == '\r') ? ' ' : c;
        break;
      }
    }
    out += '\n';
    if (code == 0 && out.size() >= 4 && out.compare(out.size() - 4, 4, "EOF\n") == 0) break;
  }
  return out;
}

}  // namespace dxf

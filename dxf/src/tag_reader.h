#pragma once
// Layer 1: group-code tags from ASCII DXF text. One pass over the buffer; a
// Tag's value is a view into it, so no line is copied or allocated.
#include <cstdint>
#include <string_view>
#include <vector>

#include "dxf/reader.h"

namespace dxf {

struct Tag {
  int code = 0;
  std::string_view value;  // trailing CR, spaces and tabs removed
  std::uint32_t line = 0;  // line of the group code
};

class TagReader {
 public:
  explicit TagReader(std::string_view text);
  // Next tag, skipping 999 comments. Returns false at the end of the text.
  // Throws ReadError for a non-integer group code or a code with no value line.
  bool next(Tag& tag);

 private:
  bool getline(std::string_view& out);

  std::string_view text_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 0;
};

std::string_view trim(std::string_view s);

// Numeric values of a tag; throw ReadError naming the line for garbage, NaN or infinity.
double parse_double(const Tag& tag);
// Accepts an integer written as a float ("1.0", as ProE writes) and reports it once.
int parse_int(const Tag& tag, std::vector<Diagnostic>& diagnostics);

// Binary DXF → equivalent ASCII text (the sentinel must be present).
std::string binary_to_text(std::string_view data);

}  // namespace dxf

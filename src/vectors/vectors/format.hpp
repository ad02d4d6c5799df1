// vectors/format.hpp — the vector-file line format, version 1 (documented in docs/vectors.md).
//
//   gsdot3-vectors 1 unit=blend tfx_rounding=floor ... bilinear=lerp16_4     header: version, unit, options
//   # ALPHA_1 Cs Cd => R G B                                                 comment: the field names
//   0000000000000044 ffff00ff ff00ff00 => 0ff 000 0ff                        one case
//
// Fields are hex (0-9, a-f, A-F), separated by blanks; "=>" separates inputs from outputs. Writers
// give each field exactly its digit count; readers accept 1 up to that many digits. Blank lines and
// lines starting with '#' are ignored.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "gs_arith/options.hpp"
#include "vectors/units.hpp"

namespace gsdot3::vectors {

inline constexpr int format_version = 1;
inline constexpr std::string_view format_magic = "gsdot3-vectors";

// A line that does not follow the format; the message says what is wrong (without the line number).
struct format_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct header {
  const unit* u = nullptr;
  gs::model_options options;
};

std::string header_line(const unit& u, const gs::model_options& o);
std::string fields_comment(const unit& u);
// Throws format_error: not a header, another version, an unknown unit or option.
header parse_header(std::string_view line);

// "f1 f2 ... => o1 o2 ...", each field at its width.
std::string case_line(const unit& u, const values& inputs, const values& outputs);
// The fields alone, at their widths: "f1 f2 ...".
std::string format_fields(const std::vector<field>& fields, const values& v);

struct parsed_case {
  values inputs, outputs;
};
// Throws format_error for a wrong field count, a missing "=>", a non-hex or too long field.
parsed_case parse_case(const unit& u, std::string_view line);

// True for blank lines and comments.
bool is_ignorable(std::string_view line);

}  // namespace gsdot3::vectors

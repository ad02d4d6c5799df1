// vectors/format.cpp — writing and reading vector-file lines.
#include "vectors/format.hpp"

#include <cstdint>
#include <vector>

namespace gsdot3::vectors {
namespace {

std::vector<std::string_view> split_blanks(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::uint64_t parse_field(const field& f, std::string_view token) {
  if (token.size() > static_cast<std::size_t>(f.digits))
    throw format_error("field " + std::string(f.name) + " '" + std::string(token) + "' has more than " +
                       std::to_string(f.digits) + " hex digits");
  std::uint64_t v = 0;
  for (char c : token) {
    const int d = hex_digit(c);
    if (d < 0) throw format_error("field " + std::string(f.name) + " '" + std::string(token) + "' is not hex");
    v = v << 4 | static_cast<std::uint64_t>(d);
  }
  return v;
}

values parse_fields(const std::vector<field>& fields, const std::vector<std::string_view>& tokens, const char* side) {
  if (tokens.size() != fields.size())
    throw format_error(std::string("expected ") + std::to_string(fields.size()) + " " + side + " fields, found " +
                       std::to_string(tokens.size()));
  values v;
  for (std::size_t i = 0; i < fields.size(); ++i) v.push_back(parse_field(fields[i], tokens[i]));
  return v;
}

}  // namespace

std::string header_line(const unit& u, const gs::model_options& o) {
  std::string s(format_magic);
  s.append(" ").append(std::to_string(format_version)).append(" unit=").append(u.name);
  for (const auto& row : gs::option_catalogue())
    s.append(" ").append(row.name).append("=").append(gs::option_value(o, row.name));
  return s;
}

std::string fields_comment(const unit& u) {
  std::string s = "#";
  for (const auto& f : u.inputs) s.append(" ").append(f.name);
  s.append(" =>");
  for (const auto& f : u.outputs) s.append(" ").append(f.name);
  return s;
}

header parse_header(std::string_view line) {
  const auto tokens = split_blanks(line);
  if (tokens.empty() || tokens[0] != format_magic)
    throw format_error("expected the header line '" + std::string(format_magic) + " " + std::to_string(format_version) +
                       " unit=NAME ...'");
  if (tokens.size() < 2 || tokens[1] != std::to_string(format_version))
    throw format_error("unsupported format version '" + (tokens.size() < 2 ? std::string() : std::string(tokens[1])) +
                       "' (this gsdot3 reads version " + std::to_string(format_version) + ")");
  header h;
  for (std::size_t i = 2; i < tokens.size(); ++i) {
    const auto eq = tokens[i].find('=');
    if (eq == std::string_view::npos)
      throw format_error("header item '" + std::string(tokens[i]) + "' is not NAME=VALUE");
    const auto name = tokens[i].substr(0, eq), value = tokens[i].substr(eq + 1);
    if (name == "unit") {
      h.u = find_unit(value);
      if (!h.u)
        throw format_error("unknown unit '" + std::string(value) + "' (one of " + std::string(unit_names()) + ")");
    } else if (auto err = gs::set_option(h.options, name, value)) {
      throw format_error(*err);
    }
  }
  if (!h.u) throw format_error("the header names no unit=NAME");
  return h;
}

std::string format_fields(const std::vector<field>& fields, const values& v) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string s;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) s += ' ';
    for (int d = fields[i].digits - 1; d >= 0; --d) s += digits[(v[i] >> (4 * d)) & 0xF];
  }
  return s;
}

std::string case_line(const unit& u, const values& inputs, const values& outputs) {
  return format_fields(u.inputs, inputs) + " => " + format_fields(u.outputs, outputs);
}

parsed_case parse_case(const unit& u, std::string_view line) {
  const auto tokens = split_blanks(line);
  std::size_t arrow = 0;
  while (arrow < tokens.size() && tokens[arrow] != "=>") ++arrow;
  if (arrow == tokens.size()) throw format_error("no '=>' between inputs and outputs");
  const std::vector<std::string_view> in(tokens.begin(), tokens.begin() + static_cast<std::ptrdiff_t>(arrow));
  const std::vector<std::string_view> out(tokens.begin() + static_cast<std::ptrdiff_t>(arrow) + 1, tokens.end());
  return {parse_fields(u.inputs, in, "input"), parse_fields(u.outputs, out, "output")};
}

bool is_ignorable(std::string_view line) {
  for (char c : line) {
    if (c == '#') return true;
    if (c != ' ' && c != '\t' && c != '\r') return false;
  }
  return true;
}

}  // namespace gsdot3::vectors

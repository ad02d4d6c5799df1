// vectors/verify.cpp — verification of vector files and of the ps2autotests blend recordings.
#include "vectors/verify.hpp"

#include <cstdint>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "gs_arith/pixel_pipeline.hpp"
#include "vectors/format.hpp"

namespace gsdot3::vectors {

void apply_overrides(gs::model_options& o, const verify_settings& s) {
  for (const auto& [name, value] : s.option_overrides) {
    if (auto err = gs::set_option(o, name, value)) throw format_error(*err);
  }
}

verify_result verify_vectors(std::istream& in, std::ostream& report, const verify_settings& s) {
  reporter rep(report, s);
  std::optional<header> h;
  std::string line;
  std::size_t number = 0;
  while (!rep.stopped() && std::getline(in, line)) {
    ++number;
    if (!h) {
      if (is_ignorable(line)) continue;
      try {
        h = parse_header(line);
      } catch (const format_error& e) { throw format_error("line " + std::to_string(number) + ": " + e.what()); }
      apply_overrides(h->options, s);
      continue;
    }
    if (is_ignorable(line)) continue;
    const unit& u = *h->u;
    try {
      const parsed_case c = parse_case(u, line);
      const values expected = u.evaluate(c.inputs, h->options);
      if (expected == c.outputs) {
        rep.pass();
      } else {
        rep.mismatch(format_fields(u.inputs, c.inputs), format_fields(u.outputs, c.outputs),
                     format_fields(u.outputs, expected));
      }
    } catch (const format_error& e) { rep.malformed(number, e.what()); } catch (const domain_error& e) {
      rep.malformed(number, std::string("input outside the unit's domain: ") + e.what());
    }
  }
  if (!h)
    throw format_error("line " + std::to_string(number + 1) + ": no header line '" + std::string(format_magic) + " " +
                       std::to_string(format_version) + " unit=NAME ...' (empty input)");
  return rep.finish();
}

namespace {

// The pixel the recording read back: `dst` drawn without blending over a cleared PSMCT32 frame,
// then `src` with blending on (see ../shared/hw/README.md for the test program's setup).
std::uint32_t ps2autotests_pixel(const gs::alpha_reg& alpha, std::uint32_t src, std::uint32_t dst,
                                 const gs::model_options& o) {
  gs::gs_registers regs;  // PSMCT32, FBMSK 0, COLCLAMP = 1, no PABE / FBA / dither / texture / alpha test
  regs.PRIM.PRIM = gs::prim_type::SPRITE;
  auto draw = [&](std::uint32_t colour, std::uint32_t old) {
    const gs::pixel_input p{gs::fragment_colour::flat(gs::rgba8::from_u32(colour)), gs::rgba8{}, old, 0, 0};
    return gs::pixel_pipeline(regs, p, o).out;
  };
  const std::uint32_t first = draw(dst, 0);
  regs.PRIM.ABE = true;
  regs.ALPHA_1 = alpha;
  return draw(src, first);
}

std::string hex(std::uint64_t v, int digits) {
  static constexpr char d[] = "0123456789abcdef";
  std::string s;
  for (int i = digits - 1; i >= 0; --i) s += d[(v >> (4 * i)) & 0xF];
  return s;
}

// "ABCD: ..." with A, B, C, D each 0..2 (the ALPHA_1 selectors of the following samples).
bool is_mode_line(std::string_view line) {
  if (line.size() < 5 || line[4] != ':') return false;
  for (std::size_t i = 0; i < 4; ++i)
    if (line[i] < '0' || line[i] > '2') return false;
  return true;
}

// Consumes exactly `digits` hex digits from the front of `rest`.
std::optional<std::uint32_t> take_hex(std::string_view& rest, std::size_t digits) {
  if (rest.size() < digits) return std::nullopt;
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < digits; ++i) {
    const char c = rest[i];
    const int d = c >= '0' && c <= '9'   ? c - '0'
                  : c >= 'a' && c <= 'f' ? c - 'a' + 10
                  : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                         : -1;
    if (d < 0) return std::nullopt;
    v = v << 4 | static_cast<std::uint32_t>(d);
  }
  rest.remove_prefix(digits);
  return v;
}

bool take_literal(std::string_view& rest, std::string_view word) {
  if (rest.substr(0, word.size()) != word) return false;
  rest.remove_prefix(word.size());
  return true;
}

struct blend_sample {
  std::uint32_t src, dst, fix, recorded;
};

// "  src: SSSSSSSS, dst: DDDDDDDD, fix: FF => RRRRRRRR" (blanks allowed around the line only).
std::optional<blend_sample> parse_sample(std::string_view line) {
  auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!line.empty() && blank(line.front())) line.remove_prefix(1);
  while (!line.empty() && blank(line.back())) line.remove_suffix(1);
  std::optional<std::uint32_t> src, dst, fix, recorded;
  if (!take_literal(line, "src: ") || !(src = take_hex(line, 8)) || !take_literal(line, ", dst: ") ||
      !(dst = take_hex(line, 8)) || !take_literal(line, ", fix: ") || !(fix = take_hex(line, 2)) ||
      !take_literal(line, " => ") || !(recorded = take_hex(line, 8)) || !line.empty())
    return std::nullopt;
  return blend_sample{*src, *dst, *fix, *recorded};
}

}  // namespace

verify_result verify_ps2autotests(std::istream& input, std::ostream& report, const verify_settings& s) {
  gs::model_options o;
  apply_overrides(o, s);
  // Not a recording at all (no mode line: another format, e.g. a gsdot3 vector file) is one error, not
  // a failure per line.
  const std::string text{std::istreambuf_iterator<char>(input), std::istreambuf_iterator<char>()};
  std::istringstream in(text);
  bool has_mode = false;
  for (std::string line; !has_mode && std::getline(in, line);) has_mode = is_mode_line(line);
  if (!has_mode)
    throw format_error(text.starts_with(format_magic)
                           ? "a gsdot3 vector file, not a ps2autotests recording (leave out --format ps2autotests)"
                           : "no 'ABCD: ...' mode line: not a ps2autotests gs/blend.expected recording");
  in.clear();
  in.seekg(0);
  reporter rep(report, s);
  std::optional<gs::alpha_reg> alpha;
  std::string mode;
  std::string line;
  std::size_t number = 0;
  while (!rep.stopped() && std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (is_ignorable(line) || line.rfind("--", 0) == 0) continue;  // blank, "-- TEST BEGIN/END"
    if (is_mode_line(line)) {
      auto digit = [&](int i) { return static_cast<std::uint8_t>(line[static_cast<std::size_t>(i - 1)] - '0'); };
      alpha = gs::alpha_reg{static_cast<gs::blend_colour>(digit(1)), static_cast<gs::blend_colour>(digit(2)),
                            static_cast<gs::blend_alpha>(digit(3)), static_cast<gs::blend_colour>(digit(4)), gs::u8{}};
      mode = line.substr(0, 4);
      continue;
    }
    const auto sample = parse_sample(line);
    if (!sample) {
      rep.malformed(number, "neither an 'ABCD: ...' mode line nor a '  src: S, dst: D, fix: F => R' sample");
      continue;
    }
    if (!alpha) {
      rep.malformed(number, "a sample before any 'ABCD: ...' mode line");
      continue;
    }
    const auto [src, dst, fix, recorded] = *sample;
    gs::alpha_reg reg = *alpha;
    reg.FIX = gs::u8::from_wrapped(fix);
    const std::uint32_t model = ps2autotests_pixel(reg, src, dst, o);
    if (model == recorded) {
      rep.pass();
    } else {
      rep.mismatch(mode + " " + hex(src, 8) + " " + hex(dst, 8) + " " + hex(fix, 2), hex(recorded, 8), hex(model, 8));
    }
  }
  return rep.finish();
}

}  // namespace gsdot3::vectors

// gsdot3 alu — the GS pixel pipeline as a calculator: registers + one pixel's inputs -> the new
// frame-buffer word, optionally with every stage's value.
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "model_args.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/profiles.hpp"
#include "gs_arith/registers.hpp"

namespace gsdot3::cli {
namespace {

bool has_hex_prefix(const std::string& text) {
  return text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
}

// The digits of `text` from `first` on, in base 10 or 16, at most `max`.
std::uint64_t parse_digits(const std::string& what, const std::string& text, std::size_t first, bool hex,
                           std::uint64_t max) {
  if (first >= text.size()) throw usage_error(what + ": empty number");
  const std::uint64_t base = hex ? 16 : 10;
  std::uint64_t v = 0;
  for (std::size_t i = first; i < text.size(); ++i) {
    const char ch = text[i];
    int d;
    if (ch >= '0' && ch <= '9')
      d = ch - '0';
    else if (hex && ch >= 'a' && ch <= 'f')
      d = ch - 'a' + 10;
    else if (hex && ch >= 'A' && ch <= 'F')
      d = ch - 'A' + 10;
    else
      throw usage_error(what + ": malformed number '" + text + "'" + (hex ? "" : " (hex needs a 0x prefix)"));
    if (v > (max - static_cast<std::uint64_t>(d)) / base)
      throw usage_error(what + ": value '" + text + "' out of range");
    v = v * base + static_cast<std::uint64_t>(d);
  }
  return v;
}

// "0x..." hex or decimal, at most `max`.
std::uint64_t parse_number(const std::string& what, const std::string& text, std::uint64_t max) {
  const bool hex = has_hex_prefix(text);
  return parse_digits(what, text, hex ? 2 : 0, hex, max);
}

// A colour AABBGGRR: 1..8 hex digits, 0x prefix optional.
std::uint32_t parse_colour(const std::string& what, const std::string& text) {
  const std::size_t first = has_hex_prefix(text) ? 2 : 0;
  if (text.size() <= first || text.size() - first > 8)
    throw usage_error(what + ": expected AABBGGRR (up to 8 hex digits), got '" + text + "'");
  return static_cast<std::uint32_t>(parse_digits(what, text, first, true, 0xFFFFFFFFu));
}

struct alu_args {
  std::vector<std::string> regs;
  model_args model{"--option"};
  std::string vertex, texel, dst = "00000000";
  unsigned x = 0, y = 0;
  bool trace = false;
};

void run_alu(const alu_args& a) {
  gs::gs_registers regs;
  for (const auto& r : a.regs) {
    const auto [name, value] = split_assignment("--reg", r);
    if (name == "RGBAQ") throw usage_error("--reg: give the vertex colour with --vertex, not RGBAQ");
    try {
      gs::set_register(regs, name, parse_number("--reg " + name, value, ~std::uint64_t{0}));
    } catch (const gs::register_error& e) { throw usage_error(std::string("--reg: ") + e.what()); }
  }
  const gs::model_options opts = a.model.resolve();
  if (regs.PRIM.TME && a.texel.empty()) throw usage_error("PRIM.TME = 1 needs --texel");
  const std::uint32_t dst = parse_colour("--dst", a.dst);
  if (gs::bits_of(regs.FRAME_1.PSM) == gs::pixel_bits::b16 && dst > 0xFFFFu)
    throw usage_error("--dst: a 16-bit frame (FRAME_1.PSM) holds a 16-bit word, got " + a.dst);
  const gs::pixel_input in{gs::fragment_colour::flat(gs::rgba8::from_u32(parse_colour("--vertex", a.vertex))),
                           gs::rgba8::from_u32(a.texel.empty() ? 0u : parse_colour("--texel", a.texel)), dst, a.x, a.y};
  const gs::pixel_trace t = gs::pixel_pipeline(regs, in, opts);
  if (a.trace) std::cout << gs::format_trace(t);
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", static_cast<unsigned>(t.out));
  std::cout << buf << "\n";
}

std::string option_help() {
  std::string s;
  for (const auto& row : gs::option_catalogue()) {
    s.append("\n  ").append(row.name).append(":");
    for (auto v : row.values) s.append(" ").append(v);
    s.append(" (default ").append(row.values.front()).append(")");
  }
  return s;
}

}  // namespace

void add_alu_command(CLI::App& app, context& ctx) {
  auto args = std::make_shared<alu_args>();
  CLI::App* cmd =
      app.add_subcommand("alu", "One pixel through the modeled GS: prints the new frame-buffer word 0xAABBGGRR");
  cmd->footer(
      "Prints the new frame-buffer word as 0xAABBGGRR (A8B8G8R8, alpha in the top byte; 16-bit frames: 0x0000XXXX).\n"
      "Unset registers are neutral: PRIM = 0 (no texture, no blending), TEX0_1 = 0, ALPHA_1 = 0, TEST_1 = 0 (no "
      "alpha test), FRAME_1 = 0 (PSMCT32, FBMSK = 0), COLCLAMP = 1 (clamp), PABE = 0, FBA_1 = 0, DTHE = 0, DIMX = 0. "
      "--dst defaults to 0x00000000, --x and --y to 0.\nModel options (--option NAME=VALUE):" +
      option_help());
  cmd->add_option(
      "--reg", args->regs,
      "Register NAME=VALUE, VALUE a 64-bit number (0x hex or decimal). NAME: PRIM, TEX0_1, ALPHA_1, TEST_1, "
      "FRAME_1, COLCLAMP, PABE, FBA_1, DTHE, DIMX (GS manual bit layouts; reserved values are errors). "
      "Repeatable; the last one wins.");
  cmd->add_option("--vertex", args->vertex, "Vertex (flat fragment) colour AABBGGRR, hex")->required();
  cmd->add_option("--texel", args->texel, "Texel colour AABBGGRR after CLUT/filtering; required when PRIM.TME = 1");
  cmd->add_option("--dst", args->dst, "Old frame-buffer word, hex (default 00000000)");
  cmd->add_option("--x", args->x, "Pixel x (dither matrix column x & 3; default 0)");
  cmd->add_option("--y", args->y, "Pixel y (dither matrix row y & 3; default 0)");
  cmd->add_flag("--trace", args->trace, "Print every stage's value before the result");
  args->model.add_to(cmd, "(listed below)");
  cmd->callback([args, &ctx] {
    run_alu(*args);
    ctx.exit_code = 0;
  });
}

}  // namespace gsdot3::cli

// gsdot3 mem — the GS local memory: where a pixel lives (addr) and how one format's page lies over
// another's (view, a PNG).
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/psm_names.hpp"
#include "pipeline/files.hpp"
#include "pipeline/memory_picture.hpp"

namespace gsdot3::cli {
namespace {

namespace mem = gs::mem;

std::string psm_list() {
  std::string s;
  for (const auto& e : mem::psm_names) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

mem::psm psm_arg(const std::string& what, const std::string& name) {
  if (const auto p = mem::parse_psm(name)) return *p;
  throw usage_error(what + ": unknown format '" + name + "' (one of " + psm_list() + ")");
}

struct addr_args {
  std::string psm = "PSMCT32";
  unsigned bp = 0, bw = 1, x = 0, y = 0;
  bool json = false;
};

void run_addr(const addr_args& a) {
  const mem::psm p = psm_arg("--psm", a.psm);
  if (a.bp > 16383) throw usage_error("--bp: " + std::to_string(a.bp) + " out of range 0..16383 (256-byte blocks)");
  if (a.bw > 63) throw usage_error("--bw: " + std::to_string(a.bw) + " out of range 0..63 (64-pixel units)");
  if (a.x > 2047 || a.y > 2047) throw usage_error("X, Y: out of range 0..2047");
  const mem::buffer b{fixed::uint<14>::from_wrapped(a.bp), fixed::uint<6>::from_wrapped(a.bw), p};
  const mem::location at = mem::locate(b, a.x, a.y);
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%06x", at.byte);
  const bool nibble = mem::value_bits(p) == 4;
  const std::string half = nibble ? (at.bit == 0 ? "lo" : "hi") : "";
  if (a.json) {
    nlohmann::json j = {{"psm", a.psm},
                        {"bp", a.bp},
                        {"bw", a.bw},
                        {"x", a.x},
                        {"y", a.y},
                        {"address", hex},
                        {"page", at.page()},
                        {"block", at.block()},
                        {"column", at.column()},
                        {"bit", at.bit},
                        {"bits", at.bits}};
    if (nibble) j["nibble"] = half;
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << hex << (nibble ? "." + half : "") << "\n"
            << "page " << at.page() << "\n"
            << "block " << at.block() << "\n"
            << "column " << at.column() << "\n";
}

struct view_args {
  std::string base = "PSMCT32", as = "PSMT8", colour = "channel", out = "mem-view.png";
  int scale = 4;
};

void run_view(const view_args& a) {
  const mem::psm base = psm_arg("--base", a.base), view = psm_arg("--as", a.as);
  if (a.scale < 1 || a.scale > 16) throw usage_error("--scale: out of range 1..16");
  if (a.colour != "channel" && a.colour != "pixel")
    throw usage_error("--colour: channel or pixel, got '" + a.colour + "'");
  const pipeline::image img = pipeline::page_overlay_image(base, view, a.colour, a.scale);
  try {
    pipeline::write_png(a.out, img);
  } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
  std::cout << a.out << "\n";
}

}  // namespace

void add_mem_command(CLI::App& app, context&) {
  auto* cmd = app.add_subcommand("mem", "The GS local memory: pixel addresses (addr) and format overlays (view)");
  cmd->require_subcommand(1);

  auto args = std::make_shared<addr_args>();
  auto* addr = cmd->add_subcommand("addr",
                                   "Where pixel/texel (X, Y) lives: byte address (0x..., .lo/.hi for "
                                   "4-bit formats), then page, block, column");
  addr->add_option("--psm", args->psm, "Storage format: " + psm_list())->capture_default_str();
  addr->add_option("--bp", args->bp, "Base pointer in 256-byte blocks (as TBP0, DBP, CBP count)")
      ->capture_default_str();
  addr->add_option("--bw", args->bw, "Buffer width in 64-pixel units (TBW, FBW, DBW)")->capture_default_str();
  addr->add_option("X", args->x, "x coordinate (0..2047)")->required();
  addr->add_option("Y", args->y, "y coordinate (0..2047)")->required();
  addr->add_flag("--json", args->json, "Print one JSON object instead");
  addr->callback([args] { run_addr(*args); });

  auto vargs = std::make_shared<view_args>();
  auto* view = cmd->add_subcommand("view",
                                   "Draw one page of format --as lying over the page of format --base "
                                   "(e.g. a PSMCT32 page read as PSMT8) as a PNG");
  view->add_option("--base", vargs->base, "Format the page was written in")->capture_default_str();
  view->add_option("--as", vargs->as, "Format the page is read as (the picture's pixels)")->capture_default_str();
  view->add_option("--colour", vargs->colour,
                   "channel: which part of the base pixel (R red, G green, B blue, A grey); pixel: which base "
                   "pixel (red = x, green = y)")
      ->capture_default_str();
  view->add_option("--scale", vargs->scale, "Pixels per texel (block edges drawn from 3 up)")->capture_default_str();
  view->add_option("-o,--out", vargs->out, "PNG file (written atomically)")->capture_default_str();
  view->callback([vargs] { run_view(*vargs); });
}

}  // namespace gsdot3::cli

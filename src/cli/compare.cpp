// gsdot3 compare — per-pixel differences of two frames (e.g. an emulator's or a console's screenshot
// of a dump against the model's frame): counts, a heat map PNG and the first differing pixels in hex.
// Exit 0 when equal, 1 when they differ, 2 on bad input.
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "image_compare.hpp"

namespace gsdot3::cli {
namespace {

struct args {
  std::string a, b, heat;
  int first = 10;
};

void run(const args& o, context& ctx) {
  ctx.exit_code = compare_pngs(o.a, o.b, o.heat, o.first, std::cout) == 0 ? 0 : 1;
}

}  // namespace

void add_compare_command(CLI::App& app, context& ctx) {
  auto o = std::make_shared<args>();
  auto* cmd = app.add_subcommand("compare",
                                 "Per-pixel differences of two PNG frames of the same size: counts, "
                                 "a heat map, the first differing pixels in hex (exit 1 when they differ)");
  cmd->add_option("A", o->a, "First PNG (e.g. the model's frame)")->required();
  cmd->add_option("B", o->b, "Second PNG (e.g. an emulator's or a console's screenshot)")->required();
  cmd->add_option("--heat", o->heat, "Write a heat map PNG: differing pixels red (brighter = larger), others dimmed A");
  cmd->add_option("--first", o->first, "How many differing pixels to list")->capture_default_str();
  cmd->callback([o, &ctx] { run(*o, ctx); });
}

}  // namespace gsdot3::cli

// cli/cost_args.cpp — see cost_args.hpp.
#include "cost_args.hpp"

#include "commands.hpp"

namespace gsdot3::cli {

void cost_args::add_to(CLI::App* cmd) {
  cmd->add_option("--walk", walk, "Pixel cycles: blocks (8x2 / 4x2 blocks touched) or pixels (pixels / rate)")
      ->capture_default_str();
  cmd->add_option("--page-break-cycles", o.page_break_cycles, "Cycles per frame / Z page change")
      ->capture_default_str();
  cmd->add_option("--texture-miss-cycles", o.texture_miss_cycles, "Cycles per texture miss")->capture_default_str();
  cmd->add_option("--texture-miss-unit", texture_unit, "What a texture miss leaves: page or quarter_page")
      ->capture_default_str();
  cmd->add_option("--sprite-setup-cycles", o.sprite_setup_cycles, "Set-up cycles per sprite")->capture_default_str();
  cmd->add_option("--clut-load-extra-cycles", o.clut_load_extra_cycles, "Cycles per CLUT load beyond its bytes")
      ->capture_default_str();
  cmd->add_option("--blend-rate-divisor", o.blend_rate_divisor,
                  "Pixel-rate divisor when the blend reads the destination (1: full rate, the sourced figure)")
      ->capture_default_str();
}

gs::cost::cost_options cost_args::resolve() const {
  namespace cost = gs::cost;
  cost::cost_options r = o;
  if (walk == "blocks")
    r.walk = cost::pixel_walk::blocks;
  else if (walk == "pixels")
    r.walk = cost::pixel_walk::pixels;
  else
    throw usage_error("--walk: blocks or pixels, got '" + walk + "'");
  if (texture_unit == "page")
    r.texture_miss_unit = cost::texture_unit::page;
  else if (texture_unit == "quarter_page")
    r.texture_miss_unit = cost::texture_unit::quarter_page;
  else
    throw usage_error("--texture-miss-unit: page or quarter_page, got '" + texture_unit + "'");
  if (r.blend_rate_divisor == 0) throw usage_error("--blend-rate-divisor: 1 or more");
  return r;
}

}  // namespace gsdot3::cli

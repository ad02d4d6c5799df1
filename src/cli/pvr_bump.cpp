// gsdot3 pvr-bump — a normal map or height map PNG to a PowerVR Series 2 bump texture (seed 004):
// 16-bit texels, S (elevation) in the high byte and R (azimuth) in the low byte, written as raw
// little-endian 16-bit words in row order, plus a preview PNG of the normals the texels decode to
// (packed n·127.5 + 127.5). Both outputs are written atomically (temporary name, then rename).
// Image input is PNG only (pipeline/files.hpp); a TGA/JPEG reader would plug in at read_input().
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "commands.hpp"
#include "output_file.hpp"
#include "pipeline/files.hpp"
#include "pipeline/normal_map.hpp"
#include "powervr/texture.hpp"

namespace gsdot3::cli {

namespace {
namespace pvr = schemes::powervr;

struct pvr_bump_args {
  std::string in, out, preview, rounding = "kallistios", azimuth = "255";
  bool height = false;
  float strength = 2.0f;
};

struct input_normals {
  int width = 0, height = 0;
  std::vector<glm::dvec3> normals;
};

input_normals read_input(const pvr_bump_args& a) {
  pipeline::image img;
  try {
    img = pipeline::read_texture_image_png(a.in, a.height);
  } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
  input_normals n{img.width, img.height, {}};
  const auto ch = static_cast<std::size_t>(img.channels);
  if (a.height) {
    std::vector<float> h;
    for (std::size_t i = 0; i < img.data.size(); i += ch) h.push_back(img.data[i]);
    for (const auto& v : pipeline::normals_from_height(h, img.width, img.height, a.strength)) n.normals.emplace_back(v);
  } else {
    for (std::size_t i = 0; i + 2 < img.data.size(); i += ch)
      n.normals.push_back({img.data[i] / 127.5 - 1.0, img.data[i + 1] / 127.5 - 1.0, img.data[i + 2] / 127.5 - 1.0});
  }
  return n;
}

void run_pvr_bump(const pvr_bump_args& a) {
  if (a.strength <= 0.0f || !std::isfinite(a.strength)) throw usage_error("--strength must be a positive number");
  const auto rounding = a.rounding == "nearest" ? pvr::texel_rounding::nearest : pvr::texel_rounding::kallistios;
  const auto scale = a.azimuth == "256" ? pvr::azimuth_scale::kos_256 : pvr::azimuth_scale::flycast_255;
  const input_normals in = read_input(a);
  std::vector<std::uint8_t> raw;
  pipeline::image preview{in.width, in.height, 3, {}};
  for (const auto& n : in.normals) {
    const pvr::bump_texel t = pvr::encode_normal(n, rounding, scale);
    const std::uint16_t word = t.packed();  // S << 8 | R, written little-endian
    raw.push_back(static_cast<std::uint8_t>(word & 0xFF));
    raw.push_back(static_cast<std::uint8_t>(word >> 8));
    const glm::dvec3 d =
        pvr::decode_normal(t, rounding == pvr::texel_rounding::kallistios ? pvr::azimuth_scale::flycast_255 : scale);
    for (int c = 0; c < 3; ++c) preview.data.push_back(static_cast<std::uint8_t>(std::lround(d[c] * 127.5 + 127.5)));
  }
  write_output(a.out, std::string_view(reinterpret_cast<const char*>(raw.data()), raw.size()), "--out");
  const std::string pv = a.preview.empty() ? a.out + ".preview.png" : a.preview;
  try {
    pipeline::write_png(pv, preview);
  } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
  std::fprintf(stderr, "gsdot3 pvr-bump: %dx%d texels -> %s (%zu bytes), preview %s\n", in.width, in.height,
               a.out.c_str(), raw.size(), pv.c_str());
}
}  // namespace

void add_pvr_bump_command(CLI::App& app, context& ctx) {
  auto args = std::make_shared<pvr_bump_args>();
  auto* cmd = app.add_subcommand(
      "pvr-bump",
      "Convert a normal map (RGB PNG, n = c/127.5 − 1) or a height map (grey PNG, --height-map) to a PowerVR\n"
      "Series 2 bump texture: 16-bit texels S << 8 | R (S = elevation, 255 = straight out; R = azimuth), raw\n"
      "little-endian, plus a preview PNG of the decoded normals. Sides must be powers of two from 8 to 1024.");
  cmd->add_option("in", args->in, "Input PNG")->required();
  cmd->add_option("out", args->out, "Output raw 16-bit texture")->required();
  cmd->add_flag("--height-map", args->height, "The input is a height map (grey levels; central differences)");
  cmd->add_option("--strength", args->strength, "Height map slope scale (grey levels per texel)")
      ->capture_default_str();
  cmd->add_option("--rounding", args->rounding,
                  "kallistios: pvrtex's (u8)(x·255 + 0.5) with S ^ 0xFF, azimuth /255 | nearest: round to nearest")
      ->check(CLI::IsMember({"kallistios", "nearest"}))
      ->capture_default_str();
  cmd->add_option("--azimuth", args->azimuth, "Azimuth steps per turn for --rounding nearest: 255 (flycast) or 256")
      ->check(CLI::IsMember({"255", "256"}))
      ->capture_default_str();
  cmd->add_option("--preview", args->preview, "Preview PNG (default: OUT.preview.png)");
  cmd->callback([args, &ctx] {
    run_pvr_bump(*args);
    ctx.exit_code = 0;
  });
}

}  // namespace gsdot3::cli

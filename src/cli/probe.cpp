// gsdot3 probe — the option probe (docs/dumps.md, "The option probe"): `probe --out F.gs` writes the
// GS dump whose frame tells the model options' values apart, `probe decode SHOT` reads a console's or
// an emulator's screenshot of that frame (PNG through libpng, BMP through stb_image) and says which
// value of each option it shows. Exit codes of decode: 0 every probed option and check matched, 1
// some did not, 2 bad input.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "model_args.hpp"
#include "output_file.hpp"
#include "gs_packets/dump.hpp"
#include "pipeline/files.hpp"
#include "pipeline/image_io.hpp"
#include "probe/decode.hpp"
#include "probe/design.hpp"
#include "probe/frame.hpp"
#include "probe/packets.hpp"
#include "probe/recording.hpp"

namespace gsdot3::cli {
namespace {

namespace pr = gsdot3::probe;

struct probe_args {
  std::string out, png;
  model_args model{"--option"};
};
struct decode_args {
  std::string shot, out;
};

std::string legend() {
  std::string s = "frame " + std::to_string(pr::frame_width) + "x" + std::to_string(pr::frame_height) +
                  " PSMCT32 at FBP 0; patches are 8x8 cells, the decoder reads their inner 6x6 pixels\n";
  for (const pr::patch& p : pr::probe_design().patches)
    s += p.name + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + "): " + p.what + "\n";
  for (const pr::unprobed& u : pr::probe_design().not_probed) s += u.option + ": not probed: " + u.reason + "\n";
  return s;
}

void run_probe(const probe_args& a) {
  if (a.out.empty() && a.png.empty()) throw usage_error("probe: nothing to write (give --out F.gs and/or --png F.png)");
  const gs::model_options o = a.model.resolve();
  if (!a.out.empty()) {
    try {
      gs::dump::save_dump(a.out, pr::probe_dump());
    } catch (const std::exception& e) { throw usage_error("--out: " + std::string(e.what())); }
    std::cerr << "gsdot3 probe: wrote " << a.out << "\n";
  }
  if (!a.png.empty()) {
    const std::vector<std::uint32_t> frame = pr::model_frame(o);
    pipeline::image img{pr::frame_width, pr::frame_height, 3, std::vector<std::uint8_t>(3 * frame.size())};
    for (std::size_t i = 0; i < frame.size(); ++i)
      for (std::size_t c = 0; c < 3; ++c) img.data[3 * i + c] = static_cast<std::uint8_t>(frame[i] >> (8 * c));
    try {
      pipeline::write_png(a.png, img);
    } catch (const std::exception& e) { throw usage_error("--png: " + std::string(e.what())); }
    std::cerr << "gsdot3 probe: wrote the model's frame to " << a.png << "\n";
  }
  std::cout << legend();
}

// The screenshot as 0xRRGGBB pixels, refused unless it is exactly the frame's size.
pr::rgb_frame read_screenshot(const std::string& file) {
  pipeline::image img;
  try {
    const std::vector<std::uint8_t> bytes = pipeline::read_file_bytes(file, "screenshot");
    if (bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G') {
      img = pipeline::decode_png(bytes.data(), bytes.size(), file);
    } else if (bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M') {
      img = pipeline::decode_bmp(bytes.data(), bytes.size(), file);
    } else {
      throw usage_error(file + ": not a PNG or BMP image");
    }
  } catch (const usage_error&) { throw; } catch (const std::exception& e) {
    throw usage_error(e.what());
  }
  if (img.width != pr::frame_width || img.height != pr::frame_height)
    throw usage_error(file + ": the screenshot is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                      "; the probe frame is " + std::to_string(pr::frame_width) + "x" +
                      std::to_string(pr::frame_height) +
                      " (scaled, cropped or bordered screenshots are refused: save the frame buffer at its own size)");
  pr::rgb_frame f(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
  for (std::size_t i = 0; i < f.size(); ++i) {
    const std::uint8_t* p = &img.data[i * static_cast<std::size_t>(img.channels)];
    f[i] = img.channels == 1 ? std::uint32_t{p[0]} * 0x010101u
                             : std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2];
  }
  return f;
}

int run_decode(const decode_args& a) {
  const pr::rgb_frame shot = read_screenshot(a.shot);
  const std::vector<pr::verdict> v = pr::decode(shot);
  std::cout << pr::format_verdicts(v);
  if (!a.out.empty()) {
    write_output(a.out, pr::write_recording(shot, v), "--out");
    std::cerr << "gsdot3 probe decode: wrote the recording " << a.out << " (check it with gsdot3 vectors ver)\n";
  }
  for (const pr::verdict& x : v)
    if (x.not_probed.empty() && x.matches.empty()) return 1;
  return 0;
}

}  // namespace

void add_probe_command(CLI::App& app, context& ctx) {
  auto args = std::make_shared<probe_args>();
  auto* cmd = app.add_subcommand(
      "probe",
      "The option probe: a GS dump whose 640x448 frame tells every model option's values apart (docs/dumps.md); "
      "prints the patch legend. `probe decode SHOT` reads a screenshot of that frame.");
  cmd->add_option("--out", args->out, "GS dump to write (.gs, .gs.xz or .gs.zst; written atomically)");
  cmd->add_option("--png", args->png, "Also write the frame the model predicts (PNG, atomically)");
  args->model.add_to(cmd, "for --png");
  auto dargs = std::make_shared<decode_args>();
  auto* dec = cmd->add_subcommand(
      "decode",
      "Which value of each option a screenshot of the probe frame shows: PNG or BMP, exactly 640x448 (other sizes "
      "are refused). Exit 0 when every probed option and check matched, 1 when some showed none of its values.");
  dec->add_option("screenshot", dargs->shot, "The frame buffer as PNG or BMP")->required();
  dec->add_option("--out", dargs->out, "Write the recording (gsdot3-probe format, read by gsdot3 vectors ver)");
  dec->callback([dargs, &ctx] { ctx.exit_code = run_decode(*dargs); });
  cmd->callback([args, dec] {
    if (!dec->parsed()) run_probe(*args);
  });
}

}  // namespace gsdot3::cli

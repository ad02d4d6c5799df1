// gsdot3 replay — runs a PCSX2 GS dump through the model's packet interpreter (register writes,
// host -> local IMAGE transfers and drawing into the modelled local memory), writes the displayed
// frame (the read circuit PMODE / DISPFB / DISPLAY select, gs_packets/display.hpp) and chosen buffers
// as PNG, and compares the frame with a screenshot (--expect, the compare command's code). A primitive
// the model cannot draw stops the replay with a one-line error (exit 2), or with --skip-unmodelled is
// skipped; either way it is named with its dump byte offset.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dump_notes.hpp"
#include "image_compare.hpp"
#include "model_args.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/psm_names.hpp"
#include "gs_packets/display.hpp"
#include "gs_packets/interpreter.hpp"
#include "pipeline/files.hpp"

namespace gsdot3::cli {
namespace {

namespace mem = gs::mem;

struct buffer_arg {
  unsigned fbp = 0, fbw = 0;
  mem::psm psm = mem::psm::PSMCT32;
  std::string text;
};

buffer_arg parse_buffer(const std::string& s) {
  std::stringstream in(s);
  std::string fbp, fbw, psm;
  if (!std::getline(in, fbp, ',') || !std::getline(in, fbw, ',') || !std::getline(in, psm) || psm.empty())
    throw usage_error("--buffer: expected FBP,FBW,PSM (e.g. 0,10,PSMCT32), got '" + s + "'");
  buffer_arg b;
  b.text = s;
  try {
    std::size_t used = 0;
    b.fbp = static_cast<unsigned>(std::stoul(fbp, &used));
    if (used != fbp.size()) throw std::invalid_argument(fbp);
    b.fbw = static_cast<unsigned>(std::stoul(fbw, &used));
    if (used != fbw.size()) throw std::invalid_argument(fbw);
  } catch (const std::exception&) { throw usage_error("--buffer: FBP and FBW must be numbers, got '" + s + "'"); }
  if (b.fbp > 511) throw usage_error("--buffer: FBP " + std::to_string(b.fbp) + " out of range 0..511 (8 KiB pages)");
  if (b.fbw < 1 || b.fbw > 63) throw usage_error("--buffer: FBW " + std::to_string(b.fbw) + " out of range 1..63");
  const auto p = mem::parse_psm(psm);
  if (!p) throw usage_error("--buffer: unknown format '" + psm + "'");
  b.psm = *p;
  return b;
}

// 8-bit RGB for colour formats (PSMCT16/16S: 5 bits widened as x << 3 | x >> 2), grey (low 8 bits of
// the value) for the others.
// The rectangle (x0, y0) .. + width × height of the buffer.
pipeline::image picture(const mem::local_memory& m, const mem::buffer& buf, unsigned x0, unsigned y0, unsigned width,
                        unsigned height) {
  const bool rgb32 = buf.PSM == mem::psm::PSMCT32 || buf.PSM == mem::psm::PSMCT24;
  const bool rgb16 = buf.PSM == mem::psm::PSMCT16 || buf.PSM == mem::psm::PSMCT16S;
  pipeline::image img{static_cast<int>(width), static_cast<int>(height), rgb32 || rgb16 ? 3 : 1, {}};
  for (unsigned y = y0; y < y0 + height; ++y)
    for (unsigned x = x0; x < x0 + width; ++x) {
      const std::uint32_t v = m.read_pixel(buf, x % 2048, y % 2048);
      if (rgb32) {
        for (int c = 0; c < 3; ++c) img.data.push_back(static_cast<std::uint8_t>(v >> (8 * c)));
      } else if (rgb16) {
        for (int c = 0; c < 3; ++c) {
          const auto f = static_cast<std::uint8_t>((v >> (5 * c)) & 31);
          img.data.push_back(static_cast<std::uint8_t>(f << 3 | f >> 2));
        }
      } else {
        img.data.push_back(static_cast<std::uint8_t>(v));
      }
    }
  return img;
}

struct args {
  std::string file, out = "replay", expect, heat;
  std::vector<std::string> buffers;
  unsigned height = 0;
  bool skip_unmodelled = false;
  model_args model;
};

// Writes into the staging folder; prints the name the file has once the folder is committed (--out).
void write_picture(const pipeline::staged_directory& dir, const std::string& name, const std::string& out,
                   const pipeline::image& img) {
  try {
    pipeline::write_png(dir.path() / name, img);
  } catch (const std::runtime_error& e) { throw usage_error(dir.as_target(e.what())); }
  std::cout << (std::filesystem::path(out) / name).string() << "\n";
}

void run(const args& a, context& ctx) {
  std::vector<buffer_arg> bufs;
  for (const auto& s : a.buffers) bufs.push_back(parse_buffer(s));
  if (a.height > 2048) throw usage_error("--height: out of range 1..2048");
  if (!a.expect.empty()) check_png("--expect", a.expect);  // before the replay, which may take long
  gs::dump::gs_dump d;
  try {
    d = gs::dump::load_dump(a.file);
  } catch (const gs::dump::dump_error& e) { throw usage_error(e.what()); }
  mem::local_memory m;
  gs::packets::interpreter it(m, {.model = a.model.resolve(), .skip_unmodelled = a.skip_unmodelled});
  try {
    print_dump_notes(a.file, d, gs::dump::decode_paths(d));
    it.replay(d);
  } catch (const gs::dump::dump_error& e) {
    throw usage_error(a.file + ": " + e.what());
  } catch (const gs::packets::unmodelled_error& e) {
    throw usage_error(a.file + ": " + e.what() + " (not modelled; --skip-unmodelled skips such primitives)");
  }
  for (const auto& t : it.transfers())
    std::cout << "transfer at byte " << t.offset << ": " << t.trxreg.RRW.value() << "x" << t.trxreg.RRH.value() << " "
              << mem::name_of(t.bitbltbuf.DPSM) << " to DBP " << t.bitbltbuf.DBP.value() << " DBW "
              << t.bitbltbuf.DBW.value() << " at (" << t.trxpos.DSAX.value() << ", " << t.trxpos.DSAY.value() << ")\n";
  for (const auto& u : it.unmodelled_features())
    std::cout << "unmodelled at byte " << u.offset << ": " << u.what << "\n";
  std::cout << "primitives drawn " << it.primitives_drawn() << " (" << it.pixels_drawn() << " pixels), skipped "
            << it.primitives_skipped() << "\n";
  const gs::packets::display_state disp = gs::packets::decode_display(it.privileged());
  if (!disp.unmodelled.empty()) std::cout << "display: " << disp.unmodelled << "\n";
  if (disp.frame)
    std::cout << "display: circuit " << disp.frame->circuit << ", " << disp.frame->width << "x" << disp.frame->height
              << " " << mem::name_of(disp.frame->buffer.PSM) << " at (" << disp.frame->x << ", " << disp.frame->y
              << ") of FBP " << disp.frame->buffer.BP.value() / 32 << " FBW " << disp.frame->buffer.BW.value() << "\n";
  if (!a.expect.empty() && (!disp.frame || disp.frame->width == 0 || disp.frame->height == 0))
    throw usage_error("--expect: the dump displays no frame to compare");
  if (bufs.empty() && !disp.frame) return;
  std::optional<pipeline::staged_directory> out;  // the PNGs appear together or not at all
  try {
    out.emplace(a.out, "display.png");
  } catch (const std::runtime_error& e) { throw usage_error("--out: " + std::string(e.what())); }
  const bool displayed = disp.frame && disp.frame->width > 0 && disp.frame->height > 0;
  if (displayed)
    write_picture(*out, "display.png", a.out,
                  picture(m, disp.frame->buffer, disp.frame->x, disp.frame->y, disp.frame->width, disp.frame->height));
  for (const auto& b : bufs) {
    unsigned h = a.height;
    if (h == 0)  // the lowest row any transfer into this buffer wrote
      for (const auto& t : it.transfers())
        if (t.bitbltbuf.DBP.value() == static_cast<int>(b.fbp * 32) &&
            t.bitbltbuf.DBW.value() == static_cast<int>(b.fbw))
          h = std::max(h, static_cast<unsigned>(t.trxpos.DSAY.value() + t.trxreg.RRH.value()));
    if (h == 0) throw usage_error("--buffer " + b.text + ": no transfer wrote it; give --height");
    const std::string name = "buffer_" + std::to_string(b.fbp) + "_" + std::to_string(b.fbw) + "_" +
                             std::string(mem::name_of(b.psm)) + ".png";
    const mem::buffer buf{fixed::uint<14>::from_wrapped(b.fbp * 32), fixed::uint<6>::from_wrapped(b.fbw), b.psm};
    write_picture(*out, name, a.out, picture(m, buf, 0, 0, 64 * b.fbw, h));
  }
  try {
    out->commit();
  } catch (const std::runtime_error& e) { throw usage_error("--out: " + std::string(e.what())); }
  // After the commit, so that every message names the frame where the user finds it.
  if (displayed && !a.expect.empty())
    ctx.exit_code =
        compare_pngs((std::filesystem::path(a.out) / "display.png").string(), a.expect, a.heat, 10, std::cout) == 0 ? 0
                                                                                                                    : 1;
}

}  // namespace

void add_replay_command(CLI::App& app, context& ctx) {
  auto a = std::make_shared<args>();
  auto* cmd = app.add_subcommand("replay",
                                 "Run a PCSX2 GS dump through the model (register writes, IMAGE "
                                 "transfers, drawing) and write the displayed frame and buffers as PNG");
  cmd->add_option("FILE", a->file, "The dump (.gs, .gs.xz, .gs.zst)")->required();
  cmd->add_option("--buffer", a->buffers, "A buffer to write: FBP (8 KiB pages),FBW (64 pixels),PSM; repeatable");
  cmd->add_option("--height", a->height, "Rows to write (default: the lowest row the dump's transfers wrote)");
  cmd->add_option("--out", a->out, "Directory for the PNGs (display.png: the displayed frame)")->capture_default_str();
  cmd->add_flag("--skip-unmodelled", a->skip_unmodelled,
                "Skip (and list) primitives using what the model lacks (fog, AA1, points, lines, mip-mapping, ...) "
                "instead of stopping");
  cmd->add_option("--expect", a->expect,
                  "Compare the displayed frame with this PNG (a screenshot), as `gsdot3 compare` "
                  "does; exit 1 when they differ");
  cmd->add_option("--heat", a->heat, "With --expect: write the heat map PNG here");
  a->model.add_to(cmd, "the drawing runs under (as `gsdot3 dump` printed for its dumps)");
  cmd->callback([a, &ctx] { run(*a, ctx); });
}

}  // namespace gsdot3::cli

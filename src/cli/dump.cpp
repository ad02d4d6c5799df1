// gsdot3 dump — one GS method's frame as a PCSX2 GS dump (pipeline/frame_packets.hpp): the
// environment, the uploads, every pass's registers and primitives, the display registers, a vsync.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "gs_arith/options.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/packetiser.hpp"
#include "gs_packets/state.hpp"
#include "gs_packets/video_mode.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/prepare.hpp"
#include "scene_options.hpp"

namespace gsdot3::cli {

void add_dump_command(CLI::App& app, context& ctx) {
  auto out = std::make_shared<std::string>();
  auto video = std::make_shared<std::string>("ntsc");
  auto max_packet = std::make_shared<std::size_t>(gs::packets::default_max_packet_bytes);
  auto* cmd = app.add_subcommand(
      "dump",
      "Write one GS method's frame (the memory path's buffers) as a PCSX2 GS dump (.gs, .gs.xz, .gs.zst): "
      "header, version-8 state, the GIF packets of every pass, display registers, a vsync");
  cmd->add_option("--out", *out, "the dump file; .xz or .zst (any case) compresses it")->required();
  cmd->add_option("--video", *video, "video mode the display registers set: ntsc, pal or vesa")
      ->check(CLI::IsMember({"ntsc", "pal", "vesa"}))
      ->capture_default_str();
  cmd->add_option("--max-packet", *max_packet,
                  "largest GIF packet (one transfer each) in bytes; PCSX2's path buffer holds 9 MiB (9437184)")
      ->check(CLI::Range(std::size_t{32}, std::size_t{1} << 30))
      ->capture_default_str();
  auto scene = add_scene_options(cmd, pipeline::frame_use::packets);
  cmd->get_option("--method")->required();
  cmd->callback([out, video, max_packet, scene, &ctx] {
    scene_setup st = scene();
    if (st.methods.size() != 1 || !st.schemes.empty())
      throw usage_error("--method: name one GS method (" + pipeline::method_names() + ") for a dump");
    st.options.memory_path = true;
    const auto t0 = std::chrono::steady_clock::now();
    std::cerr << "gsdot3: building the " << pipeline::name(st.methods[0]) << " packets\n";
    const pipeline::prepared_scene ps = pipeline::prepare(st.in.s, 0.0f, st.options.specular);
    pipeline::frame_packets fp;
    try {
      fp = pipeline::build_frame_packets(st.in.s, ps, st.methods[0], st.options);
    } catch (const std::invalid_argument& e) {
      throw usage_error(e.what());
    } catch (const pipeline::texture_does_not_fit& e) { throw usage_error(e.what()); }
    std::cerr << "gsdot3: writing " << *out << "\n";
    gs::dump::gs_dump d;
    try {
      d = pipeline::frame_dump(fp, {*gs::packets::video_mode_named(*video), *max_packet});
      gs::dump::save_dump(*out, d);
    } catch (const gs::dump::dump_error& e) { throw usage_error(e.what()); } catch (const std::invalid_argument& e) {
      throw usage_error(e.what());
    }
    std::size_t transfers = 0, largest = 0;
    for (const auto& p : d.packets)
      if (p.type == gs::dump::packet_type::transfer) ++transfers, largest = std::max(largest, p.data.size());
    if (largest > gs::packets::pcsx2_path_buffer_bytes)
      std::cerr << "gsdot3: warning: a transfer of " << largest << " bytes exceeds PCSX2's 9 MiB GIF path buffer\n";
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << *out << ": " << pipeline::name(st.methods[0]) << ", state version " << gs::dump::state_version_written
              << ", " << fp.gif.size() << " bytes of GIF packets in " << transfers << " transfers (largest " << largest
              << " bytes), " << *video << ", " << fp.triangles << " triangles, " << fp.sprites
              << " sprites; displayed: DISPFB1 FBP " << fp.buffers.output() << " FBW " << fp.buffers.fbw << " PSMCT32, "
              << st.in.s.width << "x" << st.in.s.height << "; " << seconds << " s\n";
    // The frame is the model's under these options: a replay that should reproduce it needs them too.
    std::string differ;
    const gs::model_options defaults{};
    for (const auto& row : gs::option_catalogue())
      if (gs::option_value(st.options.model, row.name) != gs::option_value(defaults, row.name))
        differ += " --model-option " + std::string(row.name) + "=" +
                  std::string(gs::option_value(st.options.model, row.name));
    std::cout << "replay under the same model options: gsdot3 replay " << *out << differ << "\n";
    ctx.exit_code = 0;
  });
}

}  // namespace gsdot3::cli

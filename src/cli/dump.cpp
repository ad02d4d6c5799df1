// gsdot3 dump — one GS method's frame as a PCSX2 GS dump (pipeline/frame_packets.hpp): the
// environment, the uploads, every pass's registers and primitives, the display registers, a vsync.
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/state.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/prepare.hpp"
#include "scene_options.hpp"

namespace gsdot3::cli {

void add_dump_command(CLI::App& app, context& ctx) {
  auto out = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand(
      "dump", "Write one GS method's frame (the memory path's buffers) as a PCSX2 GS dump (.gs, .gs.xz, .gs.zst): "
              "header, version-8 state, the GIF packets of every pass, display registers, a vsync");
  cmd->add_option("--out", *out, "the dump file; .xz or .zst compresses it")->required();
  auto scene = add_scene_options(cmd);
  cmd->get_option("--method")->required();
  cmd->callback([out, scene, &ctx] {
    scene_setup st = scene();
    if (st.methods.size() != 1 || !st.schemes.empty())
      throw usage_error("--method: name one GS method (two-pass, four-pass or baseline) for a dump");
    st.options.memory_path = true;
    const auto t0 = std::chrono::steady_clock::now();
    std::cerr << "gsdot3: building the " << pipeline::name(st.methods[0]) << " packets\n";
    const pipeline::prepared_scene ps = pipeline::prepare(st.in.s, 0.0f, st.options.specular);
    pipeline::frame_packets fp;
    try {
      fp = pipeline::build_frame_packets(st.in.s, ps, st.methods[0], st.options);
    } catch (const std::invalid_argument& e) {
      throw usage_error(e.what());
    } catch (const pipeline::texture_does_not_fit& e) {
      throw usage_error(e.what());
    }
    std::cerr << "gsdot3: writing " << *out << "\n";
    try {
      gs::dump::save_dump(*out, pipeline::frame_dump(fp));
    } catch (const gs::dump::dump_error& e) {
      throw usage_error(e.what());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << *out << ": " << pipeline::name(st.methods[0]) << ", state version " << gs::dump::state_version_written << ", "
              << fp.gif.size() << " bytes of GIF packets, " << fp.triangles << " triangles, " << fp.sprites
              << " sprites; displayed: DISPFB1 FBP " << fp.buffers.output() << " FBW " << fp.buffers.fbw << " PSMCT32, "
              << st.in.s.width << "x" << st.in.s.height << "; " << seconds << " s\n";
    ctx.exit_code = 0;
  });
}

}  // namespace gsdot3::cli
